#pragma once
// The verdict's model-family part (compare/model_family.hpp): energy in the
// measurement that the model family does not have — what, where in Hz, how
// strong — and, when there is some, the model agreement judged again below
// the first unmodelled band only (a (scatter) of α3 low-passed there), or
// "not judged" when nothing is left below it to judge.
// docs/verdict.md "Model family" gives the thresholds and their reasons.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/link_vibration.hpp"
#include "compare/model_family.hpp"

namespace fourbar {

struct VerdictPart;
struct VerdictInputs;
struct Verdict;

/// What the verdict reads of a record's "model_family".
struct VerdictFamily {
  bool checked = false;
  std::string not_checked;
  double checked_up_to_hz = 0;
  std::vector<UnmodelledEnergy> unmodelled;
  std::optional<double> judged_below_hz, a_scatter_below;
  std::string cannot_judge;
  /// Findings set aside because they move with the crank speed
  /// (report/family_across_speeds.hpp), and the sentence that says so.
  std::vector<UnmodelledEnergy> moves_with_speed;
  std::string moves_with_speed_text;
  /// The rig file has the links' modal data but the elastic-link reference
  /// did not run (e.g. no contact stiffness): why, said in the verdict.
  std::string link_vibration_not_run;
  /// The elastic-link reference ran (the rig file gives the links' modes):
  /// only then is an elastic link's broad ringing looked for.
  bool link_vibration_checked = false;
};

/// The record's "model_family" object.
nlohmann::json model_family_json(const ModelFamilyCheck& c);

/// summary.json → model_family.link_vibration (compare/link_vibration.hpp).
nlohmann::json link_vibration_json(const LinkVibrationCheck& v);
/// From a record; nullopt when the record has no "model_family" (older records).
std::optional<VerdictFamily> verdict_family(const nlohmann::json& record);

/// "narrow resonance at 575–625 Hz (peak 600 Hz), 62 % of the measured RMS".
std::string unmodelled_text(const UnmodelledEnergy& u);

/// The model-family part.
VerdictPart family_part(const VerdictInputs& in);
/// With unmodelled energy: the agreement (and a) judged below its first band only.
void judge_agreement_below_band(const VerdictInputs& in, Verdict& v);

}  // namespace fourbar
