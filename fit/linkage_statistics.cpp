#include "fit/linkage_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "acquire/manifest.hpp"
#include "analyze/analysis_channels.hpp"
#include "analyze/conversion.hpp"
#include "analyze/link_motion.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/units.hpp"
#include "mechanism/kinematics.hpp"
#include "sim/compliant/contact_stiffness.hpp"
#include "compare/linkage_theory.hpp"
#include "sim/linkage/linkage_model.hpp"

namespace fourbar {

std::string_view name_of(FitModelKind k) { return k == FitModelKind::elastic ? "elastic" : "three-mode"; }

FitModelKind fit_model_kind(const std::string& text) {
  if (text == "three-mode") return FitModelKind::three_mode;
  if (text == "elastic") return FitModelKind::elastic;
  throw InputError("fit: --model '" + text +
                   "': write --model three-mode (the default: the rigid three-mode clearance model) or --model elastic "
                   "(the linkage model with the rig's elastic coupler and rocker, docs/fit.md)");
}

namespace {

std::string rig_name(const Rig& rig) { return rig.source.empty() ? std::string("the rig") : rig.source.string(); }

/// The linkage model's spec for a fit point.
LinkageSpec elastic_spec(const Rig& rig, const FitModel& model, double clearance_m, const ContactParameters& p,
                         double tolerance) {
  LinkageSpec spec = bearing_clearance_spec(rig, clearance_m, elastic_fit_stiffness(rig, model, clearance_m), p.restitution,
                                            p.contact == ContactLaw::stick_slip ? p.friction_coefficient : 0.0, tolerance);
  spec.elastic_modes = model.elastic_modes;
  return spec;
}

}  // namespace

double elastic_fit_stiffness(const Rig& rig, const FitModel& model, double clearance_m) {
  if (model.contact_stiffness_N_per_m_n > 0) return model.contact_stiffness_N_per_m_n;
  const BearingBodies& b = rig.bearing;
  std::string missing;
  for (const auto& [key, present] : {std::pair<const char*, bool>{"bearing_length_mm", b.length_m.has_value()},
                                     {"pin_youngs_modulus_GPa", b.pin_youngs_modulus_Pa.has_value()},
                                     {"pin_poisson_ratio", b.pin_poisson_ratio.has_value()},
                                     {"bushing_youngs_modulus_GPa", b.bushing_youngs_modulus_Pa.has_value()},
                                     {"bushing_poisson_ratio", b.bushing_poisson_ratio.has_value()}})
    if (!present) missing += (missing.empty() ? "" : ", ") + std::string(key);
  if (!missing.empty())
    throw InputError("fit --model elastic: " + rig_name(rig) + " has no [clearance] " + missing +
                     " to compute the compliant contact's stiffness from; add them to the rig file "
                     "(docs/compliant.md) or give --contact-stiffness K (N/m^1.5, e.g. 1e10)");
  ClearanceSettings cs;
  cs.model = ClearanceKind::compliant;
  cs.radial_clearance_m = clearance_m;
  resolve_contact_stiffness(rig, clearance_m, cs, [&](const char* key, const std::string& what) {
    throw InputError("fit --model elastic: " + rig_name(rig) + ": " + key + " " + what);
  });
  return cs.compliant.stiffness_N_per_m_n;
}

void check_elastic_fit_rig(const Rig& rig, const FitModel& model, double clearance_m) {
  if (!rig.coupler_elastic && !rig.rocker_elastic)
    throw InputError("fit --model elastic: " + rig_name(rig) +
                     " has no modal data for the links: neither [coupler.elastic] nor [rocker.elastic] (keys modes "
                     "and either E_GPa, density_kg_m3, width_mm, thickness_mm or mode_frequencies_Hz, with "
                     "damping_ratios; docs/flex.md, e.g. data/rigs/thesis_elastic.toml). Add the tables to the rig "
                     "file (measure the frequencies with `fourbar tap`), or fit the rigid three-mode model "
                     "(leave out --model elastic)");
  for (const auto* e : {&rig.coupler_elastic, &rig.rocker_elastic})
    if (*e && model.elastic_modes > (*e)->modes)
      throw InputError("fit: --elastic-modes " + std::to_string(model.elastic_modes) + " but " + rig_name(rig) + "'s [" +
                       (e == &rig.coupler_elastic ? "coupler" : "rocker") + ".elastic] gives " +
                       std::to_string((*e)->modes) + " modes; lower --elastic-modes or raise the table's modes");
  (void)elastic_fit_stiffness(rig, model, clearance_m);  // its own message
  try {
    (void)build_linkage(rig, elastic_spec(rig, model, clearance_m, ContactParameters{}, 1e-6));
  } catch (const InputError& e) {
    throw InputError("fit --model elastic: " + rig_name(rig) + ": " + e.what());
  }
}

void attach_sensors(RecordingTarget& t, const std::filesystem::path& manifest_file) {
  const auto mounts = tangential_mounts(*t.rig, manifest_file);
  for (std::size_t i = 0; i < 2; ++i)
    if (t.measured[i]) t.sensor[i] = mounts[i];
}

MatchedTheory simulate_linkage_turns(const RecordingTarget& t, const ContactParameters& p, int warmup, int turns,
                                    double tolerance, const FitModel& model, const CrankGrid& grid) {
  const Rig& rig = *t.rig;
  const LinkageModel linkage = build_linkage(rig, elastic_spec(rig, model, t.clearance_m, p, tolerance));
  LinkageTheoryRun run;
  run.grid = grid;
  run.crank_speed_rad_s = t.crank_speed_rad_s;
  run.clearance_m = t.clearance_m;
  // α as cell means, as the three-mode model's statistics: point values
  // would fold the contact's energy above the grid's Nyquist order into the
  // band energy (docs/verdict.md "Link vibration": 5x at 0.254 mm).
  run.sub_samples = kCellMeanSubSamples;
  run.warmup_turns = std::max(warmup, 1);
  run.turns = turns;
  run.name = "fit: " + t.name;
  for (std::size_t i = 0; i < 2; ++i)
    if (t.measured[i]) {
      if (!t.sensor[i]) throw RunError("fit: " + t.name + ": no sensor attached for the elastic model (internal error)");
      run.sensor[i] = t.sensor[i];
    }
  return simulate_linkage_theory(linkage, run);
}

SimulatedStatistics simulate_linkage_statistics(const RecordingTarget& t, const ContactParameters& p, int warmup,
                                                int turns, double tolerance, const FitModel& model) {
  // The fine grid (the band's, else the analysis grid) over the kept turns.
  CrankGrid grid = t.grid;
  if (t.band_filter) grid.grid_points_per_rev = t.band_grid_points_per_rev;
  return statistics_of_theory(t, simulate_linkage_turns(t, p, warmup, turns, tolerance, model, grid), turns);
}

}  // namespace fourbar
