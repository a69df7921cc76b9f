#include "acquire/speed_angle.hpp"

#include <algorithm>
#include <cmath>

#include "acquire/channel_inputs.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

/// The angle at `tau` seconds into the sample interval [i, i+1] of length dt,
/// the speed linear between w0 and w1 (rad/s).
double angle_in(double theta0, double w0, double w1, double dt, double tau) {
  return theta0 + w0 * tau + 0.5 * (w1 - w0) / dt * tau * tau;
}

/// The τ in [0, dt] at which the angle grows by `d` ≥ 0 from theta0: the
/// root τ ≥ 0 of a·τ² + w0·τ − d = 0 (w0, w1 > 0) in the form without
/// cancellation, which is d/w0 at a = 0.
double time_to(double w0, double w1, double dt, double d) {
  const double a = 0.5 * (w1 - w0) / dt;
  const double tau = 2 * d / (w0 + std::sqrt(std::max(0.0, w0 * w0 + 4 * a * d)));
  return std::clamp(tau, 0.0, dt);
}

double wrap_pi(double x) { return x - units::kTwoPi * std::floor((x + units::kPi) / units::kTwoPi); }

}  // namespace

std::vector<double> speed_track_pass(const BlockStream& stream, const Manifest& manifest, const ChannelSpec& speed) {
  const RecordingInfo& info = stream.reader.info();
  const auto channels = static_cast<std::size_t>(info.channels);
  const auto idx = static_cast<std::size_t>(*speed.index);
  const double factor = speed.rpm_per_V ? manifest.full_scale_V * *speed.rpm_per_V : 1.0;
  std::vector<double> rpm;
  rpm.reserve(static_cast<std::size_t>(info.frames));
  for_each_block(stream, AcquirePass::pulses, [&](std::span<const double> block, std::size_t frames, std::uint64_t) {
    for (std::size_t f = 0; f < frames; ++f) rpm.push_back(block[f * channels + idx] * factor);
  });
  return rpm;
}

SpeedAngle speed_angle_edges(const std::vector<double>& rpm, double sample_rate_hz, double start_time_s,
                             const ChannelSpec& speed, const ChannelSpec* pulse, const std::vector<double>& pulse_s,
                             const TimeRange& range, const std::filesystem::path& manifest_file) {
  SpeedAngle out;
  const double dt = 1 / sample_rate_hz;
  auto time_of = [&](std::size_t i) { return start_time_s + static_cast<double>(i) * dt; };
  std::size_t begin = 0, end = rpm.size();  // the samples in the range
  while (begin < end && !range.holds(time_of(begin))) ++begin;
  while (end > begin && !range.holds(time_of(end - 1))) --end;
  const std::string fix = std::string(speed.rpm_per_V ? "check rpm_per_V and full_scale_V"
                                                  : "check the scale: the values are read as rpm (give rpm_per_V for a voltage)");
  // A stop or a reversal cannot be integrated to a turn count: bad input, with the span.
  for (std::size_t i = begin; i < end; ++i) {
    if (rpm[i] > 0 && std::isfinite(rpm[i])) continue;
    std::size_t j = i;
    while (j + 1 < end && !(rpm[j + 1] > 0 && std::isfinite(rpm[j + 1]))) ++j;
    throw InputError(manifest_file.string() + ": " + channel_label(speed) + " reads " + format_number(rpm[i], 4) +
                     " rpm: a speed ≤ 0 (or not a number) from " + format_number(time_of(i), 6) + " s to " +
                     format_number(time_of(j), 6) + " s, through which no crank angle can be integrated; analyse "
                     "the running part only (start_s/end_s in the manifest or --start-s/--end-s); " + fix);
  }
  if (end - begin < 2) return out;

  // The trapezoid integral of the speed, one angle per sample.
  std::vector<double> w(end - begin), theta(end - begin);
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = units::rpm_to_rad_s(rpm[begin + i]);
  theta[0] = 0;
  for (std::size_t i = 1; i < w.size(); ++i) theta[i] = theta[i - 1] + 0.5 * (w[i - 1] + w[i]) * dt;
  const double t0 = time_of(begin);
  auto angle_at = [&](double t) {
    const double x = (t - t0) / dt;
    const auto i = static_cast<std::size_t>(std::clamp(std::floor(x), 0.0, static_cast<double>(w.size() - 2)));
    return angle_in(theta[i], w[i], w[i + 1], dt, t - (t0 + static_cast<double>(i) * dt));
  };

  // The zero: the median phase of the integrated angle at the pulses.
  double zero = 0;
  std::vector<double> phase;
  for (double t : pulse_s)
    if (t >= t0 && t <= time_of(end - 1)) phase.push_back(angle_at(t));
  if (pulse && !phase.empty()) {
    const double ref = phase.front();
    std::vector<double> d;
    for (double p : phase) d.push_back(wrap_pi(p - ref));
    std::vector<double> sorted = d;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    const double median = sorted[sorted.size() / 2];
    zero = ref + median;
    for (double x : d) out.zero_spread_deg = std::max(out.zero_spread_deg, units::rad_to_deg(std::abs(wrap_pi(x - median))));
    out.zero_known = true;
    out.source = "speed channel '" + speed.name + "' integrated, zero at the pulses of '" + pulse->name + "'";
    if (out.zero_spread_deg > 5)
      out.warnings.push_back("the crank angle integrated from " + channel_label(speed) + " misses the pulses of '" + pulse->name +
                             "' by up to " + format_number(out.zero_spread_deg, 3) + "° over " +
                             std::to_string(phase.size()) + " pulses: the speed's scale is off or the track lags; " + fix);
  } else if (speed.crank_offset_given) {
    out.source = "speed channel '" + speed.name + "' integrated, zero from its crank_offset_deg";
    out.warnings.push_back("the crank angle is integrated from " + channel_label(speed) +
                           " with its zero from crank_offset_deg (the crank angle at the first sample analysed: it "
                           "moves with start_s); a once-per-turn crank_pulse channel would fix the zero from the data");
  } else {
    out.source = "speed channel '" + speed.name + "' integrated, zero unknown";
    out.warnings.push_back(
        "the crank angle is integrated from " + channel_label(speed) +
        (pulse ? " and the pulse channel '" + pulse->name + "' has no edges in it"
               : std::string(" without a crank_pulse channel")) +
        ": its zero is unknown, taken as 0° at the first sample analysed. The turns, the speed and the spread are "
        "right, but the crank-angle phase is arbitrary, and so are α and ω: the conversion needs the crank angle (the "
        "gravity projection, the sensor's offset from the link line), so they are wrong in shape as well as phase. "
        "Add the once-per-turn pulse as role = \"crank_pulse\", or give crank_offset_deg on '" + speed.name +
        "' (the crank angle at the first sample analysed)");
  }

  // Virtual edges at every 2π/P of the angle from the zero, numbered from the first whole turn.
  const int P = kSpeedPositionsPerRev;
  const double pitch = units::kTwoPi / P;
  NumberedEdges& e = out.edges;
  e.positions_per_rev = P;
  NumberedSegment seg;
  const auto first_turn = static_cast<std::int64_t>(std::ceil((theta.front() - zero) / units::kTwoPi - 1e-12));
  std::int64_t p = first_turn * P;
  std::size_t i = 0;
  for (;; ++p) {
    const double target = zero + static_cast<double>(p) * pitch;
    while (i + 1 < theta.size() && theta[i + 1] < target) ++i;
    if (i + 1 >= theta.size()) break;
    const double tau = time_to(w[i], w[i + 1], dt, target - theta[i]);
    seg.time_s.push_back(t0 + static_cast<double>(i) * dt + tau);
    seg.position.push_back(p - first_turn * P);
  }
  if (!seg.time_s.empty()) e.segments.push_back(std::move(seg));
  return out;
}

}  // namespace fourbar
