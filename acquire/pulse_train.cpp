#include "acquire/pulse_train.hpp"

#include <algorithm>
#include <cmath>

#include "acquire/pulse_chain.hpp"
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

namespace {

/// Neighbours further apart than this factor do not describe one speed trend.
const double kNeighboursApart = std::log(1.9);
/// Neighbours of a missed pulse agree within this (ln): steady running.
constexpr double kSteadyForRepair = 0.2;

/// The next period from the two before it (d1 nearer), at the constant
/// acceleration they show (ω² linear in angle); a trend towards standstill
/// is capped at twice the nearer period.
double extrapolated_period(double d1, double d2) {
  if (std::abs(std::log(d1 / d2)) > kNeighboursApart) return d1;
  const double q = 2 / (d1 * d1) - 1 / (d2 * d2);
  return q > 0.25 / (d1 * d1) ? 1 / std::sqrt(q) : 2 * d1;
}

/// Periods longer than e^kPeriodOutlier times a neighbour: possibly a stall
/// or lost pulses, so no reference for the periods beside them.
std::vector<bool> long_periods(const std::vector<double>& d) {
  std::vector<bool> suspect(d.size(), false);
  const double ratio = std::exp(kPeriodOutlier);
  for (std::size_t k = 0; k < d.size(); ++k)
    suspect[k] = (k >= 1 && d[k] > ratio * d[k - 1]) || (k + 1 < d.size() && d[k] > ratio * d[k + 1]);
  return suspect;
}

/// What period k of `d` should be from its neighbours (those not `suspect`,
/// if any):
/// the constant-acceleration period between them when they agree within
/// kNeighboursApart; else (one of them out of line, or a chain end) the trend
/// of the side it fits best. NaN with no usable neighbour.
double reference_period(const std::vector<double>& d, const std::vector<bool>& suspect, std::size_t k) {
  // Neighbours that are long themselves are skipped, unless both are (a
  // period between two long ones is judged against them).
  const bool all_long = (k < 1 || suspect[k - 1]) && (k + 1 >= d.size() || suspect[k + 1]);
  auto usable = [&](std::size_t m, bool exists) { return exists && (all_long || !suspect[m]); };
  const bool left = usable(k - 1, k >= 1), right = usable(k + 1, k + 1 < d.size());
  if (left && right && std::abs(std::log(d[k - 1] / d[k + 1])) <= kNeighboursApart)
    return constant_acceleration_period(d[k - 1], d[k + 1]);
  double best = NAN;
  auto consider = [&](double ref) {
    if (std::isnan(best) || std::abs(std::log(d[k] / ref)) < std::abs(std::log(d[k] / best))) best = ref;
  };
  if (left) consider(usable(k - 2, k >= 2) ? extrapolated_period(d[k - 1], d[k - 2]) : d[k - 1]);
  if (right) consider(usable(k + 2, k + 2 < d.size()) ? extrapolated_period(d[k + 1], d[k + 2]) : d[k + 1]);
  return best;
}

/// Missed pulses in period k: its steady neighbours' period fits k_missed + 1
/// times (0 when not).
int missed_pulses(const std::vector<double>& d, std::size_t k, const PulseTrainOptions& opt) {
  if (k < 1 || k + 1 >= d.size() || std::abs(std::log(d[k - 1] / d[k + 1])) > kSteadyForRepair) return 0;
  const double r = d[k] / std::sqrt(d[k - 1] * d[k + 1]);
  const double whole = std::round(r);
  if (whole < 2 || whole > opt.max_missing + 1 || std::abs(r - whole) > opt.tolerance) return 0;
  return static_cast<int>(whole) - 1;
}

/// Twofold period steps between steady runs of three periods in a segment.
void find_period_steps(const std::vector<Pulse>& seg, const std::vector<double>& widths, PulseTrain& train) {
  constexpr std::size_t kRun = 3;
  constexpr double kSteadyRun = 1.15, kDutyAgree = 1.4;
  if (seg.size() < 2 * kRun + 1) return;
  std::vector<double> d(seg.size() - 1);
  for (std::size_t k = 0; k < d.size(); ++k) d[k] = seg[k + 1].time_s - seg[k].time_s;
  auto steady = [&](std::size_t from) {
    const auto [lo, hi] = std::minmax_element(d.begin() + static_cast<std::ptrdiff_t>(from),
                                              d.begin() + static_cast<std::ptrdiff_t>(from + kRun));
    return *hi <= kSteadyRun * *lo;
  };
  auto run_median = [&](std::size_t from) { return median({d.begin() + static_cast<std::ptrdiff_t>(from),
                                                            d.begin() + static_cast<std::ptrdiff_t>(from + kRun)}); };
  // Median pulse width as a fraction of its period over a run (NaN if unknown).
  auto duty = [&](std::size_t from) {
    std::vector<double> f;
    for (std::size_t k = from; k < from + kRun; ++k)
      if (std::isfinite(widths[k])) f.push_back(widths[k] / d[k]);
    return f.size() == kRun ? median(f) : NAN;
  };
  for (std::size_t k = kRun; k + kRun <= d.size(); ++k) {
    if (!steady(k - kRun)) continue;
    for (std::size_t after : {k, k + 1}) {  // with no period or one period of transition
      if (after + kRun > d.size() || !steady(after)) continue;
      const double before_s = run_median(k - kRun), after_s = run_median(after);
      const double ratio = after_s / before_s;
      if (!(ratio >= 0.4 && ratio <= 0.625) && !(ratio >= 1.6 && ratio <= 2.5)) continue;
      PeriodStep step{seg[k].time_s, before_s, after_s};
      const double duty_before = duty(k - kRun), duty_after = duty(after);
      step.width_before_s = duty_before * before_s, step.width_after_s = duty_after * after_s;
      step.resolved = duty_before > 0 && duty_after > 0 && std::max(duty_before / duty_after, duty_after / duty_before) <= kDutyAgree;
      train.steps.push_back(step);
      k = after + kRun - 1;  // one finding per step
      break;
    }
  }
}

}  // namespace

std::vector<PeriodStep> PulseTrain::ambiguous() const {
  std::vector<PeriodStep> out;
  for (const auto& s : steps)
    if (!s.resolved) out.push_back(s);
  return out;
}

PulseTrain clean_pulse_train(std::span<const double> e, const PulseTrainOptions& opt, std::span<const double> widths_s) {
  PulseTrain train;
  train.edges = e.size();
  const std::vector<std::size_t> chain = smoothest_pulse_chain(e);
  for (std::size_t i = 0, c = 0; i < e.size(); ++i) {
    if (c < chain.size() && chain[c] == i) ++c;
    else train.removed_s.push_back(e[i]);
  }
  std::vector<double> d;
  for (std::size_t c = 0; c + 1 < chain.size(); ++c) d.push_back(e[chain[c + 1]] - e[chain[c]]);
  const std::vector<bool> suspect = long_periods(d);
  auto width_of = [&](std::size_t edge) { return edge < widths_s.size() ? widths_s[edge] : NAN; };

  std::vector<double> normal_periods;
  std::vector<Pulse> segment;
  std::vector<double> widths;  // per pulse of the segment
  auto close_segment = [&] {
    // Times of inserted pulses: a cubic through up to two detected pulses on
    // each side, against pulse number.
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
    if (segment.size() >= 2) {
      find_period_steps(segment, widths, train);
      train.segments.push_back(std::move(segment));
    } else if (segment.size() == 1) {
      train.orphan_s.push_back(segment.front().time_s);
    }
    segment.clear(), widths.clear();
  };
  if (!chain.empty()) segment.push_back({e[chain[0]], false}), widths.push_back(width_of(chain[0]));
  for (std::size_t k = 0; k < d.size(); ++k) {
    const double ref = reference_period(d, suspect, k);
    const double next_s = e[chain[k + 1]];
    // Only a long period breaks the train: a short one the chain kept is
    // smoother kept than left out (a speed change), and a sustained halving
    // is checked below (find_period_steps).
    const bool normal = std::isnan(ref) || std::log(d[k] / ref) <= kPeriodOutlier;
    const int missed = normal ? 0 : missed_pulses(d, k, opt);
    if (!normal && missed == 0) {
      train.gaps.push_back({segment.back().time_s, next_s, d[k] / ref});
      close_segment();
    } else {
      for (int m = 0; m < missed; ++m) segment.push_back({std::nan(""), true}), widths.push_back(NAN);
      if (missed == 0) normal_periods.push_back(d[k]);
    }
    segment.push_back({next_s, false}), widths.push_back(width_of(chain[k + 1]));
  }

  close_segment();
  train.typical_period_s = median(normal_periods);
  if (train.typical_period_s == 0) train.typical_period_s = dominant_period(e);
  return train;
}

}  // namespace fourbar
