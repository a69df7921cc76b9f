#pragma once
// The fit of the bearing's contact parameters to a session's recordings
// (docs/fit.md).
//
// Parameters: the restitution e and, with `fit_friction`, the Coulomb μ of
// the stick-slip law (μ = 0 is the smooth law: the stick-slip impulse's
// tangential part is bounded by μ·F). Shared by all recordings by default.
//
// Objective: χ²(p) = Σ over recordings, links and chosen statistics of
//   (T(S_model(p)) − T(S_measured))² / (se_measured² + se_model²),
// T = log for magnitudes; se from the jackknife over turns on both sides, so
// a statistic counts by how well the measurement (and the finite simulation)
// pins it down. The model is the clearance simulator at each recording's
// operating point, `warmup_turns` discarded and `simulated_turns` kept.
//
// Search: NLopt's DIRECT-L over the box (global), then BOBYQA from its best
// point (local, derivative-free, on the noisy objective). Every simulation
// is cached by (recording, e, μ); the recordings of one evaluation, and the
// points of the profile grid, are spread over the threads (or MPI ranks) by
// cluster/case_queue.
//
// Uncertainty: χ² is noisy (chaos: nearby points come from different
// trajectories). Its noise is measured by replicates at the lowest point
// (objective_noise.hpp: e nudged by 0.001 …), and the interval is where the
// profile stays within Δ of the bottom: the `interval_level` quantile of
// the one-parameter profile ratio (χ²₁, scaled by the dispersion when the
// statistics scatter more than their errors) plus the objective's own noise.
// The profile is that of a quadratic fitted to the evaluated points near the
// bottom when one is curved upwards there (objective_surrogate.hpp), else
// the raw profile of the grid over the box. An
// interval wider than `identifiable_width` of its box is reported as not
// identifiable. The raw profiles (grid of the box) are kept for the charts.

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fit/family_judgement.hpp"
#include "fit/fit_model.hpp"
#include "fit/matched_magnification.hpp"
#include "fit/objective_noise.hpp"
#include "fit/recording_target.hpp"

namespace fourbar {

struct FitBox {
  double restitution_low = 0.0, restitution_high = 1.0;
  double friction_low = 0.0, friction_high = 0.5;
};

/// Width (log scale) of the shared offset each compared statistic of the
/// model may carry from modelling choices without a physical counterpart
/// (nuisance_offset.hpp; measured: docs/fit.md "Modelling choices").
struct ModellingOffsetSigma {
  std::array<double, kResponseStatisticCount> statistic{};  ///< per ResponseStatistic (0: none)
  double band = 0;                                          ///< the band energy above the averaging filter
};
/// The defaults (docs/fit.md "Modelling choices"): the spread's from the
/// settle speed (its change beyond the replicates' noise, 2.2 %); the band
/// energy's from the settle speed (7.4 %) and, in quadrature, the contact's
/// duration below the band top: a half-sine contact of 0.1–0.3 ms keeps
/// 0.94–0.62 of a rigid impulse's RMS in 1–3.84 kHz (log −0.06 … −0.48,
/// covered at 2σ by 0.25).
inline constexpr double kSpreadOffsetSigma = 0.022;
inline constexpr double kBandOffsetSigma = 0.26;
ModellingOffsetSigma default_modelling_offset_sigma();

struct FitOptions {
  FitBox box;
  bool fit_friction = true;        ///< μ fitted too (stick-slip); false: smooth law, e only
  int warmup_turns = 20;
  int simulated_turns = 50;        ///< turns per simulation kept for the statistics
  double tolerance = 1e-8;         ///< integrator tolerance
  FitModel model;                  ///< the theory fitted (default: the three-mode model)
  unsigned threads = 1;
  int global_evaluations = 16;     ///< DIRECT-L
  int local_evaluations = 10;      ///< BOBYQA
  int profile_points_e = 8;        ///< grid of the profile along e
  int profile_points_mu = 5;       ///< … along μ
  double identifiable_width = 0.5; ///< an interval wider than this share of its box: not identifiable
  int replicates = 4;              ///< extra χ² evaluations at the lowest point (e nudged) that measure the objective's noise
  double interval_level = 0.95;    ///< confidence level of each parameter's interval
  bool use_band = true;            ///< the band energy above the averaging filter, where recorded
  /// The statistics compared besides the band energy: those that carry e or
  /// μ above their noise (docs/fit.md: sensitivity per statistic). Each extra
  /// statistic that carries nothing adds its noise to χ² (≈ √2 per term).
  std::vector<ResponseStatistic> statistics{ResponseStatistic::spread};
  /// The modelling choices' spread carried as a profiled nuisance offset.
  ModellingOffsetSigma modelling_offset_sigma = default_modelling_offset_sigma();
  /// Turns of the runs at the fit and the prior that give the magnification
  /// factor a (0: kMagnificationTurnsPerMeasuredTurn × the most measured turns).
  int magnification_turns = 0;
  /// When the family is rejected and a recording's turns repeat every p
  /// turns while the model's do not: Newton shooting for a stable period-p
  /// motion at every kOrbitScanStep of the box's e (smooth contact, and the
  /// best point's μ when it is stick-slip), not only at the best point
  /// (`fourbar fit --orbit-scan`; 10–30 s a point and recording).
  bool orbit_scan = false;
  /// Called after each simulation (progress for `fourbar fit`); may be empty.
  std::function<void()> on_simulation;
};

/// About how many simulations a fit of `recordings` recordings runs (the
/// global and local search, the profile grid, the replicates and the runs
/// for a): the total of `fourbar fit`'s progress bar.
std::size_t expected_simulations(std::size_t recordings, const FitOptions& options);

/// Throws InputError naming the option when the box is backwards or out of
/// range, or a count is not positive.
void validate_fit_options(const FitOptions& options);

struct ParameterEstimate {
  std::string name;          ///< "restitution", "friction_coefficient"
  double value = 0, low = 0, high = 0;
  bool identifiable = true;
  /// The interval runs to the top of a box whose top is no physical bound
  /// (μ): the data bound the parameter from below only (not identifiable;
  /// for μ: above `low` the impacts stick and the statistics no longer change).
  bool lower_bound_only = false;
  std::vector<double> profile_at, profile_chi2;  ///< the profile (parameter value, min χ² there)
};

/// Sets `identifiable` and `lower_bound_only` of an estimate from its
/// interval: wider than `identifiable_width` of the box → not identifiable;
/// reaching the box's top but not its bottom when the top is no physical
/// bound (μ; e ≤ 1 is one) → bounded from below only, not identifiable.
void judge_identifiability(ParameterEstimate& p, double box_low, double box_high, bool top_is_physical,
                           double identifiable_width);

struct RecordingFitTerm {
  std::string name;
  double chi2 = 0;           ///< this recording's part of χ² at the optimum
  int terms = 0;
  double chi2_prior = 0;     ///< … at the prior (session.toml) parameters
};

struct FitResult {
  std::vector<ParameterEstimate> parameters;  ///< restitution, then friction_coefficient when fitted
  ContactParameters best;
  double chi2 = 0;           ///< at the optimum
  int terms = 0;             ///< ν: statistics compared
  double chi2_prior = 0;     ///< at the prior
  /// The profiled modelling-choice offset η̂ (log) of each compared statistic
  /// at the optimum (nuisance_offset.hpp): model = measured × e^η̂ on average.
  std::vector<std::pair<std::string, double>> modelling_offsets;
  double interval_delta = 0; ///< Δχ² above the bottom that bounded the intervals (objective_noise.hpp)
  ObjectiveNoise noise;      ///< the objective's noise from the replicates, the dispersion, the level
  bool surrogate_ok = false; ///< the smooth model of χ² had a minimum (else: raw grid profile)
  double surrogate_residual_rms = 0;
  std::optional<double> correlation;  ///< of e and μ over the profile region (weights e^(−Δχ²/2))
  std::vector<RecordingFitTerm> recordings;
  int evaluations = 0;       ///< objective evaluations (NLopt + profile)
  int simulations = 0;       ///< simulations run (cache misses)
  int simulations_on_rank_0 = 0;  ///< of these, run by this process (fewer under MPI: the other ranks ran the rest)
  long long turns_simulated = 0;
  double seconds = 0;        ///< wall time
  double cpu_seconds = 0;    ///< CPU time of the process over the fit (all threads)
  double seconds_per_simulation = 0;  ///< CPU time per simulation (wall × threads / simulations, approx.)
  /// The simulations' CPU time (each on its thread's clock; this process's
  /// only under MPI) and the wall time they would take on `threads` idle
  /// cores (SimulationCache::idle_wall_seconds).
  double simulation_cpu_seconds = 0, simulation_idle_wall_seconds = 0;
  /// Magnification factor a of α3 (α4 without a coupler channel) per
  /// recording, at the fit and at the prior, with its standard error: the
  /// model's expected RMS of the averaged deviation of the measured number
  /// of turns (from a run of `magnification_turns` turns) over the
  /// measurement's (matched_magnification.hpp).
  std::vector<std::optional<MatchedMagnification>> magnification_fitted, magnification_prior;
  int magnification_turns = 0;        ///< turns of the runs that give a (after the warm-up)
  int magnification_simulations = 0; ///< those runs (included in `simulations`)
  /// Averaged over R turns, a deviation that varies from turn to turn leaves
  /// its scatter σ/√R in the average (σ: the spread statistic). Per recording:
  /// (σ/√R)/RMS(averaged deviation) of the measurement (near 1: the averaged
  /// deviation is scatter, not a repeatable curve), and the a that the two
  /// scatters alone would give at the fit over the same number of turns,
  /// σ_model/σ_measured.
  std::vector<std::optional<double>> measured_scatter_share, magnification_from_scatter_fitted;
  std::vector<std::string> notes;     ///< not identifiable, model family, …
  /// Whether the model family describes the measurement (family_judgement.hpp).
  FamilyJudgement model_family;
};

/// χ² per term above which the fit says the model family differs from
/// what was measured (the statistics' noise would give ≈ 1).
inline constexpr double kModelFamilyChi2PerTerm = 4.0;

/// Rejects the model family of `f` with `reason` (a recording's unmodelled
/// energy, found by the caller): family_judgement.hpp says what changes.
void reject_model_family(FitResult& f, const std::string& reason, const FitOptions& options);

/// Fits `targets` together. `prior` is the session's setting (reported beside).
FitResult fit_contact_parameters(const std::vector<RecordingTarget>& targets, const ContactParameters& prior,
                                 const FitOptions& options);

/// Whether the recordings show a clearance effect above their noise: the
/// largest RecordingTarget::effect_ratio (turn-to-turn variation over the
/// sensor-noise floor). Below kEffectRatio there is nothing to fit.
double clearance_effect_ratio(const std::vector<RecordingTarget>& targets);
inline constexpr double kEffectRatio = 3.0;

}  // namespace fourbar
