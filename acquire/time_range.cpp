#include "acquire/time_range.hpp"

#include <algorithm>
#include <cmath>

#include "common/format.hpp"

namespace fourbar {

namespace {

std::string seconds(double t) { return format_number(t, 6); }

/// The longest run of consecutive turns (no gap between them) whose speeds
/// lie within ±kSteadyBand of the median speed.
struct Run {
  std::size_t first = 0, last = 0;  // plan indices, inclusive
};

Run steady_run(const std::vector<RevolutionPlan>& plan, double median_period) {
  Run best{0, 0}, cur{0, 0};
  bool have = false, in = false;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const double p = plan[i].t_end - plan[i].t_start;
    const bool ok = std::abs(median_period / p - 1) <= kSteadyBand;
    const bool joined = in && i > 0 && plan[i].t_start == plan[i - 1].t_end;
    if (ok && joined) cur.last = i;
    else if (ok) cur = {i, i}, in = true;
    else in = false;
    if (ok && (!have || cur.last - cur.first > best.last - best.first)) best = cur, have = true;
  }
  return best;
}

}  // namespace

std::string describe_range(const TimeRange& r) {
  std::string s;
  if (r.start_s) s += "start_s = " + format_number(*r.start_s, 6);
  if (r.end_s) s += std::string(s.empty() ? "" : ", ") + "end_s = " + format_number(*r.end_s, 6);
  return s;
}

void trim_pulse_train(PulseTrain& train, const TimeRange& range) {
  if (!range.active()) return;
  std::vector<std::vector<Pulse>> kept;
  for (auto& seg : train.segments) {
    std::vector<Pulse> in;
    for (const Pulse& p : seg)
      if (range.holds(p.time_s)) in.push_back(p);
    if (in.size() >= 2) kept.push_back(std::move(in));
  }
  train.segments = std::move(kept);
  std::erase_if(train.gaps, [&](const PulseGap& g) { return !range.holds(g.from_s) || !range.holds(g.to_s); });
  std::erase_if(train.orphan_s, [&](double t) { return !range.holds(t); });
}

void trim_numbered_edges(NumberedEdges& edges, const TimeRange& range) {
  if (!range.active()) return;
  const auto P = static_cast<std::int64_t>(edges.positions_per_rev);
  std::vector<NumberedSegment> kept;
  for (NumberedSegment& s : edges.segments) {
    std::size_t a = s.time_s.size(), b = 0;
    bool any = false;
    for (std::size_t i = 0; i < s.time_s.size(); ++i)
      if (s.position[i] % P == 0 && range.holds(s.time_s[i])) {
        if (!any) a = i;
        b = i, any = true;
      }
    if (!any || b == a) continue;
    NumberedSegment t;
    const std::int64_t shift = s.position[a];
    for (std::size_t i = a; i <= b; ++i) t.time_s.push_back(s.time_s[i]), t.position.push_back(s.position[i] - shift);
    kept.push_back(std::move(t));
  }
  edges.segments = std::move(kept);
}

std::vector<std::string> range_warnings(const std::vector<RevolutionPlan>& plan, double file_start_s,
                                        double file_end_s, const TimeRange& range) {
  std::vector<std::string> w;
  if (plan.empty()) return w;
  const double from = std::max(file_start_s, range.start_s.value_or(file_start_s));
  const double to = std::min(file_end_s, range.end_s.value_or(file_end_s));
  const std::string what = range.active() ? "of the range analysed (" + describe_range(range) + ")" : "of the recording";
  double covered = 0;
  std::vector<double> periods;
  for (const RevolutionPlan& p : plan) covered += p.t_end - p.t_start, periods.push_back(p.t_end - p.t_start);
  std::vector<double> sorted = periods;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  const auto [lo, hi] = std::minmax_element(periods.begin(), periods.end());
  const double change = *hi / *lo - 1;  // fastest over slowest turn
  const Run run = steady_run(plan, median);
  // To the millisecond, outwards: the bounds typed back keep these turns.
  const double steady_from = std::floor(plan[run.first].t_start * 1e3) / 1e3;
  const double steady_to = std::ceil(plan[run.last].t_end * 1e3) / 1e3;
  const std::string cut = "; to analyse only the steady turns (" + std::to_string(run.last - run.first + 1) + " of " +
                          std::to_string(plan.size()) + ", within ±" + format_number(100 * kSteadyBand) +
                          " % of the median speed), set start_s = " + seconds(steady_from) + " and end_s = " +
                          seconds(steady_to) + " in the manifest, or pass --start-s " + seconds(steady_from) +
                          " --end-s " + seconds(steady_to);
  // Outside the turns beyond the partial turn that every recording has at
  // each end (at most a turn before the first pulse, one after the last).
  const double lead = std::max(0.0, plan.front().t_start - from), tail = std::max(0.0, to - plan.back().t_end);
  const double outside = (to - from) - covered - std::min(lead, median) - std::min(tail, median);
  if (to > from && outside > kOutsideShareWarn * (to - from))
    w.push_back(format_number(outside, 3) + " s (" + format_number(100 * outside / (to - from), 3) + " %) " + what +
                " lie outside the crank's turns, beyond a partial turn at each end (the turns run from " + seconds(plan.front().t_start) + " to " +
                seconds(plan.back().t_end) + " s, " + seconds(from) + " to " + seconds(to) +
                " s recorded): a run-up, a stall or the pickup off" + cut);
  if (change > kSpeedChangeWarn)
    w.push_back("the crank speed changes by " + format_number(100 * change, 3) + " % over the turns kept (" +
                format_number(60 / *hi, 4) + " to " + format_number(60 / *lo, 4) +
                " rpm): a coast-down, a stall or a run-up is averaged with the steady turns" + cut);
  return w;
}

}  // namespace fourbar
