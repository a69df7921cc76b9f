// `fourbar tap REC`: a link's modal frequencies and damping ratios from an
// accelerometer recording of a hammer tap, as rig-file lines to paste.

#include <cmath>
#include <iostream>
#include <vector>

#include "acquire/reader.hpp"
#include "analyze/tap_modes.hpp"
#include "cli/command.hpp"
#include "common/error.hpp"
#include "common/format.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

namespace {

constexpr const char* kTapDetails =
    "Finds the tap (the largest value), fits the free decay after it with a sum of\n"
    "damped sinusoids (spectrum peaks to start, then nonlinear least squares), and\n"
    "prints each mode's natural frequency and damping ratio with its uncertainty (the\n"
    "fit's standard error and its change when the fit starts 2 ms later), then the\n"
    "[<link>.elastic] lines for the rig file, with a '#' note when two modes' ratio\n"
    "is not a pinned link's. A bounce of the hammer (a second strike) is found and\n"
    "named, as is a clipped tap (samples at the recorder's limits); the decay is\n"
    "fitted from after the last strike or clipped sample. Record the link mounted\n"
    "as in the rig (pinned at both joints), the accelerometer where the sensor sits,\n"
    "from before the tap until the ringing has died away. Exit 2 when there is no\n"
    "decay.\n"
    "docs/flex.md \"Tap test\".\n";

std::vector<double> read_channel(const std::string& file, const ReaderOptions& options, const std::string& channel,
                                 double& sample_rate_hz, std::string& channel_name) {
  const auto reader = open_recording(file, options);
  const RecordingInfo& info = reader->info();
  int index = -1;
  if (channel.empty()) {
    index = 0;
  } else {
    for (int c = 0; c < info.channels; ++c)
      if (c < static_cast<int>(info.channel_names.size()) && info.channel_names[static_cast<std::size_t>(c)] == channel)
        index = c;
    if (index < 0 && channel.find_first_not_of("0123456789") == std::string::npos) index = std::stoi(channel) - 1;
    if (index < 0 || index >= info.channels)
      throw InputError(file + ": no channel '" + channel + "' (it has " + std::to_string(info.channels) +
                       "); give --channel as a column name or a number from 1");
  }
  channel_name = index < static_cast<int>(info.channel_names.size()) &&
                         !info.channel_names[static_cast<std::size_t>(index)].empty()
                     ? info.channel_names[static_cast<std::size_t>(index)]
                     : std::to_string(index + 1);
  sample_rate_hz = info.sample_rate_hz;
  std::vector<double> out, block(static_cast<std::size_t>(4096 * info.channels));
  while (const std::size_t frames = reader->read(block))
    for (std::size_t f = 0; f < frames; ++f)
      out.push_back(block[f * static_cast<std::size_t>(info.channels) + static_cast<std::size_t>(index)]);
  return out;
}

}  // namespace

int run_tap(const Invocation& inv) {
  std::string recording, channel, link = "coupler";
  int modes = 0;
  double sample_rate_hz = 0;
  po::options_description opts("options");
  opts.add_options()("recording", po::value(&recording)->required(), "the tap recording (any format fourbar reads)")(
      "channel", po::value(&channel), "the accelerometer channel: column name or number from 1 (default: the first)")(
      "modes", po::value(&modes),
      "report the N lowest modes, 1-8 (all that stand out are fitted; default: the spectrum's peaks, at most 4)")(
      "link", po::value(&link), "the link tapped, for the rig-file lines: coupler (default) or rocker")(
      "sample-rate-hz", po::value(&sample_rate_hz), "sample rate of a text recording without a time column");
  po::positional_options_description pos;
  pos.add("recording", 1);
  po::variables_map vm;
  if (!parse_arguments("tap", "REC [--channel C] [--modes N] [--link coupler|rocker]", kTapDetails, opts, pos, inv, vm))
    return 0;
  if (link != "coupler" && link != "rocker")
    throw InputError("tap: --link must be coupler or rocker, not '" + link + "'");
  if (vm.count("modes") && (modes < 1 || modes > kMaxTapModes))
    throw InputError("tap: --modes must be 1 to " + std::to_string(kMaxTapModes));
  ReaderOptions options;
  if (vm.count("sample-rate-hz")) {
    if (!(sample_rate_hz > 0)) throw InputError("tap: --sample-rate-hz must be positive");
    options.sample_rate_hz = sample_rate_hz;
  }
  double fs = 0;
  std::string name;
  const std::vector<double> x = read_channel(recording, options, channel, fs, name);
  TapResult r;
  try {
    r = identify_tap_modes(x, fs, {modes});
  } catch (const InputError& e) {
    throw InputError(recording + ": channel '" + name + "' " + e.what());
  }
  std::cout << recording << ": channel '" << name << "', " << format_number(fs) << " Hz, tap at "
            << format_number(r.tap_time_s, 4) << " s, " << format_number(r.decay_duration_s, 3)
            << " s of decay fitted (" << format_number(r.decay_db, 3) << " dB to the noise floor)\n";
  if (r.clipped_samples > 0)
    std::cout << "  clipped: " << r.clipped_samples << " samples at the recorder's limits, the last at "
              << format_number(r.clipped_until_s, 4) << " s; the decay is fitted from after them (tap softer, or "
              << "set a larger input range, to fit the loudest part too)\n";
  if (!r.later_strikes_s.empty()) {
    // A bounce follows its strike within milliseconds; a strike later than
    // kBounceWithin_s is a tap of its own (a record of several taps).
    constexpr double kBounceWithin_s = 0.05;
    std::vector<double> bounces, taps;
    double previous = r.tap_time_s;
    for (double t : r.later_strikes_s) {
      (t - previous < kBounceWithin_s ? bounces : taps).push_back(t);
      previous = t;
    }
    if (!bounces.empty()) {
      std::cout << "  the hammer struck again (a bounce) at";
      for (double t : bounces)
        std::cout << " " << format_number(t, 4) << " s (+" << format_number(1e3 * (t - r.tap_time_s), 3) << " ms)";
      std::cout << "\n";
    }
    if (!taps.empty()) {
      std::cout << "  the record holds " << taps.size() << " more tap(s), at";
      for (double t : taps) std::cout << " " << format_number(t, 4) << " s";
      std::cout << "; one tap is fitted, the last (cut the record to fit another)\n";
    }
    std::cout << "  the decay is fitted from " << format_number(r.decay_start_s, 4)
              << " s, after the last strike, where it is free"
              << (bounces.empty() ? "" : " (a quick, firm tap avoids the bounce)") << "\n";
  }
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const TapMode& m = r.modes[k];
    std::cout << "  mode " << k + 1 << ": " << format_number(m.frequency_Hz, 6) << " ± "
              << format_number(m.frequency_uncertainty_Hz(), 2) << " Hz, damping ratio "
              << format_number(m.damping_ratio, 4) << " ± " << format_number(m.damping_uncertainty(), 2) << "\n";
  }
  if (!r.steady_tones_Hz.empty()) {
    std::cout << "  steady tone(s), fitted and left out (no decay over the " << format_number(r.decay_duration_s, 3)
              << " s fitted: mains hum or a machine nearby):";
    for (double f : r.steady_tones_Hz) std::cout << " " << format_number(f, 5) << " Hz";
    std::cout << "\n";
  }
  if (!r.higher_modes_Hz.empty()) {
    std::cout << "  also fitted, not reported (only the " << r.modes.size() << " lowest were asked for):";
    for (double f : r.higher_modes_Hz) std::cout << " " << format_number(f, 5) << " Hz";
    std::cout << "\n";
  }
  // The rig file's k-th entry is the link's k-th in-plane bending mode; a
  // pinned–pinned bar's follow as k², so a ratio far from that says a mode
  // is missing (the tap or the sensor at its node) or does not belong.
  for (std::size_t k = 1; k < r.modes.size(); ++k) {
    const double ratio = r.modes[k].frequency_Hz / r.modes[k - 1].frequency_Hz;
    const double expected = std::pow(static_cast<double>(k + 1) / static_cast<double>(k), 2);
    if (ratio > 1.5 * expected)
      std::cout << "# note: mode " << k + 1 << " is " << format_number(ratio, 3) << " times mode " << k
                << ", a pinned-pinned link's next mode near " << format_number(expected, 3)
                << " times: a mode between them may be missing (tap and measure away from its node, e.g. at 0.3 "
                   "of the length), and the rig file's entries must be the link's modes in order\n";
    else if (ratio < 0.65 * expected)
      std::cout << "# note: mode " << k + 1 << " is only " << format_number(ratio, 3) << " times mode " << k
                << " (a pinned-pinned link's next mode near " << format_number(expected, 3)
                << " times): check that both are this link's in-plane bending (not out-of-plane, a mount or "
                   "another part) before pasting\n";
  }
  std::cout << "# paste into the rig file (± above: the fit's 1-sigma standard error and its change when the fit "
               "starts 2 ms later, in quadrature):\n["
            << link << ".elastic]\n"
            << "mode_frequencies_Hz = [";
  for (std::size_t k = 0; k < r.modes.size(); ++k)
    std::cout << (k ? ", " : "") << format_number(r.modes[k].frequency_Hz, 6);
  std::cout << "]\ndamping_ratios = [";
  for (std::size_t k = 0; k < r.modes.size(); ++k)
    std::cout << (k ? ", " : "") << format_number(r.modes[k].damping_ratio, 3);
  std::cout << "]\n";
  return 0;
}

}  // namespace fourbar::cli
