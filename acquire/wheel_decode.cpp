#include "acquire/wheel_decode.hpp"

#include <algorithm>
#include <cmath>

#include "acquire/index_marks.hpp"
#include "common/error.hpp"
#include "common/format.hpp"

namespace fourbar {

namespace {

/// More than this share of turns with a wrong count is a wrong key, not a glitch.
constexpr double kMaxBadTurnShare = 0.1;

std::string where(const Manifest& m, const ChannelSpec& c, const char* key) {
  return m.file.string() + ": channel '" + c.name + "' key '" + key + "'";
}

/// Turns (reference edge index `starts[j]` to `starts[j+1]`) whose count is
/// `expected` become segments of consecutive turns; `position(j, r)` numbers
/// the r-th edge of turn j within it.
template <class Position>
void segments_from_turns(const std::vector<double>& edges, const std::vector<std::size_t>& starts,
                         const std::vector<bool>& good, Position position, NumberedEdges& out) {
  std::size_t j = 0;
  while (j < good.size()) {
    if (!good[j]) { ++j; continue; }
    std::size_t j1 = j;
    while (j1 + 1 < good.size() && good[j1 + 1]) ++j1;
    NumberedSegment s;
    for (std::size_t t = j; t <= j1; ++t)
      for (std::size_t e = starts[t]; e < starts[t + 1]; ++e) {
        s.time_s.push_back(edges[e]);
        s.position.push_back(position(t - j, e - starts[t]));
      }
    // The edge that closes the last turn.
    s.time_s.push_back(edges[starts[j1 + 1]]);
    s.position.push_back(position(j1 + 1 - j, 0));
    out.segments.push_back(std::move(s));
    j = j1 + 1;
  }
}

/// Counts per turn against `expected`: InputError when too many differ.
std::vector<bool> check_counts(const std::vector<std::size_t>& starts, std::size_t expected, const std::string& key_where,
                               const std::string& what, const std::string& fix, NumberedEdges& out) {
  std::vector<bool> good;
  std::size_t bad = 0, lo = SIZE_MAX, hi = 0;
  for (std::size_t j = 0; j + 1 < starts.size(); ++j) {
    const std::size_t n = starts[j + 1] - starts[j];
    good.push_back(n == expected);
    bad += n != expected;
    if (n != expected) lo = std::min(lo, n), hi = std::max(hi, n);
  }
  if (bad > 0 && static_cast<double>(bad) > kMaxBadTurnShare * static_cast<double>(good.size()))
    throw InputError(key_where + " says " + std::to_string(expected) + " " + what + " per turn, but " +
                     std::to_string(bad) + " of " + std::to_string(good.size()) + " turns counted " +
                     (lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi)) + "; " + fix);
  if (bad > 0)
    out.warnings.push_back(std::to_string(bad) + " of " + std::to_string(good.size()) + " turns counted " +
                           (lo == hi ? std::to_string(lo) : std::to_string(lo) + " to " + std::to_string(hi)) + " " +
                           what + " instead of " + std::to_string(expected) + " (glitches): those turns are dropped");
  out.turns_cut = bad;
  return good;
}

void need_two_marks(std::size_t marks, const Manifest& m, const std::filesystem::path& rec) {
  if (marks >= 2) return;
  const ChannelSpec& idx = *m.channel_with(ChannelRole::crank_index);
  throw InputError(rec.string() + ": the index channel '" + idx.name + "' (index " + std::to_string(*idx.index) +
                   ") marks " + std::to_string(marks) + " turn" + (marks == 1 ? "" : "s") +
                   "; at least 2 index marks are needed to count the turns: check the channel, its polarity and "
                   "thresholds in " + m.file.string() + ", or record longer");
}

void tooth_wheel_with_index(const WheelEdges& e, const Manifest& m, const std::filesystem::path& rec, NumberedEdges& out) {
  const ChannelSpec& p = m.pulse_channel();
  const auto P = static_cast<std::size_t>(p.pulses_per_rev);
  const std::vector<std::size_t> starts = place_index_marks(e.teeth_s, e.index_s).reference_edges;
  need_two_marks(starts.size(), m, rec);
  const auto good = check_counts(starts, P, where(m, p, "pulses_per_rev"), "teeth",
                                 "set pulses_per_rev to the teeth counted between two index marks, or check the "
                                 "thresholds of both channels", out);
  segments_from_turns(e.teeth_s, starts, good,
                      [&](std::size_t turn, std::size_t r) { return static_cast<std::int64_t>(turn * P + r); }, out);
}

void tooth_wheel_with_gap(const WheelEdges& e, const Manifest& m, const std::filesystem::path& rec, NumberedEdges& out) {
  const ChannelSpec& p = m.pulse_channel();
  const auto P = static_cast<std::size_t>(p.pulses_per_rev), K = static_cast<std::size_t>(p.missing_teeth);
  const auto& t = e.teeth_s;
  std::vector<std::size_t> starts;
  double biggest = 0;
  const double limit = 0.5 * static_cast<double>(K + 2);  // halfway between one pitch and K + 1
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double d = t[i + 1] - t[i];
    double ref = INFINITY;
    if (i > 0) ref = std::min(ref, t[i] - t[i - 1]);
    if (i + 2 < t.size()) ref = std::min(ref, t[i + 2] - t[i + 1]);
    if (!std::isfinite(ref)) continue;
    biggest = std::max(biggest, d / ref);
    if (d / ref > limit) starts.push_back(i + 1);
  }
  if (starts.size() < 2)
    throw InputError(where(m, p, "missing_teeth") + " = " + std::to_string(K) + ": " + std::to_string(starts.size()) +
                     " gap" + (starts.size() == 1 ? "" : "s") + " of " + std::to_string(K + 1) + " pitches among the " +
                     std::to_string(t.size()) + " teeth of " + rec.string() + " (the longest interval is " +
                     format_number(biggest, 3) + " pitches); at least 2 are needed: check missing_teeth, or mark the "
                     "turns with a crank_index channel");
  const auto good = check_counts(starts, P - K, where(m, p, "pulses_per_rev"), "teeth (pulses_per_rev − missing_teeth)",
                                 "set pulses_per_rev and missing_teeth to the wheel (a 60-2 wheel has 58 teeth), or "
                                 "check the thresholds", out);
  segments_from_turns(t, starts, good,
                      [&](std::size_t turn, std::size_t r) { return static_cast<std::int64_t>(turn * P + r); }, out);
}

struct Event {
  double t;
  bool b, rising;
};

void quadrature(const WheelEdges& e, const Manifest& m, const std::filesystem::path& rec, NumberedEdges& out) {
  const ChannelSpec& a = m.pulse_channel();
  const ChannelSpec& b = *m.channel_with(ChannelRole::encoder_b);
  const std::string ab = "'" + a.name + "' and '" + b.name + "'";
  std::vector<Event> ev;
  for (double t : e.a_rise_s) ev.push_back({t, false, true});
  for (double t : e.a_fall_s) ev.push_back({t, false, false});
  for (double t : e.b_rise_s) ev.push_back({t, true, true});
  for (double t : e.b_fall_s) ev.push_back({t, true, false});
  std::sort(ev.begin(), ev.end(), [](const Event& x, const Event& y) { return x.t < y.t; });
  const std::size_t na = e.a_rise_s.size() + e.a_fall_s.size(), nb = e.b_rise_s.size() + e.b_fall_s.size();
  const std::string fix = "; check that " + ab + " are the encoder's A and B outputs and their thresholds";
  if (std::max(na, nb) > std::min(na, nb) + 2 + std::max(na, nb) / 100)
    throw InputError(rec.string() + ": encoder channels " + ab + " are not in quadrature: " + std::to_string(na) +
                     " edges on A, " + std::to_string(nb) + " on B (they should match)" + fix);
  // Where B's edges fall between A's: a quarter line is half way.
  std::vector<double> frac;
  double last_a = NAN;
  for (std::size_t i = 0; i < ev.size(); ++i) {
    if (!ev[i].b) { last_a = ev[i].t; continue; }
    auto next = std::find_if(ev.begin() + static_cast<std::ptrdiff_t>(i), ev.end(), [](const Event& x) { return !x.b; });
    if (std::isnan(last_a) || next == ev.end()) continue;
    frac.push_back((ev[i].t - last_a) / (next->t - last_a));
  }
  std::nth_element(frac.begin(), frac.begin() + static_cast<std::ptrdiff_t>(frac.size() / 2), frac.end());
  const double phase = frac.empty() ? 0.0 : frac[frac.size() / 2];
  if (!(phase > 0.25 && phase < 0.75))
    throw InputError(rec.string() + ": encoder channels " + ab + " are not in quadrature: B's edges fall " +
                     format_number(100 * phase, 3) + " % of the way between A's (90° apart: 50 %)" + fix);
  // Count ±1 per edge.
  const auto first_of = [&](bool is_b) { return std::find_if(ev.begin(), ev.end(), [&](const Event& x) { return x.b == is_b; }); };
  bool la = !first_of(false)->rising, lb = !first_of(true)->rising;
  std::vector<double> time;
  std::vector<std::int64_t> count;
  std::int64_t c = 0;
  std::size_t up = 0;
  for (const Event& x : ev) {
    bool& level = x.b ? lb : la;
    level = x.rising;
    const bool forward = x.b ? (lb == la) : (la != lb);
    c += forward ? 1 : -1;
    up += forward;
    time.push_back(x.t), count.push_back(c);
  }
  const std::size_t down = ev.size() - up, minority = std::min(up, down);
  if (minority > ev.size() / 100 + 2)
    throw InputError(rec.string() + ": encoder channels " + ab + ": the count turns back at " +
                     std::to_string(minority) + " of " + std::to_string(ev.size()) +
                     " edges; A and B are not in quadrature or the crank turns back and forth" + fix);
  out.count_direction = up >= down ? 1.0 : -1.0;
  for (auto& v : count) v = static_cast<std::int64_t>(out.count_direction) * v;
  const auto P = static_cast<std::int64_t>(out.positions_per_rev);
  // Reference edge: after each index mark, or the first edge.
  std::vector<std::size_t> starts;
  if (m.channel_with(ChannelRole::crank_index)) {
    starts = place_index_marks(time, e.index_s).reference_edges;
    need_two_marks(starts.size(), m, rec);
  } else {
    for (std::size_t i = 0; i < time.size(); ++i)
      if ((count[i] - count[0]) % P == 0 && count[i] - count[0] >= 0 &&
          (starts.empty() || count[i] > count[starts.back()]))
        starts.push_back(i);
  }
  // A turn is good when the count advances by exactly P, one step per edge.
  std::vector<bool> good;
  std::size_t bad = 0;
  std::int64_t lo = INT64_MAX, hi = INT64_MIN;
  for (std::size_t j = 0; j + 1 < starts.size(); ++j) {
    const std::int64_t d = count[starts[j + 1]] - count[starts[j]];
    const bool monotone = static_cast<std::int64_t>(starts[j + 1] - starts[j]) == d;
    good.push_back(d == P && monotone);
    if (d != P || !monotone) ++bad, lo = std::min(lo, d), hi = std::max(hi, d);
  }
  if (bad > 0 && static_cast<double>(bad) > kMaxBadTurnShare * static_cast<double>(good.size()))
    throw InputError(where(m, a, "lines_per_rev") + " = " + std::to_string(a.lines_per_rev) + " gives " +
                     std::to_string(P) + " edges per turn, but " + std::to_string(bad) + " of " +
                     std::to_string(good.size()) + " turns between index marks counted " + std::to_string(lo) +
                     (lo == hi ? "" : " to " + std::to_string(hi)) +
                     "; set lines_per_rev to the encoder's lines (a quarter of the edges counted), or check the "
                     "index and thresholds");
  if (bad > 0)
    out.warnings.push_back(std::to_string(bad) + " of " + std::to_string(good.size()) +
                           " encoder turns counted wrong (glitches or the crank turning back): those turns are dropped");
  out.turns_cut = bad;
  segments_from_turns(time, starts, good, [&](std::size_t turn, std::size_t r) {
    return static_cast<std::int64_t>(turn) * P + static_cast<std::int64_t>(r);
  }, out);
}

}  // namespace

NumberedEdges number_edges(const WheelEdges& e, const Manifest& m, const std::filesystem::path& rec) {
  NumberedEdges out;
  const ChannelSpec& p = m.pulse_channel();
  out.warnings = e.warnings;
  if (p.role == ChannelRole::encoder_a) {
    out.positions_per_rev = 4 * p.lines_per_rev;
    quadrature(e, m, rec, out);
  } else {
    out.positions_per_rev = p.pulses_per_rev;
    if (p.missing_teeth > 0) tooth_wheel_with_gap(e, m, rec, out);
    else tooth_wheel_with_index(e, m, rec, out);
  }
  if (out.segments.empty())
    throw InputError(rec.string() + ": no complete turn with the right count of edges; check the crank-angle "
                     "channels in " + m.file.string());
  return out;
}

}  // namespace fourbar
