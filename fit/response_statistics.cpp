#include "fit/response_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "common/error.hpp"

namespace fourbar {

std::string_view name_of(ResponseStatistic s) {
  switch (s) {
    case ResponseStatistic::mean_deviation: return "mean_deviation";
    case ResponseStatistic::spread: return "spread";
    case ResponseStatistic::turn_deviation: return "turn_deviation";
    case ResponseStatistic::peak_median: return "peak_median";
    case ResponseStatistic::peak_p90: return "peak_p90";
    case ResponseStatistic::turn_correlation: return "turn_correlation";
  }
  return "?";
}

bool is_magnitude(ResponseStatistic s) { return s != ResponseStatistic::turn_correlation; }

namespace {

/// Linear-interpolated quantile q of `v` (not empty).
double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

/// Per-turn quantities computed once: RMS and peak of D_r, and D_r itself.
struct TurnSummary {
  std::vector<double> rms, peak;
};

std::array<double, kResponseStatisticCount> statistics_of(std::span<const double> x, std::span<const double> nominal,
                                                          const TurnSummary& per_turn,
                                                          const std::vector<double>& pair_correlation,
                                                          const std::vector<bool>& use) {
  const std::size_t n = nominal.size(), turns = use.size();
  std::array<double, kResponseStatisticCount> out{};
  std::size_t count = 0;
  for (bool u : use) count += u;
  double mean_dev_sq = 0, var_sum = 0;
  for (std::size_t k = 0; k < n; ++k) {
    double s = 0, s2 = 0;
    for (std::size_t r = 0; r < turns; ++r) {
      if (!use[r]) continue;
      const double d = x[r * n + k] - nominal[k];
      s += d, s2 += d * d;
    }
    const double c = static_cast<double>(count);
    const double mean = s / c;
    mean_dev_sq += mean * mean;
    var_sum += std::max(0.0, (s2 - c * mean * mean) / (c - 1));
  }
  std::vector<double> rms, peak, corr;
  for (std::size_t r = 0; r < turns; ++r) {
    if (!use[r]) continue;
    rms.push_back(per_turn.rms[r]);
    peak.push_back(per_turn.peak[r]);
    if (r + 1 < turns && use[r + 1]) corr.push_back(pair_correlation[r]);
  }
  out[index_of(ResponseStatistic::mean_deviation)] = std::sqrt(mean_dev_sq / static_cast<double>(n));
  out[index_of(ResponseStatistic::spread)] = std::sqrt(var_sum / static_cast<double>(n));
  out[index_of(ResponseStatistic::turn_deviation)] = quantile(rms, 0.5);
  out[index_of(ResponseStatistic::peak_median)] = quantile(peak, 0.5);
  out[index_of(ResponseStatistic::peak_p90)] = quantile(peak, 0.9);
  double c = 0;
  for (double v : corr) c += v;
  out[index_of(ResponseStatistic::turn_correlation)] = corr.empty() ? 0.0 : c / static_cast<double>(corr.size());
  return out;
}

}  // namespace

StatisticValues response_statistics(std::span<const double> x, std::span<const double> nominal, std::size_t blocks) {
  const std::size_t n = nominal.size();
  if (n == 0 || x.size() % n != 0) throw RunError("response statistics: turns are not whole grid rows");
  const std::size_t turns = x.size() / n;
  if (turns < 4) throw RunError("response statistics need at least 4 turns, got " + std::to_string(turns));
  blocks = std::clamp<std::size_t>(blocks, 2, turns / 2);

  TurnSummary per_turn;
  for (std::size_t r = 0; r < turns; ++r) {
    double s2 = 0, p = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double d = x[r * n + k] - nominal[k];
      s2 += d * d, p = std::max(p, std::abs(d));
    }
    per_turn.rms.push_back(std::sqrt(s2 / static_cast<double>(n)));
    per_turn.peak.push_back(p);
  }
  std::vector<double> pair_corr(turns, 0.0);
  for (std::size_t r = 0; r + 1 < turns; ++r) {
    double ma = 0, mb = 0;
    for (std::size_t k = 0; k < n; ++k) ma += x[r * n + k] - nominal[k], mb += x[(r + 1) * n + k] - nominal[k];
    ma /= static_cast<double>(n), mb /= static_cast<double>(n);
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double a = x[r * n + k] - nominal[k] - ma, b = x[(r + 1) * n + k] - nominal[k] - mb;
      sab += a * b, saa += a * a, sbb += b * b;
    }
    pair_corr[r] = (saa > 0 && sbb > 0) ? sab / std::sqrt(saa * sbb) : 0.0;
  }

  StatisticValues out;
  out.turns = turns;
  out.value = statistics_of(x, nominal, per_turn, pair_corr, std::vector<bool>(turns, true));
  // Delete-one-block jackknife.
  std::vector<std::array<double, kResponseStatisticCount>> leave_out;
  for (std::size_t b = 0; b < blocks; ++b) {
    std::vector<bool> use(turns, true);
    const std::size_t lo = b * turns / blocks, hi = (b + 1) * turns / blocks;
    for (std::size_t r = lo; r < hi; ++r) use[r] = false;
    leave_out.push_back(statistics_of(x, nominal, per_turn, pair_corr, use));
  }
  const double nb = static_cast<double>(blocks);
  for (std::size_t i = 0; i < kResponseStatisticCount; ++i) {
    double m = 0;
    for (const auto& s : leave_out) m += s[i] / nb;
    double v = 0;
    for (const auto& s : leave_out) v += (s[i] - m) * (s[i] - m);
    out.standard_error[i] = std::sqrt((nb - 1) / nb * v);
  }
  return out;
}

}  // namespace fourbar

namespace fourbar {

namespace {

/// (excess, floor) of the turns marked in `use`.
std::pair<double, double> band_of(std::span<const double> x, std::size_t n, const std::vector<bool>& use) {
  std::vector<double> ms(n, 0.0);
  double count = 0;
  for (std::size_t r = 0; r < use.size(); ++r) {
    if (!use[r]) continue;
    count += 1;
    for (std::size_t k = 0; k < n; ++k) ms[k] += x[r * n + k] * x[r * n + k];
  }
  double mean = 0;
  for (double& v : ms) v /= count, mean += v / static_cast<double>(n);
  const double fl = quantile(ms, 0.1);
  return {std::sqrt(std::max(0.0, mean - fl)), std::sqrt(fl)};
}

}  // namespace

BandEnergy band_energy(std::span<const double> x, std::size_t n, std::size_t blocks) {
  if (n == 0 || x.size() % n != 0) throw RunError("band energy: turns are not whole grid rows");
  const std::size_t turns = x.size() / n;
  if (turns < 4) throw RunError("band energy needs at least 4 turns, got " + std::to_string(turns));
  blocks = std::clamp<std::size_t>(blocks, 2, turns / 2);
  BandEnergy out;
  std::tie(out.excess, out.floor) = band_of(x, n, std::vector<bool>(turns, true));
  std::vector<double> leave_out;
  for (std::size_t b = 0; b < blocks; ++b) {
    std::vector<bool> use(turns, true);
    for (std::size_t r = b * turns / blocks; r < (b + 1) * turns / blocks; ++r) use[r] = false;
    leave_out.push_back(band_of(x, n, use).first);
  }
  const double nb = static_cast<double>(blocks);
  double m = 0, v = 0;
  for (double s : leave_out) m += s / nb;
  for (double s : leave_out) v += (s - m) * (s - m);
  out.standard_error = std::sqrt((nb - 1) / nb * v);
  return out;
}

}  // namespace fourbar
