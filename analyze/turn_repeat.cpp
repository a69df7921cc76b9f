#include "analyze/turn_repeat.hpp"

#include <cmath>

#include "common/error.hpp"

namespace fourbar {

TurnRepeatAccumulator::TurnRepeatAccumulator(std::size_t n) : n_(n), average_(n) {
  if (n == 0) throw RunError("turn repeat: no grid points per turn");
}

void TurnRepeatAccumulator::add(std::span<const double> turn) {
  if (turn.size() != n_) throw RunError("turn repeat: a turn of " + std::to_string(turn.size()) + " values, not " + std::to_string(n_));
  average_.add(turn);
  // recent_ holds turns r − 1, r − 2, … (newest last): lag p pairs this turn with recent_[size − p].
  for (std::size_t p = 1; p <= recent_.size(); ++p) {
    const std::vector<double>& before = recent_[recent_.size() - p];
    double s = 0;
    for (std::size_t k = 0; k < n_; ++k) s += (turn[k] - before[k]) * (turn[k] - before[k]);
    lag_sum_[p - 1] += s;
    ++lag_pairs_[p - 1];
  }
  if (recent_.size() == kMaxTurnRepeatPeriod) {
    recent_.front().assign(turn.begin(), turn.end());
    recent_.push_back(std::move(recent_.front()));
    recent_.pop_front();
  } else {
    recent_.emplace_back(turn.begin(), turn.end());
  }
}

TurnRepeat TurnRepeatAccumulator::result() const {
  TurnRepeat out;
  const std::size_t turns = average_.revolutions();
  out.turns = turns;
  if (turns < 2) return out;
  // Mean square deviation from the mean curve over every value: the sample
  // variance per angle times (R − 1)/R, averaged over the angles.
  const AngleAverage avg = average_.result();
  double dev = 0;
  for (double s : avg.std) dev += s * s;
  dev *= static_cast<double>(turns - 1) / static_cast<double>(turns) / static_cast<double>(n_);
  if (!(dev > 0)) return out;
  for (std::size_t p = 1; p <= kMaxTurnRepeatPeriod; ++p)
    if (lag_pairs_[p - 1] > 0)
      out.by_lag[p - 1] = std::sqrt(lag_sum_[p - 1] / static_cast<double>(lag_pairs_[p - 1] * n_) / (2.0 * dev));
  if (out.neighbours() < 1 - kTurnRepeatRatio) return out;
  for (std::size_t p = 2; p <= kMaxTurnRepeatPeriod; ++p)
    if (lag_pairs_[p - 1] > 0 && out.by_lag[p - 1] < kTurnRepeatRatio) {
      (lag_pairs_[p - 1] + p >= 2 * p + 4 ? out.period : out.unconfirmed_period) = p;
      break;
    }
  return out;
}

TurnRepeat turn_repeat(std::span<const double> x, std::size_t n) {
  if (n == 0 || x.size() % n != 0) throw RunError("turn repeat: turns are not whole grid rows");
  TurnRepeatAccumulator acc(n);
  for (std::size_t r = 0; r < x.size() / n; ++r) acc.add(x.subspan(r * n, n));
  return acc.result();
}

}  // namespace fourbar
