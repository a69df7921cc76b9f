#include "acquire/pulse_train.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include "common/statistics.hpp"

namespace fourbar {

namespace {

/// Number of edges i that have a partner j with |e_j − e_i − c| ≤ 0.1·c.
std::size_t pairs_at(std::span<const double> e, double c) {
  std::size_t score = 0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    auto it = std::lower_bound(e.begin() + static_cast<std::ptrdiff_t>(i) + 1, e.end(), e[i] + 0.9 * c);
    score += it != e.end() && *it <= e[i] + 1.1 * c;
  }
  return score;
}

/// The next period from the recent ones: least-squares line through them,
/// extrapolated one step; their median if there are too few or the line
/// strays more than 30 % from the last period (an outlier among them).
double predict_period(const std::deque<double>& recent) {
  const double med = median({recent.begin(), recent.end()});
  const std::size_t n = recent.size();
  if (n < 3) return med;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i);
    sx += x, sy += recent[i], sxx += x * x, sxy += x * recent[i];
  }
  const double dn = static_cast<double>(n);
  const double b = (dn * sxy - sx * sy) / (dn * sxx - sx * sx), a = (sy - b * sx) / dn;
  const double next = a + b * dn;
  return std::abs(next / recent.back() - 1) < 0.3 ? next : med;
}

/// Lagrange interpolation of time against pulse number through `known`.
double interpolate_time(const std::vector<std::pair<double, double>>& known, double k) {
  double t = 0;
  for (std::size_t i = 0; i < known.size(); ++i) {
    double w = 1;
    for (std::size_t j = 0; j < known.size(); ++j)
      if (j != i) w *= (k - known[j].first) / (known[i].first - known[j].first);
    t += w * known[i].second;
  }
  return t;
}

}  // namespace

std::size_t PulseTrain::revolutions() const {
  std::size_t n = 0;
  for (const auto& s : segments) n += s.size() - 1;
  return n;
}

double dominant_period(std::span<const double> e) {
  if (e.size() < 2) return 0;
  std::vector<double> candidates;
  for (std::size_t i = 0; i + 1 < e.size(); ++i) {
    candidates.push_back(e[i + 1] - e[i]);
    if (i + 2 < e.size()) candidates.push_back(e[i + 2] - e[i]);
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<std::size_t> scores;
  std::size_t best = 0;
  for (double c : candidates) scores.push_back(pairs_at(e, c)), best = std::max(best, scores.back());
  for (std::size_t i = 0; i < candidates.size(); ++i)  // smallest of the near-best
    if (static_cast<double>(scores[i]) >= 0.9 * static_cast<double>(best)) return candidates[i];
  return candidates.back();
}

PulseTrain clean_pulse_train(std::span<const double> e, const PulseTrainOptions& opt) {
  PulseTrain train;
  train.edges = e.size();
  const std::size_t n = e.size();
  const double tol = opt.tolerance;
  constexpr std::size_t kWindow = 32;  // edges used to (re)start the period estimate
  std::vector<double> normal_periods;

  std::size_t i = 0;
  while (i < n) {
    // Start a segment: the period from the edges ahead, then the first edge
    // that has a partner one period later.
    double period = dominant_period(e.subspan(i, std::min(kWindow, n - i)));
    if (period <= 0) {
      for (; i < n; ++i) train.orphan_s.push_back(e[i]);
      break;
    }
    auto partner = [&](std::size_t from, double p) {
      auto it = std::lower_bound(e.begin() + static_cast<std::ptrdiff_t>(from) + 1, e.end(), e[from] + (1 - tol) * p);
      return it != e.end() && *it <= e[from] + (1 + tol) * p;
    };
    while (i < n && !partner(i, period)) train.removed_s.push_back(e[i++]);
    if (i >= n) break;

    std::vector<Pulse> segment{{e[i], false}};
    std::deque<double> recent;
    ++i;
    for (;;) {
      const double last = segment.back().time_s;
      // Edges within half a period of the last pulse are echoes or doubled marks.
      while (i < n && e[i] <= last + 0.5 * period) train.removed_s.push_back(e[i++]);
      if (i >= n) break;
      // The first k whose window [last + (k−tol)P, last + (k+tol)P] holds an
      // edge; in it, the edge closest to last + k·P.
      std::size_t chosen = n;
      int k_found = 0;
      for (int k = 1; k <= opt.max_missing + 1 && chosen == n; ++k) {
        const double lo = last + (k - tol) * period, hi = last + (k + tol) * period, target = last + k * period;
        for (std::size_t j = i; j < n && e[j] <= hi; ++j)
          if (e[j] >= lo && (chosen == n || std::abs(e[j] - target) < std::abs(e[chosen] - target))) chosen = j;
        if (chosen != n) k_found = k;
      }
      // Several edges one period on (an echo a few milliseconds after the
      // pulse is closer to last + P than the drifting speed lets P predict):
      // take the one that keeps the speed smoothest, i.e. whose own next
      // period matches the one just ended, |e_next − 2·e_j + last| least.
      if (k_found == 1) {
        const double lo = last + (1 - tol) * period, hi = last + (1 + tol) * period;
        double best = INFINITY;
        for (std::size_t j = i; j < n && e[j] <= hi; ++j) {
          if (e[j] < lo) continue;
          const double step = e[j] - last;
          auto it = std::lower_bound(e.begin() + static_cast<std::ptrdiff_t>(j) + 1, e.end(), e[j] + (1 - tol) * step);
          double score = INFINITY;
          for (; it != e.end() && *it <= e[j] + (1 + tol) * step; ++it)
            score = std::min(score, std::abs(*it - 2 * e[j] + last));
          if (score < best) best = score, chosen = j;
        }
      }
      // With k = 1 the edges before the chosen one are spurious. With k > 1
      // (missed pulses) any edge before it is unexplained, as is no edge at all:
      // a gap that cuts the segment here.
      if (chosen == n || (k_found > 1 && chosen != i)) {
        train.gaps.push_back({last, e[i], (e[i] - last) / period});
        break;
      }
      for (std::size_t j = i; j < chosen; ++j) train.removed_s.push_back(e[j]);
      const double interval = e[chosen] - last;
      for (int m = 1; m < k_found; ++m) segment.push_back({std::nan(""), true});
      segment.push_back({e[chosen], false});
      i = chosen + 1;
      // Track the period: the trend of the last six (per-revolution) periods
      // extrapolated one step, so that a run-up or coast-down is followed.
      recent.push_back(interval / k_found);
      if (recent.size() > 6) recent.pop_front();
      period = predict_period(recent);
      if (k_found == 1) normal_periods.push_back(interval);
    }

    // Times of inserted pulses: a cubic through up to two detected pulses
    // on each side, against pulse number.
    for (std::size_t m = 0; m < segment.size(); ++m) {
      if (!segment[m].inserted) continue;
      std::vector<std::pair<double, double>> known;
      for (std::size_t b = m, found = 0; b-- > 0 && found < 2;)
        if (!segment[b].inserted) known.emplace_back(static_cast<double>(b), segment[b].time_s), ++found;
      for (std::size_t a = m + 1, found = 0; a < segment.size() && found < 2; ++a)
        if (!segment[a].inserted) known.emplace_back(static_cast<double>(a), segment[a].time_s), ++found;
      segment[m].time_s = interpolate_time(known, static_cast<double>(m));
      train.inserted_s.push_back(segment[m].time_s);
    }
    if (segment.size() >= 2) train.segments.push_back(std::move(segment));
    else train.orphan_s.push_back(segment.front().time_s);
  }
  train.typical_period_s = median(normal_periods);
  if (train.typical_period_s == 0) train.typical_period_s = dominant_period(e);
  return train;
}

}  // namespace fourbar
