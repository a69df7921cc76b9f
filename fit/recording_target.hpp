#pragma once
// One recording as a fit target: its operating point (rig, clearance, mean
// crank speed, crank-angle grid, the pass band it was analysed with) and the
// response statistics of its coupler and rocker α; and the same statistics of
// the clearance model at that operating point for given contact parameters.
//
// The simulated side goes through the processing the measurement went
// through from the link motion on: the matched theory (compare/) samples α
// as cell means on the measurement's grid (what an anti-aliased
// accelerometer sees of an impact), the measurement's pass band is applied in
// the crank-angle domain (apply_pass_band), and the statistics are taken
// with the same function on the same grid. What it does not repeat is the
// sensor: noise, hum and quantisation enter the measured statistics only
// (docs/fit.md measures how much; the fit weights each statistic by the
// measurement's own standard error).

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analyze/filter_design.hpp"
#include "analyze/pipeline.hpp"
#include "compare/link_quantity.hpp"
#include "compare/matched_theory.hpp"
#include "fit/response_statistics.hpp"
#include "mechanism/rig.hpp"

namespace fourbar {

/// The contact parameters the fit varies (names as in session.toml [theory]).
struct ContactParameters {
  double restitution = 0.5;
  ContactLaw contact = ContactLaw::smooth;
  double friction_coefficient = 0.0;
};

/// The two links whose α the statistics are taken of.
enum class FitLink { coupler = 0, rocker = 1 };
inline constexpr std::array<FitLink, 2> kFitLinks{FitLink::coupler, FitLink::rocker};
std::string_view name_of(FitLink l);

struct RecordingTarget {
  std::string name;                 ///< the recording's file name
  std::shared_ptr<const Rig> rig;
  double clearance_m = 0;
  double crank_speed_rad_s = 0;
  CrankGrid grid;
  FilterSpec filter;                ///< the α pass band as analysed
  std::size_t turns = 0;            ///< measured turns in the statistics
  std::array<std::vector<double>, 2> nominal;  ///< nominal α3, α4 through the pass band
  std::array<std::optional<StatisticValues>, 2> measured;  ///< by FitLink; absent without the channel
  /// The band above the averaging filter (band_analysis_options): absent
  /// when the sample rate leaves no such band.
  std::optional<FilterSpec> band_filter;
  std::size_t band_grid_points_per_rev = 0;  ///< a whole multiple of grid.grid_points_per_rev
  std::array<std::optional<BandEnergy>, 2> measured_band;
  /// How far the turn-to-turn variation stands above the sensor noise: the
  /// largest over the links of excess / floor (band_energy) of the band
  /// above the averaging filter, or, without that band, of the analysis
  /// band's deviations from the averaged curve. White noise alone gives
  /// ≈ 0.6 for 25 turns (the scatter of the 10 % quantile).
  double effect_ratio = 0;
  /// Each link's tangential accelerometer as analyze used it (by FitLink):
  /// what the elastic-link model reads (attach_sensors, linkage_statistics.hpp).
  std::array<std::optional<ResolvedMount>, 2> sensor;
  /// Whether each link's measured turns repeat every few turns (turn_repeat,
  /// on the analysis band's α): a periodic motion, which a model run from
  /// the recording's start may not take (docs/fit.md "A periodic recording").
  std::array<TurnRepeat, 2> repeat;
};

/// The analysis of the band above the averaging filter: band-pass from the
/// α filter's upper corner to kBandTopPerSampleRate × the sample rate, on a
/// grid that is a whole multiple of the analysis grid and holds the band.
/// Empty when the band would be narrower than an octave. `band_top_hz` > 0
/// caps the upper edge (below kBandTopPerSampleRate × the sample rate).
std::optional<AnalyzeOptions> band_analysis_options(const RecordingAnalysis& analysis, AnalyzeOptions base,
                                                    double band_top_hz = 0);
/// Upper edge of the band, per sample rate: well below Nyquist, where the
/// sample-period mean of an accelerometer (and the model's cell mean) still
/// pass most of the signal (sinc(0.3) = 0.86).
inline constexpr double kBandTopPerSampleRate = 0.3;
/// `fourbar fit`'s default cap of the band's upper edge: a rigid impact is an
/// impulse, a real (compliant) one lasts 0.1–0.3 ms and its spectrum falls
/// above ≈ 1/(3·duration); above this the band energy measures the contact's
/// duration, which the three-mode model does not have (docs/fit.md "Band
/// top": measured on the independent generator's sessions).
inline constexpr double kBandTopHz = 3840.0;

/// The target of an analysed recording (analysis with keep_revolutions).
/// InputError when it has neither link's α or fewer than 8 turns.
/// `band`: the same recording analysed with band_analysis_options (may be null).
RecordingTarget make_recording_target(const RecordingAnalysis& analysis, const RecordingAnalysis* band,
                                      const std::string& name);

struct SimulatedStatistics {
  std::array<std::optional<StatisticValues>, 2> link;  ///< by FitLink (only those the target has)
  std::array<std::optional<BandEnergy>, 2> band;       ///< when the target has the band
  double impacts_per_rev = 0;                          ///< above the simulator's settle speed
  double sum_normal_impulse_per_rev_Ns = 0;            ///< ΣF
  int turns = 0;
  std::array<TurnRepeat, 2> repeat;                    ///< of the kept turns after the pass band (turn_repeat)
};

/// Modelling choices without a physical counterpart (TheorySettings;
/// bench/fit_modelling_choices measures their effect on each statistic).
struct ModellingChoices {
  double settle_speed_m_s = 1e-6;
  bool point_samples = false;
};

/// The three-mode theory's settings at contact parameters p (the fit's runs).
TheorySettings theory_settings(const ContactParameters& p, int warmup, int turns, double tolerance);

/// The clearance model at the target's operating point with `p`: `warmup`
/// turns discarded, `turns` turns through the pass band and the statistics.
SimulatedStatistics simulate_statistics(const RecordingTarget& target, const ContactParameters& p, int warmup,
                                        int turns, double tolerance = 1e-8, const ModellingChoices& choices = {});

/// The statistics of a model run already on the target's grid (the band's
/// finer grid when the target has the band, else its analysis grid):
/// `th.series[…].clearance_revolutions` hold `turns` turns before any pass
/// band. Both models go through it (simulate_statistics, linkage_statistics.hpp).
SimulatedStatistics statistics_of_theory(const RecordingTarget& target, MatchedTheory th, int turns);

}  // namespace fourbar
