// `fourbar sweep SWEEP.toml [--out FILE] [--jobs N]`: a clearance × rpm × e × μ
// grid over a base clearance scene, run on all cores, written as one table
// (the analogue of thesis Figs 7.10 and 7.11).

#include <iostream>
#include <thread>

#include "cli/command.hpp"
#include "common/atomic_output.hpp"
#include "common/csv_writer.hpp"
#include "common/error.hpp"
#include "common/provenance.hpp"
#include "common/units.hpp"
#include "sim/clearance/sweep.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

int run_sweep(const Invocation& inv) {
  std::string sweep_file, out_file;
  // Signed, so that "--jobs -1" is refused instead of wrapping round to 4294967295.
  long long jobs = std::max(1u, std::thread::hardware_concurrency());
  po::options_description opts("options");
  opts.add_options()("sweep", po::value(&sweep_file)->required(), "sweep file (TOML)")(
      "out,o", po::value(&out_file), "output table (default: out/<sweep name>.csv)")(
      "jobs,j", po::value(&jobs), "threads (default: all cores)");
  po::positional_options_description pos;
  pos.add("sweep", 1);
  po::variables_map vm;
  if (!parse_arguments(
          "sweep", "SWEEP.toml [--out FILE] [--jobs N]",
          "Runs the clearance model over a grid and writes one CSV row per grid point.\n\n"
          "Sweep file keys:\n"
          "  scene                 base scene (model = \"clearance\"), relative to the sweep file\n"
          "  radial_mm             array of radial clearances in mm (default: the scene's)\n"
          "  crank_speed_rpm       array of crank speeds in rpm (default: the scene's)\n"
          "  restitution           array of coefficients of restitution (default: the scene's)\n"
          "  friction_coefficient  array of Coulomb μ (base scene must be stick-slip)\n"
          "  revolutions           turns counted per grid point (default 10)\n"
          "  skip_revolutions      start-up turns run first and not counted (default 2)\n\n"
          "Columns: radial_mm, crank_speed_rpm, restitution, friction_coefficient,\n"
          "impacts_per_rev (n), sum_normal_impulse_per_rev_Ns (ΣF), impact_index_Ns\n"
          "(I_n = ΣF/n, 0 when n = 0), contact_losses_per_rev, following_share,\n"
          "energy_residual_rel, max_penetration_rel.",
          opts, pos, inv, vm))
    return 0;
  if (jobs < 1 || jobs > 4096) throw InputError("sweep: --jobs " + std::to_string(jobs) + " must be between 1 and 4096");

  Scene base;
  const SweepGrid grid = load_sweep(sweep_file, base);
  if (out_file.empty()) out_file = (std::filesystem::path("out") / std::filesystem::path(sweep_file).stem()).string() + ".csv";
  const std::filesystem::path out_path(out_file);
  if (out_path.has_parent_path()) ensure_output_dir(out_path.parent_path());

  const std::vector<SweepPoint> points = fourbar::run_sweep(base, grid, static_cast<unsigned>(jobs));

  Provenance prov{inv.command_line, {sweep_file, base.source, base.rig->source}};
  CsvWriter csv(out_path, prov.comment_lines(),
                {"radial_mm", "crank_speed_rpm", "restitution", "friction_coefficient", "impacts_per_rev",
                 "sum_normal_impulse_per_rev_Ns", "impact_index_Ns", "contact_losses_per_rev", "following_share",
                 "energy_residual_rel", "max_penetration_rel"});
  for (const SweepPoint& p : points) {
    const double row[] = {units::m_to_mm(p.radial_clearance_m), units::rad_s_to_rpm(p.crank_speed_rad_s),
                          p.restitution, p.friction_coefficient, p.impacts_per_rev, p.sum_normal_impulse_per_rev_Ns,
                          p.impact_index_Ns, p.contact_losses_per_rev, p.following_share, p.energy_residual_rel,
                          p.max_penetration_rel};
    csv.row(row);
  }
  csv.commit();
  std::cout << "wrote " << out_path.string() << " (" << points.size() << " grid points, " << grid.revolutions
            << " counted turns each, " << jobs << " threads)\n";
  return 0;
}

}  // namespace fourbar::cli
