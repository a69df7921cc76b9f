#include "fit/family_judgement.hpp"

#include <algorithm>
#include <cmath>

#include "common/format.hpp"
#include "common/units.hpp"
#include "compare/elastic_reference.hpp"
#include "compare/link_vibration.hpp"
#include "compare/matched_theory.hpp"
#include "fit/linkage_statistics.hpp"
#include "fit/session_fit.hpp"

namespace fourbar {

void widen_for_model_error(ParameterEstimate& p, double delta, double scale, double box_low, double box_high) {
  p.identifiable = false;
  const std::size_t n = std::min(p.profile_at.size(), p.profile_chi2.size());
  if (n == 0) {
    p.low = box_low, p.high = box_high;
    return;
  }
  const double bottom = *std::min_element(p.profile_chi2.begin(), p.profile_chi2.begin() + static_cast<std::ptrdiff_t>(n));
  const double limit = bottom + delta * scale * scale;
  std::size_t first = n, last = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (p.profile_chi2[i] <= limit) first = std::min(first, i), last = std::max(last, i);
  double low = first > 0 && first < n ? p.profile_at[first - 1] : box_low;
  double high = last + 1 < n ? p.profile_at[last + 1] : box_high;
  if (first == n) low = box_low, high = box_high;  // (cannot happen: the bottom is in the set)
  p.low = std::max(box_low, std::min({low, p.value, p.low}));
  p.high = std::min(box_high, std::max({high, p.value, p.high}));
}

namespace {

/// α3, else α4 (no coupler channel): the quantity the check compares.
LinkQuantity checked_quantity(const RecordingTarget& t) {
  return t.measured[static_cast<std::size_t>(FitLink::coupler)] ? LinkQuantity::alpha3 : LinkQuantity::alpha4;
}

}  // namespace

ModelFamilyCheck family_check_of(const RecordingTarget& t, const std::vector<double>& measured_turns, MatchedTheory& theory,
                                 const ModelFamilySettings& settings) {
  apply_pass_band(theory, t.filter);
  const TheorySeries& s = theory.series[index_of(checked_quantity(t))];
  const bool has_top = t.filter.band == BandType::lowpass || t.filter.band == BandType::bandpass;
  return check_model_family(measured_turns, s.clearance_revolutions, s.nominal, std::abs(t.crank_speed_rad_s) / units::kTwoPi,
                            has_top ? t.filter.high_hz : 0.0, settings);
}

ModelFamilyCheck family_check_at(const RecordingTarget& t, const std::vector<double>& measured_turns,
                                 const ContactParameters& p, int warmup, int turns, const ModelFamilySettings& settings,
                                 std::string* vibration_not_checked) {
  TheorySettings ts;
  ts.restitution = p.restitution;
  ts.contact = p.contact;
  ts.friction_coefficient = p.friction_coefficient;
  ts.warmup_revolutions = warmup;
  ts.averaged_revolutions = turns;
  MatchedTheory theory = simulate_matched_theory(*t.rig, t.clearance_m, t.crank_speed_rad_s, t.grid, ts);
  ModelFamilyCheck c = family_check_of(t, measured_turns, theory, settings);
  if (!c.checked || !(t.rig->coupler_elastic || t.rig->rocker_elastic)) return c;
  // The rig gives the links' modes: where does the measurement lie between
  // the same contact with rigid and with elastic links (as the report's
  // verdict asks, compare/link_vibration.hpp)?
  ElasticReferenceRun where;
  where.rig = t.rig.get();
  where.clearance_m = t.clearance_m;
  where.crank_speed_rad_s = t.crank_speed_rad_s;
  where.grid = t.grid;
  where.filter = t.filter;
  where.sensor = t.sensor;
  where.name = t.name;
  // The reference at e within [0.5, 0.9]: the fitted e may sit at the box's
  // floor, where the compliant contact's calibrated damping diverges (e = 0
  // failed: the linkage's accelerations could not be solved), and over
  // 0.5–0.9 the measurement's position between the two models barely moves
  // (docs/verdict.md "Link vibration"; above 0.9 elastic_reference caps it).
  TheorySettings reference = ts;
  reference.restitution = std::max(ts.restitution, kFitReferenceMinRestitution);
  const ElasticReference ref = elastic_reference(where, reference, settings, c.checked_up_to_hz);
  if (!ref.theory) {
    if (vibration_not_checked) *vibration_not_checked = ref.not_run;
    return c;
  }
  const LinkQuantity q = checked_quantity(t);
  const TheorySeries& s = theory.series[index_of(q)];  // (through the pass band: family_check_of)
  (void)check_link_vibration(c, measured_turns, s.clearance_revolutions,
                             ref.rigid_links->series[index_of(q)].clearance_revolutions,
                             ref.theory->series[index_of(q)].clearance_revolutions, s.nominal);
  return c;
}

ModelFamilyCheck elastic_family_check_at(const RecordingTarget& t, const std::vector<double>& measured_turns,
                                         const ContactParameters& p, int warmup, int turns, double tolerance,
                                         const FitModel& model, const ModelFamilySettings& settings) {
  MatchedTheory theory = simulate_linkage_turns(t, p, warmup, turns, tolerance, model, t.grid);
  return family_check_of(t, measured_turns, theory, settings);
}

namespace {

/// What the orbit search found, as a clause of the periodic note.
std::string orbit_clause(const OrbitSearchResult& r, int period) {
  const std::string p = std::to_string(period);
  const std::string how = "; Newton shooting on the model at the best point (its turn map at the recording's mean speed, "
                          "started from its own turn starts) ";
  if (r.starts == 0) return how + "could not run: the model's own run failed there";
  for (const FoundOrbit& o : r.orbits)
    if (o.stable)
      return how + "finds a stable period-" + p + " motion from start " + std::to_string(r.starts) + " (a run on it repeats to " +
             format_number(o.repeat_distance, 2) + " of the clearance's scale): the model has the recorded kind of motion, "
             "and its runs from the fit's start do not take it";
  return how + "finds no stable period-" + p + " motion from " + std::to_string(r.starts) + " starts (" +
         std::to_string(r.converged) + " converged, onto " + std::to_string(r.orbits.size()) + " unstable orbits)";
}

}  // namespace

std::string periodic_recordings_note(const std::vector<RecordingTarget>& targets,
                                     const std::vector<std::optional<std::array<TurnRepeat, 2>>>& model,
                                     const std::vector<std::optional<OrbitSearchResult>>& orbits) {
  std::string which;
  bool model_irregular = false, stable_found = false, searched = false;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const RecordingTarget& t = targets[k];
    for (FitLink l : kFitLinks) {
      const auto i = static_cast<std::size_t>(l);
      const TurnRepeat& r = t.repeat[i];
      if (!t.measured[i] || r.period < 2) continue;
      which += std::string(which.empty() ? "" : "; ") + t.name + "'s " + std::string(name_of(l)) + " repeats every " +
               std::to_string(r.period) + " turns (turn i against turn i + " + std::to_string(r.period) + ": " +
               format_number(r.ratio(), 2) + " of what irregular turns give, against " + format_number(r.neighbours(), 2) +
               " for neighbouring turns)";
      if (k < model.size() && model[k]) {
        const double m = (*model[k])[i].by_lag[r.period - 1];
        const bool repeats = m < kTurnRepeatRatio;
        model_irregular = model_irregular || !repeats;
        which += ", the model's run at the best point " + std::string(repeats ? "repeats too" : "does not") + " (" +
                 format_number(m, 2) + ")";
        if (!repeats && k < orbits.size() && orbits[k]) {
          searched = true;
          stable_found = stable_found || orbits[k]->any_stable();
          which += orbit_clause(*orbits[k], static_cast<int>(r.period));
        }
      }
      break;  // one link per recording
    }
  }
  if (which.empty()) return "";
  std::string tail = " (docs/fit.md \"A periodic recording\")";
  if (model_irregular && stable_found)
    tail = " So the rejection may come from the motion the runs took rather than from a wrong model" + tail;
  else if (model_irregular && searched)
    tail = " The search covers the best point only: a model with other parameters may hold the motion (on a test session it "
           "was found at the true parameters and not at the best point), and the fit's runs compare the "
           "recording with the model's usual motion either way; so the rejection may still come from the motion its "
           "runs took rather than from a wrong model. `fourbar fit SESSION_DIR --orbit-scan` searches every " +
           format_number(kOrbitScanStep, 2) + " of the box's e (10-30 s a point and recording)" + tail;
  else if (model_irregular)
    tail = " A model may have such a motion beside an irregular one and not reach it from the recording's start; then "
           "the rejection may come from the motion its runs took rather than from a wrong model" + tail;
  return "the measured turns hold a periodic motion: " + which + "." + tail;
}

}  // namespace fourbar
