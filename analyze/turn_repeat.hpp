#pragma once
// Whether a link's turns repeat with a period of several turns (a periodic
// motion of the mechanism, e.g. period 2: impacts alternating between two
// patterns). With x_r the turns' deviations from their mean curve,
//   ratio_p = RMS over r of (x_{r+p} − x_r) / (√2 · RMS of x_r),
// about 1 for irregular turns or noise at every p, about 0 at the period of
// a periodic motion and √2 at p = 1 for period 2. `period` is the shortest
// p in 2 … kMaxTurnRepeatPeriod with ratio_p < kTurnRepeatRatio while
// ratio_1 ≥ 1 − kTurnRepeatRatio (turns that differ from their neighbours),
// with at least 2p + 4 turns; 0 when none. A period-1 motion (every turn
// alike) gives no period: its spread is the noise's, as the model's.
// The mean curve cancels in x_{r+p} − x_r, so the numerator streams with the
// last kMaxTurnRepeatPeriod turns kept, and the denominator is the
// synchronous average's spread (averaging.hpp). The analysis streams it
// over its averaged turns (LinkResult::alpha_repeat: `fourbar analyze`, and
// the measured side of the report and the fit); the model's turns, a whole
// grid, go through turn_repeat.
// On the e = 0.8 virtual-rig session (docs/fit.md "A periodic recording"):
// 250 rpm, 0.254 mm gives ratio_2 = 0.14, ratio_1 = 1.41; its three other
// recordings 0.98–1.05 at every p.

#include <array>
#include <cstddef>
#include <deque>
#include <span>
#include <vector>

#include "analyze/averaging.hpp"

namespace fourbar {

inline constexpr std::size_t kMaxTurnRepeatPeriod = 4;
inline constexpr double kTurnRepeatRatio = 0.3;
/// The analysis leaves the first and last turns of each pulse-train segment
/// out of this measure: its filter continues the signal at a segment's ends
/// by repeating the first and last turn, right for a motion that repeats
/// every turn and not for one of period 2 or more, and the mismatch rings
/// into the turns next to the ends (a drive of ±5 % at a period of 2 turns,
/// 20 turns: ratio_2 0.46 with every turn, 0.16 without the end turns, 0.054
/// without two at each end; docs/analysis.md "Turns that repeat").
inline constexpr std::size_t kTurnRepeatEdgeTurns = 2;

struct TurnRepeat {
  std::size_t period = 0;
  /// ratio_p for p = 1 … kMaxTurnRepeatPeriod (1 where there are too few turns).
  std::array<double, kMaxTurnRepeatPeriod> by_lag{1, 1, 1, 1};
  std::size_t turns = 0;  ///< turns measured
  /// A p whose ratio passes (ratio_p < kTurnRepeatRatio, neighbours differ)
  /// but with fewer than 2p + 4 turns: a period these turns cannot confirm (0: none).
  std::size_t unconfirmed_period = 0;
  double ratio() const { return by_lag[period >= 2 ? period - 1 : 1]; }  ///< at the period (ratio_2 when none)
  double neighbours() const { return by_lag[0]; }                      ///< ratio_1
};

/// Turns in, one at a time and in order; `gap()` where a turn is missing
/// (a clipped or guard turn left out), so that lags pair only turns that
/// followed each other.
class TurnRepeatAccumulator {
 public:
  explicit TurnRepeatAccumulator(std::size_t grid_points_per_rev);
  void add(std::span<const double> turn);
  void gap() { recent_.clear(); }
  std::size_t turns() const { return average_.revolutions(); }
  TurnRepeat result() const;

 private:
  std::size_t n_;
  SynchronousAverager average_;
  std::deque<std::vector<double>> recent_;  ///< the last turns, newest last
  std::array<double, kMaxTurnRepeatPeriod> lag_sum_{};
  std::array<std::size_t, kMaxTurnRepeatPeriod> lag_pairs_{};
};

/// The same of `turns` consecutive rows of N values (row-major).
TurnRepeat turn_repeat(std::span<const double> turns, std::size_t grid_points_per_rev);

}  // namespace fourbar
