#include "fit/orbit_search.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <thread>
#include <utility>

#include "common/format.hpp"
#include "compare/matched_theory.hpp"
#include "fit/family_judgement.hpp"
#include "fit/session_fit.hpp"

namespace fourbar {

OrbitSearchResult search_periodic_orbit(const RecordingTarget& t, const ContactParameters& p, double tolerance, int period,
                                        int starts) {
  const TheorySettings ts = theory_settings(p, 0, 0, tolerance);
  OrbitSearchSettings s;
  s.period = period;
  s.starts = starts;
  s.stop_at_first_stable = true;
  try {
    const TurnMap map(*t.rig, t.clearance_m, t.crank_speed_rad_s, clearance_settings(*t.rig, t.clearance_m, ts));
    return find_periodic_orbits(map, s);
  } catch (const std::exception&) {  // the model's own run failed there: nothing searched (starts = 0)
    return {};
  }
}

std::string orbit_scan_note(const std::string& recording, int period, const std::vector<OrbitScanPoint>& scan) {
  if (scan.empty()) return "";
  // Grouped by contact law and μ, in the order scanned.
  std::string text;
  for (std::size_t i = 0; i < scan.size();) {
    const ContactParameters& first = scan[i].parameters;
    std::string law = first.contact == ContactLaw::stick_slip ? "stick-slip, mu " + format_number(first.friction_coefficient, 3)
                                                               : std::string("smooth");
    std::string stable, checked;
    for (; i < scan.size() && scan[i].parameters.contact == first.contact &&
           scan[i].parameters.friction_coefficient == first.friction_coefficient;
         ++i) {
      const std::string e = format_number(scan[i].parameters.restitution, 3);
      // starts = 0: the model's own run failed there, nothing was searched.
      checked += (checked.empty() ? "" : ", ") + e + (scan[i].starts == 0 ? " (model run failed)" : "");
      if (scan[i].stable) stable += (stable.empty() ? "" : ", ") + e;
    }
    text += std::string(text.empty() ? "" : "; ") + "(" + law + ") " +
            (stable.empty() ? "at none of e = " + checked : "at e = " + stable + " of e = " + checked);
  }
  return "orbit scan of " + recording + ": the model holds a stable period-" + std::to_string(period) + " motion " + text +
         " (Newton shooting from up to " + std::to_string(kOrbitSearchStarts) +
         " of its own turn starts at each point; an e where none was found may still hold one with a small basin). "
         "Where it does, the model has a motion of the recording's period, which the fit's runs, from the model's "
         "usual start, do not take; whether it is the recorded motion is not checked (docs/fit.md \"A periodic "
         "recording\")";
}

std::vector<OrbitScanPoint> scan_periodic_orbits(const RecordingTarget& t, const ContactParameters& best,
                                                 const OrbitSearchOptions& o, int period) {
  std::vector<OrbitScanPoint> points;
  std::vector<ContactParameters> laws{ContactParameters{0, ContactLaw::smooth, 0}};
  if (best.contact == ContactLaw::stick_slip && best.friction_coefficient > 0) laws.push_back(best);
  for (const ContactParameters& law : laws)
    for (double e = std::ceil(o.restitution_low / kOrbitScanStep - 1e-9) * kOrbitScanStep;
         e <= o.restitution_high + 1e-9; e += kOrbitScanStep) {
      OrbitScanPoint p;
      p.parameters = law;
      p.parameters.restitution = std::round(e / kOrbitScanStep) * kOrbitScanStep + 0.0;  // + 0.0: no "-0" in the note
      points.push_back(p);
    }
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i; (i = next++) < points.size();) {
      const OrbitSearchResult r = search_periodic_orbit(t, points[i].parameters, o.tolerance, period);
      points[i].stable = r.any_stable();
      points[i].starts = r.starts;
    }
  };
  std::vector<std::thread> pool;
  for (unsigned k = 1; k < std::max(1u, o.threads); ++k) pool.emplace_back(work);
  work();
  for (std::thread& th : pool) th.join();
  return points;
}

OrbitSearchOptions orbit_search_options(const FitOptions& o) {
  return {o.tolerance, std::max(1u, o.threads), o.box.restitution_low, o.box.restitution_high, o.orbit_scan,
          o.model.kind == FitModelKind::three_mode};
}

PeriodicSearch search_periodic_recordings(const std::vector<RecordingTarget>& targets,
                                          const std::vector<std::optional<std::array<TurnRepeat, 2>>>& model,
                                          const ContactParameters& best, const OrbitSearchOptions& o) {
  PeriodicSearch out;
  out.best_point.resize(targets.size());
  if (!o.three_mode) return out;
  for (std::size_t r = 0; r < targets.size(); ++r)
    for (FitLink l : kFitLinks) {
      const auto i = static_cast<std::size_t>(l);
      const std::size_t p = targets[r].repeat[i].period;
      if (!targets[r].measured[i] || p < 2) continue;
      if (r < model.size() && model[r] && (*model[r])[i].by_lag[p - 1] >= kTurnRepeatRatio) {
        out.best_point[r] = search_periodic_orbit(targets[r], best, o.tolerance, static_cast<int>(p));
        if (o.scan)
          out.scan_notes.push_back(
              orbit_scan_note(targets[r].name, static_cast<int>(p), scan_periodic_orbits(targets[r], best, o, static_cast<int>(p))));
      }
      break;  // one link per recording, as the note
    }
  return out;
}

std::vector<std::string> periodic_notes(const std::vector<RecordingTarget>& targets,
                                        const std::vector<std::optional<std::array<TurnRepeat, 2>>>& model,
                                        const ContactParameters& best, const OrbitSearchOptions& o) {
  PeriodicSearch searched = search_periodic_recordings(targets, model, best, o);
  std::vector<std::string> notes;
  if (std::string periodic = periodic_recordings_note(targets, model, searched.best_point); !periodic.empty())
    notes.push_back(std::move(periodic));
  for (std::string& n : searched.scan_notes) notes.push_back(std::move(n));
  return notes;
}

}  // namespace fourbar
