// `fourbar inspect REC [--manifest-template]`: what a recording holds, from
// the file alone — before there is a manifest.

#include <cstdio>
#include <iostream>

#include "acquire/inspect.hpp"
#include "acquire/manifest_template.hpp"
#include "cli/command.hpp"
#include "common/error.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

namespace {

constexpr const char* kInspectDetails = R"(Reads a recording without a manifest (WAV/W64/RF64/FLAC/CAF/AIFF, MATLAB
.mat v5/v7/v7.3, NI TDMS, UFF dataset 58/58b, CSV/TSV text) and prints its format, sample rate and
duration, and per channel: min, max, mean (the DC level), RMS, AC RMS (about
the mean), clipping (samples at the digital rails of an integer format, or
runs of >= 3 equal samples at the channel's min or max), whether it is a
pulse train (its rate -> the crank speed at one pulse per turn) and a guess
of its role (from the data and the channel's name).

--manifest-template writes instead, on stdout, a manifest to start from:
  fourbar inspect REC.wav --manifest-template > REC.toml
with the channels, the crank-pulse channel and its polarity, and "FILL IN"
for each value only the set-up can tell (rig, sensitivities, axis signs,
positions, AC coupling, crank offset and direction). acquire, analyze and
report refuse the manifest while a "FILL IN" is left, naming the key.
A text file without a time column or a preamble's sample rate needs
--sample-rate-hz; --header-line N names the line of its column names when
the search below the preamble does not find them; a .mat file
without a time variable or rate scalar needs --rate-variable or
--sample-rate-hz (both are written into the template).
)";

std::string num(double v, const char* fmt = "%.4g") {
  char buf[48];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string pad(std::string s, std::size_t width) {
  if (s.size() < width) s.append(width - s.size(), ' ');
  return s;
}

void print_inspection(std::ostream& os, const RecordingInspection& r) {
  const RecordingInfo& i = r.info;
  os << i.file.string() << ": " << i.format << " " << i.sample_format << ", " << i.channels << " channel"
     << (i.channels == 1 ? "" : "s") << ", " << num(i.sample_rate_hz, "%.10g") << " Hz"
     << (i.rate_variable ? " (from the variable '" + *i.rate_variable + "')" : "") << ", " << i.frames << " samples = "
     << num(i.duration_s(), "%.6g") << " s";
  if (i.start_time_s != 0) os << " from t = " << num(i.start_time_s, "%.6g") << " s";
  if (!i.started_at.empty()) os << ", started " << i.started_at;
  os << "\n\n";
  std::size_t w = 4;
  for (const auto& ch : r.channels) w = std::max(w, ch.name.size() + (ch.unit.empty() ? 0 : ch.unit.size() + 3));
  os << "  ch  " << pad("name", w) << "         min         max   mean (DC)         RMS      AC RMS  clipped  role guess\n";
  for (const auto& ch : r.channels) {
    std::string label = ch.name.empty() ? "-" : ch.name;
    if (!ch.unit.empty()) label += " [" + ch.unit + "]";
    char row[160];
    std::snprintf(row, sizeof row, "%4d  %s %11.5g %11.5g %11.5g %11.5g %11.5g  %-7s  ", ch.index, pad(label, w).c_str(),
                  ch.min, ch.max, ch.mean, ch.rms, ch.ac_rms,
                  ch.rail_samples ? "YES" : ch.clipped() ? "maybe" : "no");
    os << row << (ch.role.empty() ? "?" : ch.role) << "\n";
  }
  os << "\n";
  for (const auto& ch : r.channels) os << "  channel " << ch.index << ": " << ch.reason << "\n";
  if (r.pulse_channel >= 0) {
    const PulseTrainGuess& p = *r.channels[static_cast<std::size_t>(r.pulse_channel)].pulse;
    os << "\ncrank pulses on channel " << r.pulse_channel << ": " << num(p.rpm, "%.5g") << " rpm at one pulse per turn ("
       << num(p.rate_hz, "%.6g") << " Hz, " << p.pulses << " pulses)\n";
  } else {
    os << "\nno channel looks like a crank-pulse train (two levels, regular edges)\n";
  }
  for (const auto& n : i.notes) os << "note: " << n << "\n";
}

}  // namespace

int run_inspect(const Invocation& inv) {
  std::string recording, rate_variable, time_column;
  double sample_rate_hz = 0;
  std::size_t header_line = 0;
  bool want_template = false;
  po::options_description opts("options");
  opts.add_options()("recording", po::value(&recording)->required(), "the recording (WAV, FLAC, …, .mat, .tdms, .uff, CSV)")(
      "manifest-template", po::bool_switch(&want_template),
      "write a manifest template to stdout instead of the summary (FILL IN marks what to enter)")(
      "sample-rate-hz", po::value(&sample_rate_hz), "sample rate of a text or .mat recording that does not give one")(
      "rate-variable", po::value(&rate_variable), ".mat: the scalar variable that holds the sample rate in Hz")(
      "time-column", po::value(&time_column), "text: the time column's name, when not t/time/time_s")(
      "header-line", po::value(&header_line), "text: the line number (from 1) of the column names, when not found below the preamble");
  po::positional_options_description pos;
  pos.add("recording", 1);
  po::variables_map vm;
  if (!parse_arguments("inspect", "REC [--manifest-template] [--sample-rate-hz F] [--rate-variable NAME]", kInspectDetails, opts,
                       pos, inv, vm))
    return 0;
  ReaderOptions options;
  if (vm.count("sample-rate-hz")) {
    if (!(sample_rate_hz > 0)) throw InputError("inspect: --sample-rate-hz must be positive");
    options.sample_rate_hz = sample_rate_hz;
  }
  if (!rate_variable.empty()) options.rate_variable = rate_variable;
  if (!time_column.empty()) options.time_column = time_column;
  if (vm.count("header-line")) {
    if (header_line < 1) throw InputError("inspect: --header-line counts lines from 1");
    options.header_line = header_line;
  }
  const auto reader = open_recording(recording, options);
  const RecordingInspection r = inspect_recording(*reader);
  if (want_template) std::cout << manifest_template(r, options);
  else print_inspection(std::cout, r);
  return 0;
}

}  // namespace fourbar::cli
