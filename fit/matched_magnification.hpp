#pragma once
// The thesis's magnification factor a (compare/magnification.hpp) of a
// fitted model, made comparable with the measurement and given with its
// standard error (docs/fit.md, "The magnification factor a of the fitted
// model").
//
// a = RMS(model − nominal) / RMS(measured − nominal) of the averaged curves.
// With chaotic impacts the averaged deviation of R turns holds the
// turn-to-turn scatter as well as any repeatable curve d: E[md_R²] = d² +
// σ²/R (σ: the spread statistic; turns independent). A model averaged over
// more turns than the measurement therefore gives a < 1 at the true
// parameters (measured: 46 model turns against 23 put a at ≈ 0.8), and a
// model averaged over as few is as noisy as the measurement. So the model
// runs M ≫ R turns, and its side of a is what it expects of an averaged
// curve of the measured R turns:
//   md_model(R)² = md_M² + σ_M² (1/R − 1/M)         (E = d² + σ²/R)
//   a = md_model(R) / md_measured
// Its standard error: the measured md's jackknife error (relative) and the
// model's (from its md and σ jackknife errors), added in quadrature. At the
// true parameters E[a²] = 1 up to the sensor noise in the measured average;
// whether a differs from 1 is a question of that error: with 25 turns it is
// 8–36 % (docs/fit.md).

#include <cstddef>
#include <optional>

#include "fit/response_statistics.hpp"

namespace fourbar {

struct MatchedMagnification {
  double value = 0;           ///< a
  double standard_error = 0;  ///< of a (measurement and model in quadrature)
  double measured_relative_error = 0;  ///< the measurement's share: se(md)/md
  double model_relative_error = 0;     ///< the model's share
};

/// Model turns per measured turn of the simulation that gives a: its error
/// is then ≈ 1/√8 of the measurement's (docs/fit.md: cost).
inline constexpr int kMagnificationTurnsPerMeasuredTurn = 8;

/// a of a model run of `model_turns` turns against a measurement of
/// `measured_turns` turns (both's statistics as response_statistics gives
/// them). Absent when the measured averaged deviation is 0 or a count is
/// below 2.
std::optional<MatchedMagnification> matched_magnification(const StatisticValues& measured, std::size_t measured_turns,
                                                          const StatisticValues& model, std::size_t model_turns);

}  // namespace fourbar
