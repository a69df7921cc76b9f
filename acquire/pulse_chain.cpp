#include "acquire/pulse_chain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace fourbar {

namespace {

double sq(double x) { return x * x; }

/// misfit² of period d, capped.
/// Relative discount on leaving out an edge right after another (see below).
constexpr double kEchoPreference = 1e-4;

double misfit_cost(double d, double reference) { return std::min(sq(std::log(d / reference)), kMisfitCap); }

/// misfit² of a period d that may span k = 1 … kMaxMissedTurns turns (missed
/// pulses), each missed pulse at kMissedCost.
double period_cost(double d, double reference) {
  double best = misfit_cost(d, reference);
  for (int k = 2; k <= kMaxMissedTurns && best > kMissedCost * (k - 1); ++k)
    best = std::min(best, misfit_cost(d / k, reference) + kMissedCost * (k - 1));
  return best;
}

}  // namespace

double constant_acceleration_period(double a_s, double b_s) {
  return 1.0 / std::sqrt(0.5 * (1.0 / (a_s * a_s) + 1.0 / (b_s * b_s)));
}

std::vector<std::size_t> smoothest_pulse_chain(std::span<const double> e) {
  const std::size_t n = e.size();
  if (n < 3) {
    std::vector<std::size_t> all(n);
    for (std::size_t i = 0; i < n; ++i) all[i] = i;
    return all;
  }
  // State at edge j: (a, b) = edges skipped before j's predecessor i (i = j − a − 1)
  // and before i's predecessor h (h = i − b − 1); kNone: no such pulse (chain start).
  constexpr std::size_t kNone = kMaxSkipped, kS = kMaxSkipped + 1;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // Costs of the states of the last kS edges (a ring: transitions reach at
  // most kMaxSkipped edges ahead); the back pointers of all (1 byte each).
  constexpr std::size_t kStates = kS * kS;
  auto slot = [&](std::size_t j, std::size_t a, std::size_t b) { return ((j % kS) * kS + a) * kS + b; };
  auto at = [&](std::size_t j, std::size_t a, std::size_t b) { return (j * kS + a) * kS + b; };
  std::vector<double> cost(kS * kStates, kInf);
  // Per state, b of the predecessor state; for (j, none, none) 0 (the chain
  // starts at j) or 1 + the state the break came from, (s·kS + a)·kS + b.
  std::vector<std::uint8_t> back(n * kStates, 0);
  // Cost of leaving edge m out, a hair less for an edge that follows its
  // predecessor closely (g small): of an exact tie (a doubled mark on every
  // turn) the second edge of each pair, the echo, goes. prefix[m]: edges 0 … m−1.
  std::vector<double> prefix(n + 1, 0.0);
  for (std::size_t m = 0; m < n; ++m) {
    const double g = m == 0 || m + 1 == n ? 1.0 : (e[m] - e[m - 1]) / (e[m + 1] - e[m - 1]);
    prefix[m + 1] = prefix[m] + kRemoveCost * (1 + kEchoPreference * g);
  }
  auto left_out = [&](std::size_t from, std::size_t to) { return prefix[to] - prefix[from]; };  // edges from … to−1
  auto fresh_row = [&](std::size_t j) {
    std::fill_n(cost.begin() + static_cast<std::ptrdiff_t>((j % kS) * kStates), kStates, kInf);
    cost[slot(j, kNone, kNone)] = left_out(0, j);  // the chain starts at j
  };
  for (std::size_t j = 0; j < kS && j < n; ++j) fresh_row(j);

  // Two states at one edge differ in what follows by at most the two
  // period costs that involve their last two periods (each ≤ kMisfitCap) and
  // the end term: a state dearer than the best by more cannot win (exact pruning).
  constexpr double kPrune = (2 + kBoundaryWeight) * kMisfitCap;
  double best = kInf;  // best complete chain, ended at an edge so far
  std::size_t bj = 0, ba = kNone, bb = kNone;
  for (std::size_t j = 0; j < n; ++j) {
    double row_best = kInf;
    for (std::size_t k = 0; k < kStates; ++k) row_best = std::min(row_best, cost[(j % kS) * kStates + k]);
    for (std::size_t a = 0; a < kS; ++a)
      for (std::size_t b = 0; b < kS; ++b) {
        const double c = cost[slot(j, a, b)];
        if (c > row_best + kPrune || (a == kNone && b != kNone)) continue;
        // End here: the last period counts with its one neighbour; edges after are left out.
        double end = c + left_out(j + 1, n);
        if (a != kNone && b != kNone) {
          const std::size_t i = j - a - 1, h = i - b - 1;
          end += kBoundaryWeight * misfit_cost(e[j] - e[i], e[i] - e[h]);
        }
        if (end < best) best = end, bj = j, ba = a, bb = b;
        for (std::size_t s = 0; s < kMaxSkipped && j + 1 + s < n; ++s) {
          const std::size_t l = j + 1 + s;
          double add = left_out(j + 1, l);
          if (a != kNone) {
            const std::size_t i = j - a - 1;
            const double d = e[j] - e[i], r = e[l] - e[j];
            if (b != kNone) {
              const std::size_t h = i - b - 1;
              add += period_cost(d, constant_acceleration_period(e[i] - e[h], r));
            } else {
              add += kBoundaryWeight * misfit_cost(d, r);
            }
          }
          if (c + add < cost[slot(l, s, a)]) cost[slot(l, s, a)] = c + add, back[at(l, s, a)] = static_cast<std::uint8_t>(b);
          // Or a break after j: the period to l judges nothing, the chain goes on from l.
          double brk = left_out(j + 1, l) + kBreakCost;
          if (a != kNone && b != kNone) {
            const std::size_t i = j - a - 1, h = i - b - 1;
            brk += kBoundaryWeight * misfit_cost(e[j] - e[i], e[i] - e[h]);
          }
          if (c + brk < cost[slot(l, kNone, kNone)])
            cost[slot(l, kNone, kNone)] = c + brk,
            back[at(l, kNone, kNone)] = static_cast<std::uint8_t>(1 + (s * kS + a) * kS + b);
        }
      }
    if (j + kS < n) fresh_row(j + kS);
  }

  std::vector<std::size_t> chain;
  for (std::size_t j = bj, a = ba, b = bb;;) {
    chain.push_back(j);
    if (a != kNone) {
      const std::size_t prev_b = back[at(j, a, b)];
      j = j - a - 1, a = b, b = prev_b;
      continue;
    }
    const std::size_t code = back[at(j, kNone, kNone)];  // 0: the chain starts here; else a break
    if (code == 0) break;
    const std::size_t c = code - 1;
    j = j - c / (kS * kS) - 1, a = (c / kS) % kS, b = c % kS;
  }
  return {chain.rbegin(), chain.rend()};
}

}  // namespace fourbar
