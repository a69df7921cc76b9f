#pragma once
// The fit's search for periodic motions of the model (docs/fit.md "A
// periodic recording"): when a recording's turns repeat every p turns and
// the model's run at the best point does not, Newton shooting on the
// three-mode model's turn map (sim/studies/periodic_orbit.hpp) for a stable
// period-p motion at the best point and, with `fourbar fit --orbit-scan`,
// at every kOrbitScanStep of the box's e.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fit/recording_target.hpp"
#include "sim/studies/periodic_orbit.hpp"

namespace fourbar {

/// One point of the orbit scan (FitOptions::orbit_scan): the contact
/// parameters and whether Newton shooting found a stable motion there.
struct OrbitScanPoint {
  ContactParameters parameters;
  bool stable = false;
  int starts = 0;
};
/// The scan's step in e.
inline constexpr double kOrbitScanStep = 0.05;

/// The scan of one recording (period p) as a note: where the model holds a
/// stable period-p motion, of the points checked; "" for an empty scan.
std::string orbit_scan_note(const std::string& recording, int period, const std::vector<OrbitScanPoint>& scan);

/// Newton starts for the fit's orbit search (the model's own turn starts):
/// on the e = 0.8 session's period-2 recording 6 of 100 reach its stable
/// orbit, so 60 miss it with a chance of about 2 % (docs/fit.md "A periodic
/// recording"). About 0.5 s a start at 250 rpm; the search stops at the first
/// stable orbit.
inline constexpr int kOrbitSearchStarts = 60;

/// Newton shooting for a stable motion of the measured `period` in the
/// three-mode model at contact parameters `p`, the recording's speed and
/// clearance (sim/studies/periodic_orbit.hpp).
OrbitSearchResult search_periodic_orbit(const RecordingTarget& target, const ContactParameters& p, double tolerance,
                                        int period, int starts = kOrbitSearchStarts);

/// Scan points of one recording: the orbit search at every kOrbitScanStep of
/// [restitution_low, restitution_high], smooth and (when `best` is
/// stick-slip) at its μ, on `threads` threads.
struct OrbitSearchOptions {
  double tolerance = 1e-8;
  unsigned threads = 1;
  double restitution_low = 0, restitution_high = 1;
  bool scan = false;        ///< FitOptions::orbit_scan
  bool three_mode = true;   ///< the fitted model is the three-mode one (the turn map's); else nothing is searched
};
struct FitOptions;
/// The fit's options as the search's (fit/session_fit.hpp).
OrbitSearchOptions orbit_search_options(const FitOptions& o);

std::vector<OrbitScanPoint> scan_periodic_orbits(const RecordingTarget& target, const ContactParameters& best,
                                                 const OrbitSearchOptions& o, int period);

/// Per recording: the best-point search (absent where not run: no measured
/// period, or the model's run repeats too) and, with the scan, its notes.
struct PeriodicSearch {
  std::vector<std::optional<OrbitSearchResult>> best_point;
  std::vector<std::string> scan_notes;
};
PeriodicSearch search_periodic_recordings(const std::vector<RecordingTarget>& targets,
                                          const std::vector<std::optional<std::array<TurnRepeat, 2>>>& model,
                                          const ContactParameters& best, const OrbitSearchOptions& o);

/// The rejection's notes on periodic recordings: periodic_recordings_note
/// (fit/family_judgement.hpp) with the best-point searches, then the scan's.
std::vector<std::string> periodic_notes(const std::vector<RecordingTarget>& targets,
                                        const std::vector<std::optional<std::array<TurnRepeat, 2>>>& model,
                                        const ContactParameters& best, const OrbitSearchOptions& o);

}  // namespace fourbar
