#include "acquire/inspect.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "acquire/inspect_pulse.hpp"
#include "common/format.hpp"

namespace fourbar {

namespace {

constexpr std::size_t kBlockFrames = 8192;

bool contains(const std::string& s, const char* word) { return s.find(word) != std::string::npos; }

/// Reads every block of `reader` from the start, calling f(frame, channel, value).
template <class F>
void each_sample(Reader& reader, F&& f) {
  reader.rewind();
  const auto channels = static_cast<std::size_t>(reader.info().channels);
  std::vector<double> block(kBlockFrames * channels);
  std::uint64_t frame = 0;
  while (const std::size_t n = reader.read(block)) {
    for (std::size_t i = 0; i < n; ++i, ++frame)
      for (std::size_t c = 0; c < channels; ++c) f(frame, c, block[i * channels + c]);
  }
}

void guess_role(ChannelInspection& ch) {
  const std::string by_name = role_from_name(ch.name);
  if (ch.constant) {
    ch.role = "ignore";
    ch.reason = "constant " + format_number(ch.mean, 4) + ": not connected or switched off";
  } else if (ch.pulse) {
    const PulseTrainGuess& p = *ch.pulse;
    ch.role = "crank_pulse";
    ch.reason = "pulse train: " + std::to_string(p.pulses) + " pulses at " + format_number(p.rate_hz, 4) + " Hz = " +
                format_number(p.rpm, 4) + " rpm at one pulse per turn; short state " + (p.short_state_high ? "high" : "low") +
                " (" + format_number(100 * std::min(p.high_fraction, 1 - p.high_fraction), 4) + " % of the time)";
    if (p.regular_fraction < 0.98)
      ch.reason += "; " + format_number(100 * (1 - p.regular_fraction), 4) + " % of the intervals irregular (missing or extra pulses)";
  } else if (!by_name.empty() && by_name != "crank_pulse") {
    ch.role = by_name;
    ch.reason = "its name says " + by_name + "; the data look like a vibration signal (DC " + format_number(ch.mean, 4) +
                ", AC RMS " + format_number(ch.ac_rms, 4) + ")";
  } else {
    ch.reason = std::string(by_name == "crank_pulse" ? "named like a pulse channel but not a pulse train; " : "") +
                "a continuous signal (DC " + format_number(ch.mean, 4) + ", AC RMS " + format_number(ch.ac_rms, 4) +
                "): an accelerometer? its role cannot be told from the data";
  }
  if (ch.rail_samples > 0)
    ch.reason += "; CLIPPED: " + std::to_string(ch.rail_samples) + " samples at digital full scale";
  else if (ch.clipped())
    ch.reason += "; possibly CLIPPED: " + std::to_string(ch.flat_extreme_samples) +
                 " samples flat at its extremes (or coarse quantisation)";
}

}  // namespace

std::string role_from_name(const std::string& name) {
  std::string n = name;
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (contains(n, "pulse") || contains(n, "crank") || contains(n, "trig") || contains(n, "tach") || contains(n, "index"))
    return "crank_pulse";
  const bool coupler = contains(n, "coupler") || contains(n, "koppel");
  const bool rocker = contains(n, "rocker") || contains(n, "schwinge");
  if (coupler == rocker) return "";
  const bool tangential = contains(n, "tang") || n.ends_with("_t");
  const bool normal = contains(n, "norm") || n.ends_with("_n");
  if (tangential == normal) return "";
  return std::string(coupler ? "coupler" : "rocker") + (tangential ? "_tangential" : "_normal");
}

RecordingInspection inspect_recording(Reader& reader) {
  RecordingInspection r;
  r.info = reader.info();
  const auto channels = static_cast<std::size_t>(r.info.channels);
  r.channels.resize(channels);
  for (std::size_t c = 0; c < channels; ++c) {
    r.channels[c].index = static_cast<int>(c);
    if (c < r.info.channel_names.size()) r.channels[c].name = r.info.channel_names[c];
    if (c < r.info.channel_units.size()) r.channels[c].unit = r.info.channel_units[c];
  }

  // Pass 1: range, moments, samples at the digital rails.
  std::vector<double> sum(channels, 0), sum_sq(channels, 0);
  for (auto& ch : r.channels) ch.min = INFINITY, ch.max = -INFINITY;
  const int bits = r.info.integer_bits;
  const double rail_high = bits > 0 ? 1.0 - 1.5 / std::ldexp(1.0, bits - 1) : INFINITY;
  each_sample(reader, [&](std::uint64_t, std::size_t c, double x) {
    ChannelInspection& ch = r.channels[c];
    ch.min = std::min(ch.min, x), ch.max = std::max(ch.max, x);
    sum[c] += x, sum_sq[c] += x * x;
    if (bits > 0 && std::abs(x) >= rail_high) ++ch.rail_samples;  // writers put -1.0 at -32767 or -32768
  });
  const double n = static_cast<double>(std::max<std::uint64_t>(r.info.frames, 1));
  for (std::size_t c = 0; c < channels; ++c) {
    ChannelInspection& ch = r.channels[c];
    if (r.info.frames == 0) ch.min = ch.max = 0;
    ch.mean = sum[c] / n;
    ch.rms = std::sqrt(sum_sq[c] / n);
    ch.ac_rms = std::sqrt(std::max(0.0, sum_sq[c] / n - ch.mean * ch.mean));
    ch.constant = !(ch.max - ch.min > 1e-12 * std::max(1.0, std::abs(ch.mean)));
  }

  // Pass 2: runs at the extremes and pulse trains (both need the range).
  std::vector<PulseTrainDetector> detectors;
  for (const auto& ch : r.channels) detectors.emplace_back(ch.min, ch.max);
  std::vector<double> last(channels, NAN);
  std::vector<std::uint64_t> run(channels, 0);
  auto close_run = [&](std::size_t c) {
    if (run[c] >= 3) r.channels[c].flat_extreme_samples += run[c];
    run[c] = 0;
  };
  each_sample(reader, [&](std::uint64_t, std::size_t c, double x) {
    detectors[c].add(x);
    ChannelInspection& ch = r.channels[c];
    if (!ch.constant && (x == ch.min || x == ch.max) && (run[c] == 0 || x == last[c])) ++run[c];
    else {
      close_run(c);
      if (!ch.constant && (x == ch.min || x == ch.max)) run[c] = 1;
    }
    last[c] = x;
  });
  for (std::size_t c = 0; c < channels; ++c) {
    close_run(c);
    ChannelInspection& ch = r.channels[c];
    if (!ch.constant) ch.pulse = detectors[c].result(r.info.sample_rate_hz);
    guess_role(ch);
  }
  // One crank pulse: the most regular train; the others are listed as pulse trains but not given the role.
  double best = -1;
  for (const auto& ch : r.channels)
    if (ch.pulse && ch.pulse->regular_fraction > best) best = ch.pulse->regular_fraction, r.pulse_channel = ch.index;
  for (auto& ch : r.channels)
    if (ch.pulse && ch.index != r.pulse_channel) ch.role.clear(), ch.reason += "; another channel is a more regular train";
  return r;
}

}  // namespace fourbar
