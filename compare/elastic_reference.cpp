#include "compare/elastic_reference.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "common/format.hpp"
#include "common/units.hpp"
#include "compare/linkage_theory.hpp"
#include "sim/compliant/contact_stiffness.hpp"
#include "sim/linkage/linkage_model.hpp"

namespace fourbar {

namespace {

std::string modes_text(const ElasticLink& link) {
  std::string s;
  for (Eigen::Index k = 0; k < link.frequencies_rad_s.size(); ++k)
    s += (k ? ", " : "") + format_number(link.frequencies_rad_s[k] / units::kTwoPi, 4);
  return s + " Hz";
}

}  // namespace

ElasticReference elastic_reference(const ElasticReferenceRun& a, const TheorySettings& settings,
                                   const ModelFamilySettings& family, double top_hz) {
  ElasticReference out;
  const Rig& rig = *a.rig;
  if (!rig.coupler_elastic && !rig.rocker_elastic) return out;
  // The contact's stiffness: the session's compliant theory's, the rig
  // bearing's, else [model_family] contact_stiffness_N_per_m_n.
  double stiffness = settings.model == ClearanceKind::compliant && settings.compliant.stiffness_given
                         ? settings.compliant.stiffness_N_per_m_n
                         : family.contact_stiffness_N_per_m_n;
  if (!(stiffness > 0)) {
    try {
      ClearanceSettings cs;
      cs.model = ClearanceKind::compliant;
      cs.radial_clearance_m = a.clearance_m;
      resolve_contact_stiffness(rig, a.clearance_m, cs, [](const char* key, const std::string& what) {
        throw InputError(std::string(key) + " " + what);
      });
      stiffness = cs.compliant.stiffness_N_per_m_n;
    } catch (const InputError& e) {
      out.not_run = "the rig file has the links' modal data but no bearing to compute the contact's stiffness from (" +
                    std::string(e.what()) +
                    "); give session.toml [model_family] contact_stiffness_N_per_m_n (e.g. 1e10) or the rig's bearing keys "
                    "(docs/compliant.md)";
      return out;
    }
  }
  const double restitution = std::min(settings.restitution, kReferenceMaxRestitution);
  const bool friction = settings.model == ClearanceKind::compliant || settings.contact == ContactLaw::stick_slip;
  LinkageSpec spec = bearing_clearance_spec(rig, a.clearance_m, stiffness, restitution,
                                            friction ? settings.friction_coefficient : 0.0, kReferenceTolerance);
  try {
    // The modes the check can see: below kReferenceModeShare × its top.
    int modes = 1;
    {
      const LinkageModel all = build_linkage(rig, spec);
      for (int b : {1, 2})
        if (const ElasticLink* e = all.elastic(b))
          for (Eigen::Index m = 0; m < e->frequencies_rad_s.size(); ++m)
            if (e->frequencies_rad_s[m] / units::kTwoPi <= kReferenceModeShare * top_hz) modes = std::max(modes, static_cast<int>(m) + 1);
    }
    spec.elastic_modes = modes;
    const LinkageModel linkage = build_linkage(rig, spec);
    LinkageTheoryRun run;
    run.grid = a.grid;
    run.crank_speed_rad_s = a.crank_speed_rad_s;
    run.clearance_m = a.clearance_m;
    run.warmup_turns = std::max(settings.warmup_revolutions, 1);  // cell means need one
    run.turns = settings.averaged_revolutions;
    run.name = a.name + ": the elastic-link reference";
    run.sub_samples = kCellMeanSubSamples;  // α as cell means, as the three-mode theory's
    run.sensor = a.sensor;
    out.theory = simulate_linkage_theory(linkage, run);
    out.theory->settings = settings;
    apply_pass_band(*out.theory, a.filter);
    LinkageSpec rigid_spec = spec;
    rigid_spec.elastic = {false, false, false};
    rigid_spec.elastic_modes = 0;
    out.rigid_links = simulate_linkage_theory(build_linkage(rig, rigid_spec), run);
    out.rigid_links->settings = settings;
    apply_pass_band(*out.rigid_links, a.filter);
    for (int b : {1, 2})
      if (const ElasticLink* e = linkage.elastic(b))
        out.description += std::string(out.description.empty() ? "" : "; ") + (b == 1 ? "coupler" : "rocker") + " " +
                           std::to_string(e->modes()) + (e->modes() == 1 ? " mode (" : " modes (") + modes_text(*e) + ")";
    out.description += "; contact stiffness " + format_number(stiffness, 3) + " N/m^1.5, e = " + format_number(restitution, 3) +
                       (restitution < settings.restitution ? " (the session's " + format_number(settings.restitution, 3) +
                                                                 " capped: an undamped contact chatters without end)"
                                                           : std::string());
  } catch (const InputError& e) {
    out.theory.reset();
    out.rigid_links.reset();
    out.not_run = std::string("the elastic-link reference could not be built: ") + e.what();
  } catch (const RunError& e) {
    out.theory.reset();
    out.rigid_links.reset();
    out.not_run = std::string("the elastic-link reference failed: ") + e.what();
  }
  return out;
}

}  // namespace fourbar
