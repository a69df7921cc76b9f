#pragma once
// The verdict of one recording: four answers in words for the technician,
// each a level and one sentence that says what to do (docs/verdict.md gives
// every threshold and its reason).
//
//   set-up            does the data agree with the manifest (the set-up check);
//   measurement       noise floor of the averaged α3 against the nominal
//                     response, clipped turns, crank-speed steadiness, turns
//                     averaged (too few: how many to record);
//   clearance effect  is an effect of the clearance seen at all: the
//                     measured α3 deviation's order lines above the nominal
//                     band, clear of mains hum, in multiples of the floor
//                     between the lines, and the turn-to-turn scatter against
//                     the nominal response;
//   model family      energy the model family lacks (link vibration, sensor
//                     resonance: report/verdict_family.hpp); when found, the
//                     model agreement is judged below its band only;
//   model agreement   the magnification factor a (spectral when it has
//                     orders, else time; from the turn-to-turn scatter when
//                     the effect is chaotic) and how to act on it; the fitted
//                     contact parameters when a fit.json is given.
//
// verdict_of is a pure function of VerdictInputs; verdict_inputs reads them
// from a recording's record (comparison_record + recording_job +
// setup_check_record) and an optional fit.json (fit/fit_json.hpp).

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/verdict_family.hpp"

namespace fourbar {

enum class VerdictLevel { good, attention, problem, not_judged };
const char* to_string(VerdictLevel level);

// Thresholds (docs/verdict.md "Reading the verdict" says why each).
/// Fewer turns and the floor between order lines cannot be estimated (compare/magnification.cpp).
inline constexpr std::size_t kMinRevolutionsForFloor = 6;
/// Floor of the averaged α3 over its nominal RMS: good at most 5 %, a problem above 15 %.
inline constexpr double kFloorGood = 0.05, kFloorProblem = 0.15;
/// Crank speed std over mean: good at most 1 %, a problem above 3 %.
inline constexpr double kSpeedGood = 0.01, kSpeedProblem = 0.03;
/// Share of turns clipped (left out of the averages) above which it is a problem.
inline constexpr double kClippedProblem = 0.25;
/// Order lines over the floor between them: noise alone gives ≈ 1.2; seen at 3 (the significance of one order).
inline constexpr double kEffectNone = 2.0, kEffectSeen = 3.0;
/// Turn-to-turn scatter of α3 over its nominal RMS: none below 5 %, seen from 10 %.
inline constexpr double kScatterNone = 0.05, kScatterSeen = 0.10;
/// Magnification factor a: good within [0.8, 1.25], a problem outside [0.5, 2].
inline constexpr double kAgreeLow = 0.8, kAgreeHigh = 1.25, kAgreeProblemLow = 0.5, kAgreeProblemHigh = 2.0;
/// a (time) and a (spectral) further apart than this factor get a word on why.
/// An effect seen in the scatter only (order lines below kEffectSeen) is
/// judged by a (scatter) = model scatter / measured scatter: the averages of
/// chaotic turns compare chance residues.
inline constexpr double kTimeSpectralApart = 1.5;
/// a (scatter) compares the model's turn-to-turn scatter with the measured
/// one: a theory averaged over fewer turns has no scatter to compare (one
/// turn: none at all, a = 0), so the agreement then asks for more turns.
inline constexpr std::size_t kMinModelTurnsForScatter = 8;
/// When the effect is chaotic and the model expects it (its scatter ≥
/// kScatterSeen), the floor between order lines of the averaged α3 is the
/// impacts' own turn-to-turn scatter, not a measurement fault: the
/// measurement is then judged by the relative standard error of the a the
/// verdict judges by, a (scatter): good at most 12.5 % (a ± 2 standard errors
/// inside the ±25 % agreement band), a problem above 25 %.
inline constexpr double kScatterErrorGood = 0.125, kScatterErrorProblem = 0.25;

struct VerdictFinding {
  std::string item, channel, key, manifest, data;
  double confidence = 0;
};

/// The fitted contact parameters (fit.json), when a fit was run.
struct VerdictFit {
  std::string file;  ///< where it was read
  double restitution = 0, restitution_low = 0, restitution_high = 0;
  bool restitution_identifiable = true;
  std::string contact;
  std::optional<double> friction;
  std::optional<double> magnification_fitted;  ///< this recording's a at the fitted parameters
  std::optional<double> magnification_fitted_standard_error;  ///< its standard error (absent in older fits)
};

struct VerdictInputs {
  // Set-up check.
  bool setup_checked = false;
  std::string setup_not_checked;  ///< why not
  std::vector<VerdictFinding> findings;
  // Measurement.
  std::size_t revolutions = 0;          ///< averaged
  std::size_t revolutions_clipped = 0;  ///< left out
  bool clipping_checked = true;
  double speed_mean_rpm = 0, speed_std_rpm = 0;
  double nominal_rms = 0;               ///< of the nominal α3 (rad/s²)
  double floor_rms = 0;                 ///< floor of the averaged α3 between order lines (0: unknown)
  // Clearance effect.
  double clearance_mm = 0;
  std::optional<double> effect_to_floor, model_effect_to_floor;
  double spread_rms = 0, model_spread_rms = 0;  ///< turn-to-turn scatter of α3, measured and model
  /// Relative standard error of their ratio, a (scatter) (jackknife over turns; absent in older records).
  std::optional<double> scatter_relative_error;
  int nominal_band_orders = 0;
  // Model agreement.
  std::optional<double> a_time, a_spectral;
  std::vector<int> orders_used;
  double restitution = 0;               ///< e of the theory in the report
  std::size_t model_revolutions = 0;    ///< turns the theory averaged ([theory] averaged_revolutions; 0: unknown)
  std::string contact;
  std::optional<VerdictFit> fit;
  std::optional<VerdictFamily> family;  ///< the record's model-family check (absent in older records)
  /// The measured α3 turns repeat every `period` turns (record
  /// metrics.alpha3_rad_s2.turns_repeat, fit/response_statistics.hpp
  /// turn_repeat): ratio at the period and at lag 1, and the model's ratio at
  /// the same lag when its turns are enough to tell (≥ 2·period + 4). Absent
  /// when the measured turns do not repeat, or in older records. With
  /// `confirmed` false the ratio passes at `period` but the measured turns
  /// (`turns`) are fewer than 2·period + 4 (record unconfirmed_period_turns):
  /// said, not weighed.
  struct Repeat {
    std::size_t period = 0;
    double ratio = 1, neighbours = 1;
    std::optional<double> model_ratio;
    std::size_t model_turns = 0;
    bool confirmed = true;
    std::size_t turns = 0;
  };
  std::optional<Repeat> repeat;
};

struct VerdictPart {
  VerdictLevel level = VerdictLevel::not_judged;
  std::string words;     ///< a few words for tables ("matches", "12x floor", "a 0.73")
  std::string sentence;  ///< what it means and what to do
};

struct Verdict {
  /// In the order of verdict_parts(); family: energy the model family lacks (verdict_family.hpp).
  VerdictPart setup, measurement, effect, family, agreement;
  /// The magnification factor the agreement part judged and where it came
  /// from: "spectral", "time", or "scatter" (model over measured turn-to-turn
  /// scatter, when the effect is chaotic and lives in the scatter, not in the average).
  std::optional<double> a;
  std::optional<double> a_standard_error;  ///< of a (scatter), when known
  std::string a_from;
  VerdictLevel overall = VerdictLevel::not_judged;  ///< the worst judged part
};

/// One part of the verdict as every output shows it: its key in summary.json
/// (`verdict.<key>`) and summary.csv (`verdict_<key>`), its label in the
/// report and the terminal, and where it sits in Verdict. Every output
/// iterates this list: a part more is a member of Verdict, its function in
/// verdict_of and one entry here.
struct VerdictPartInfo {
  const char* key;
  const char* label;
  VerdictPart Verdict::*part;
};
std::span<const VerdictPartInfo> verdict_parts();

Verdict verdict_of(const VerdictInputs& in);

/// From an analysed record (status "ok" or "check set-up", with series) and,
/// when given, a fit.json (`fit_file` names it in the sentences).
VerdictInputs verdict_inputs(const nlohmann::json& record, const nlohmann::json* fit = nullptr,
                             const std::string& fit_file = {});

/// {overall, <key of each verdict_parts()>: {level, words, sentence}, a, a_standard_error, a_from}.
nlohmann::json verdict_json(const Verdict& v);

}  // namespace fourbar
