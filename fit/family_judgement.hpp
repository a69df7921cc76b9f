#pragma once
// When the fitted model family does not describe the measurement, the
// parameter block must say so (docs/fit.md "When the model family is
// rejected"): the family is rejected when χ² per term at the best point
// stays above kModelFamilyChi2PerTerm (the statistics' noise gives ≈ 1), or
// when a recording holds energy the model lacks (compare/model_family.hpp,
// checked at the fitted parameters). Then
//   - no parameter is identifiable (the values are effective ones);
//   - each interval is re-read from the raw profile with the model-error
//     scale: Δχ² ≤ interval_delta · max(1, χ²/ν), and runs to the next grid
//     point on each side outside it, so it is never narrower than the
//     profile's resolution (a zero-width interval would claim a precision
//     the misfit denies);
//   - fit.json's first key is "model_family": {"verdict": "rejected",
//     "reasons": [...]} and the terminal's first line says so.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "compare/model_family.hpp"
#include "fit/fit_model.hpp"
#include "fit/recording_target.hpp"
#include "fit/orbit_search.hpp"

namespace fourbar {

struct ParameterEstimate;

struct FamilyJudgement {
  bool rejected = false;
  std::vector<std::string> reasons;
  double error_scale = 1;  ///< √max(1, χ²/ν): the statistics' misfit in standard errors (RMS)
  /// The spectral check (energy the model lacks): the model it compared with
  /// ("three-mode" or "elastic", empty: not run) and the recordings it checked.
  std::string spectral_model;
  int spectral_recordings = 0;
};

/// Widens `p`'s interval from its raw profile (profile_at, profile_chi2)
/// to Δχ² ≤ delta·scale² above the profile's lowest point, out to the next
/// grid point on each side (within [box_low, box_high]); not identifiable.
void widen_for_model_error(ParameterEstimate& p, double delta, double scale, double box_low, double box_high);

/// For a rejection's note: the recordings whose measured turns repeat every
/// few turns (RecordingTarget::repeat), whether the model's run at the best
/// point (`model[r]`, by link; absent when it failed) repeats at that period
/// too, what Newton shooting on the model found (`orbits[r]`, absent when not
/// run) and what that means for the verdict; "" when no recording repeats.
std::string periodic_recordings_note(const std::vector<RecordingTarget>& targets,
                                     const std::vector<std::optional<std::array<TurnRepeat, 2>>>& model,
                                     const std::vector<std::optional<OrbitSearchResult>>& orbits = {});

/// The elastic-link reference's restitution in the fit: the fitted e, at least this.
inline constexpr double kFitReferenceMinRestitution = 0.5;

/// The model-family check of one recording against `theory` (the model's α
/// turns on the target's grid): the target's pass band applied to `theory`
/// in place, then check_model_family on α3 (else α4) against `measured_turns`.
ModelFamilyCheck family_check_of(const RecordingTarget& target, const std::vector<double>& measured_turns,
                                 MatchedTheory& theory, const ModelFamilySettings& settings);

/// The model-family check of one recording at contact parameters `p`: the
/// matched theory (compare/matched_theory.hpp, `warmup` + `turns` turns) at
/// the target's operating point through its pass band, against
/// `measured_turns` (α3, else α4: turns × N on the target's grid).
/// When the rig gives the links' modes, also the link-vibration check
/// (compare/link_vibration.hpp) against the elastic-link reference
/// (compare/elastic_reference.hpp, the target's sensors: attach_sensors) at
/// the same e; when that reference cannot run, why goes to
/// `vibration_not_checked`.
ModelFamilyCheck family_check_at(const RecordingTarget& target, const std::vector<double>& measured_turns,
                                 const ContactParameters& p, int warmup, int turns, const ModelFamilySettings& settings,
                                 std::string* vibration_not_checked = nullptr);

/// The same check against the elastic-link model the fit used (`--model
/// elastic`: fit/linkage_statistics.hpp, its modes, contact stiffness and
/// integrator `tolerance`): energy the measurement holds that even the
/// ringing links do not give rejects the family.
ModelFamilyCheck elastic_family_check_at(const RecordingTarget& target, const std::vector<double>& measured_turns,
                                         const ContactParameters& p, int warmup, int turns, double tolerance,
                                         const FitModel& model, const ModelFamilySettings& settings);

}  // namespace fourbar
