// `fourbar tap REC`: a link's modal frequencies and damping ratios from an
// accelerometer recording of a hammer tap, as rig-file lines to paste.

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
    "prints each mode's natural frequency and damping ratio with its standard error,\n"
    "then the [<link>.elastic] lines for the rig file. Record the link mounted as in\n"
    "the rig (pinned at both joints), the accelerometer where the sensor sits, from\n"
    "before the tap until the ringing has died away. Exit 2 when there is no decay.\n"
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
      "modes", po::value(&modes), "how many modes to fit, 1-8 (default: the spectrum's peaks, at most 4)")(
      "link", po::value(&link), "the link tapped, for the rig-file lines: coupler (default) or rocker")(
      "sample-rate-hz", po::value(&sample_rate_hz), "sample rate of a text recording without a time column");
  po::positional_options_description pos;
  pos.add("recording", 1);
  po::variables_map vm;
  if (!parse_arguments("tap", "REC [--channel C] [--modes N] [--link coupler|rocker]", kTapDetails, opts, pos, inv, vm))
    return 0;
  if (link != "coupler" && link != "rocker")
    throw InputError("tap: --link must be coupler or rocker, not '" + link + "'");
  if (vm.count("modes") && (modes < 1 || modes > 8)) throw InputError("tap: --modes must be 1 to 8");
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
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const TapMode& m = r.modes[k];
    std::cout << "  mode " << k + 1 << ": " << format_number(m.frequency_Hz, 6) << " ± "
              << format_number(m.frequency_sigma_Hz, 2) << " Hz, damping ratio " << format_number(m.damping_ratio, 4)
              << " ± " << format_number(m.damping_sigma, 2) << "\n";
  }
  std::cout << "# paste into the rig file (the standard errors above are 1 sigma):\n[" << link << ".elastic]\n"
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
