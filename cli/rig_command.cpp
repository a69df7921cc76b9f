// `fourbar rig RIG.toml`: validate a rig file and print what it describes.

#include <iostream>
#include <numbers>
#include <optional>

#include "cli/command.hpp"
#include "common/format.hpp"
#include "common/json_text.hpp"
#include "mechanism/rig_report.hpp"
#include "sim/flex/rig_elastic_link.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

int run_rig(const Invocation& inv) {
  std::string rig_file;
  bool json = false;
  po::options_description opts("options");
  opts.add_options()("rig", po::value(&rig_file)->required(), "rig file (TOML)")(
      "json", po::bool_switch(&json), "print the report as JSON");
  po::positional_options_description pos;
  pos.add("rig", 1);
  po::variables_map vm;
  if (!parse_arguments("rig", "RIG.toml [--json]",
                       "Checks every key and that the crank turns fully, then reports the Grashof\n"
                       "class, the assembly and the transmission-angle range, and the bending modes of\n"
                       "an elastic coupler or rocker. Exit 2 on a bad rig.\n",
                       opts, pos, inv, vm))
    return 0;

  const Rig rig = load_rig(rig_file);
  const RigReport report = report_rig(rig);
  const std::optional<ElasticLink> elastic[] = {rig_elastic_link(rig, RigLink::coupler),
                                                rig_elastic_link(rig, RigLink::rocker)};
  if (json) {
    std::cout << json_text(to_json(rig, report), 2) << "\n";
    return 0;
  }
  std::cout << rig_file << ": " << rig.name << "\n"
            << "  class:        " << to_string(report.grashof) << "\n"
            << "  assembly:     " << to_string(rig.assembly) << "\n"
            << "  transmission: " << report.transmission_min_deg << "° (crank " << report.transmission_min_at_crank_deg
            << "°) to " << report.transmission_max_deg << "° (crank " << report.transmission_max_at_crank_deg << "°)\n"
            << "  rocker swing: " << report.rocker_swing_deg << "°\n";
  for (const auto& link : elastic) {
    if (!link) continue;
    std::cout << "  " << (&link == &elastic[0] ? "coupler" : "rocker ") << " modes: ";
    for (int k = 0; k < link->modes(); ++k)
      std::cout << (k ? ", " : "") << format_number(link->frequencies_rad_s(k) / (2 * std::numbers::pi), 4) << " Hz"
                << (link->damping_ratios(k) > 0 ? " (ζ " + format_number(link->damping_ratios(k), 3) + ")" : "");
    std::cout << "\n";
  }
  return 0;
}

}  // namespace fourbar::cli
