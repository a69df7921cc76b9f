#pragma once
// Statistics of a link's response that converge with the number of turns
// (the motion with impacts is chaotic: trajectories cannot be compared, their
// statistics can). Computed identically on a measurement (analyze's per-turn
// grids) and on a simulation (the matched theory through the measurement's
// pass band): from the turns X_r(θ) (R × N on the crank-angle grid) and the
// nominal response n(θ), with D_r = X_r − n:
//
//   mean_deviation   RMS over θ of the averaged deviation mean_r D_r
//                    (what the magnification factor sees)
//   spread           √(mean over θ of the variance over turns of X_r(θ))
//                    (turn-to-turn spread; sensor noise adds its variance)
//   turn_deviation   median over turns of RMS_θ D_r
//   peak_median      median over turns of max_θ |D_r| (per-turn peak deviation)
//   peak_p90         90th percentile over turns of max_θ |D_r|
//   turn_correlation mean over consecutive turns of corr(D_r, D_r+1)
//                    (how much a turn repeats the one before: chaos lowers it)
//
// Each comes with its standard error from a delete-one-block jackknife over
// the turns (blocks of consecutive turns, so that the correlation between
// neighbouring turns of a chaotic motion is kept inside a block).

#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "analyze/turn_repeat.hpp"

namespace fourbar {

enum class ResponseStatistic { mean_deviation, spread, turn_deviation, peak_median, peak_p90, turn_correlation };
inline constexpr std::array<ResponseStatistic, 6> kResponseStatistics{
    ResponseStatistic::mean_deviation, ResponseStatistic::spread,   ResponseStatistic::turn_deviation,
    ResponseStatistic::peak_median,    ResponseStatistic::peak_p90, ResponseStatistic::turn_correlation};
inline constexpr std::size_t kResponseStatisticCount = kResponseStatistics.size();
inline constexpr std::size_t index_of(ResponseStatistic s) { return static_cast<std::size_t>(s); }

/// "mean_deviation", "spread", … (JSON keys and table rows).
std::string_view name_of(ResponseStatistic s);
/// Whether the statistic is a positive magnitude (compared on a log scale).
bool is_magnitude(ResponseStatistic s);

struct StatisticValues {
  std::array<double, kResponseStatisticCount> value{};
  std::array<double, kResponseStatisticCount> standard_error{};
  std::size_t turns = 0;
};

/// The statistics of `turns` (R × N, row-major, R ≥ 2) against `nominal`
/// (N). `blocks` jackknife blocks (at most R; at least 2).
StatisticValues response_statistics(std::span<const double> turns, std::span<const double> nominal,
                                    std::size_t blocks = 8);

}  // namespace fourbar

namespace fourbar {

/// Energy of a link's α in a band above the averaging filter (impacts are
/// broadband; the following mode is smooth), above the band's own floor:
/// ms(θ) = mean over turns of x_r(θ)², floor = the 10 % quantile of ms over
/// the grid (sensor noise is white and stationary, so it lifts every angle
/// alike; the quiet angles of the following mode carry only it), and
///   band_excess = √(mean over θ of ms(θ) − floor).
/// Computed identically on measurement and model; the jackknife error as in
/// response_statistics.
struct BandEnergy {
  double excess = 0, standard_error = 0;
  double floor = 0;  ///< √floor, for the record (the measurement's noise in the band)
};
BandEnergy band_energy(std::span<const double> turns, std::size_t grid_points_per_rev, std::size_t blocks = 8);

/// Whether the turns repeat every few turns: analyze/turn_repeat.hpp (TurnRepeat, turn_repeat).

}  // namespace fourbar
