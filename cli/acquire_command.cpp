// `fourbar acquire REC [--manifest M] [--out [DIR]]`: without --out, checks
// a recording with its manifest and prints a summary (nothing written); with
// it, calibrated, angle-tagged samples and revolutions with a JSON summary.

#include <cmath>
#include <iostream>
#include <memory>

#include "acquire/acquisition.hpp"
#include "cli/command.hpp"
#include "common/atomic_output.hpp"
#include "common/csv_writer.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/json_text.hpp"
#include "common/provenance.hpp"
#include "common/units.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

namespace {

constexpr const char* kAcquireDetails = R"(Reads a recording (WAV/W64/RF64/FLAC/CAF/AIFF via libsndfile, MATLAB .mat,
NI TDMS, UFF dataset 58/58b, or CSV/TSV text)
and its manifest (default: REC with extension .toml beside it), finds the
crank pulses, fits the crank angle through them. Without --out it only
checks and prints a summary (format, channels, pulses, revolutions, speed,
clipping, warnings; nothing is written). With --out DIR (--out alone:
out/<recording name>/acquire) it writes into DIR:
  samples.csv         every sample inside a complete revolution: crank_deg,
                      time_s, revolution, omega2_rad_s, alpha2_rad_s2, then
                      <channel>_m_s2 per accelerometer channel (calibrated,
                      axis sign applied, gravity still in: specific force)
  revolutions.csv     each revolution on N crank angles (same columns;
                      crank_deg from the pulse angle through one turn)
  revolution_list.csv per revolution: start_time_s, period_s, speed_rpm,
                      segment, repaired, clipped
  pulses.csv          every pulse edge: time_s, segment, status
                      (detected, inserted, removed, isolated)
  summary.json        recording, channels, thresholds, pulse repairs and
                      gaps, revolutions, rpm mean/std/min/max, clipping,
                      warnings, provenance (of the CSV files too)
With --binary, samples.f64 and revolutions.f64 hold the same columns as
float64 little-endian rows (numpy: fromfile(f, '<f8').reshape(-1, ncols));
summary.json "series" lists their columns and row counts.

Manifest (TOML) keys: rig, clearance_mm, full_scale_V, adc_range_V,
sample_rate_hz, time_column, header_line, crank_direction (ccw|cw), sampling
(simultaneous|multiplexed) + skew_us, daq_filter (none|butterworth|
linear_phase) + daq_filter_order + daq_filter_cutoff_Hz | daq_filter_delay_us,
notes; per
[[channel]]: index | column, name, role (coupler_tangential coupler_normal
rocker_tangential rocker_normal crank_pulse crank_index encoder_a encoder_b
crank_speed ignore), sensitivity_mV_per_m_s2 + gain | sensitivity_mV_per_g + gain |
volts_per_unit, axis_sign,
position_mm (from the crank pin A on the coupler, from the pivot O4 on the
rocker), offset_mm, ac_coupled + highpass_hz, sensor_resonance_Hz +
sensor_resonance_Q; crank_pulse: polarity
(rising|falling), threshold_low_V + threshold_high_V, crank_offset_deg,
debounce_ms, pulses_per_rev + (a crank_index channel | missing_teeth) for a
tooth wheel; encoder_a: lines_per_rev (with an encoder_b channel, optional
crank_index = Z); correct_tooth_spacing; crank_smoothing (none|spline) +
smoothing_period_turns; crank_speed: rpm_per_V (default: values in rpm;
an optional crank_pulse sets the zero, else crank_offset_deg); notes.
Meanings and the sensor frame: docs/acquire.md.
Warnings (repaired pulses, gaps, clipping) go to stderr and summary.json.
)";

/// A series file: CSV, or raw little-endian float64 rows (`.f64`) for long
/// recordings, whose columns summary.json lists.
class SeriesFile {
 public:
  SeriesFile(const std::filesystem::path& path, const Provenance& prov, std::vector<std::string> columns, bool binary)
      : columns_(columns) {
    if (binary) binary_ = std::make_unique<AtomicOutput>(path, true);
    else csv_ = std::make_unique<CsvWriter>(path, prov.csv_comment_lines(), std::move(columns));
  }
  void row(std::span<const double> v) {
    ++rows_;
    if (csv_) return csv_->row(v);
    for (double x : v)
      if (!std::isfinite(x)) throw RunError(binary_->path().string() + ": a value is not finite; nothing was written");
    binary_->stream().write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(double)));
  }
  void commit() { csv_ ? csv_->commit() : binary_->commit(); }
  nlohmann::json layout(const std::string& name) const {
    return {{"file", name}, {"columns", columns_}, {"rows", rows_}, {"format", csv_ ? "csv" : "float64 little-endian, row-major"}};
  }

 private:
  std::vector<std::string> columns_;
  std::unique_ptr<CsvWriter> csv_;
  std::unique_ptr<AtomicOutput> binary_;
  std::uint64_t rows_ = 0;
};

class CsvSink : public AcquisitionSink {
 public:
  CsvSink(const std::filesystem::path& dir, const Provenance& prov, const std::vector<AcquiredChannel>& channels,
          bool samples, bool binary)
      : ext_(binary ? ".f64" : ".csv") {
    std::vector<std::string> cols{"crank_deg", "time_s", "revolution", "omega2_rad_s", "alpha2_rad_s2"};
    for (const auto& c : channels) cols.push_back(c.column());
    if (samples) samples_ = std::make_unique<SeriesFile>(dir / ("samples" + ext_), prov, cols, binary);
    std::swap(cols[1], cols[2]);  // revolutions: crank_deg, revolution, time_s, …
    revolutions_ = std::make_unique<SeriesFile>(dir / ("revolutions" + ext_), prov, cols, binary);
    list_ = std::make_unique<CsvWriter>(
        dir / "revolution_list.csv", prov.csv_comment_lines(),
        std::vector<std::string>{"revolution", "start_time_s", "period_s", "speed_rpm", "segment", "repaired", "clipped"});
    row_.resize(5 + channels.size());
  }
  void on_samples(const SampleBlock& b) override {
    if (!samples_) return;
    for (std::size_t i = 0; i < b.size(); ++i) {
      row_[0] = units::rad_to_deg(b.crank_rad[i]);
      row_[1] = b.time_s[i];
      row_[2] = static_cast<double>(b.revolution[i]);
      row_[3] = b.omega2_rad_s[i];
      row_[4] = b.alpha2_rad_s2[i];
      for (std::size_t c = 0; c < b.channels_m_s2.size(); ++c) row_[5 + c] = b.channels_m_s2[c][i];
      samples_->row(row_);
    }
  }
  void on_revolution(const Revolution& r) override {
    for (std::size_t j = 0; j < r.crank_rad.size(); ++j) {
      row_[0] = units::rad_to_deg(r.crank_rad[j]);
      row_[1] = static_cast<double>(r.number);
      row_[2] = r.time_s[j];
      row_[3] = r.omega2_rad_s[j];
      row_[4] = r.alpha2_rad_s2[j];
      for (std::size_t c = 0; c < r.channels_m_s2.size(); ++c) row_[5 + c] = r.channels_m_s2[c][j];
      revolutions_->row(row_);
    }
    const double item[] = {static_cast<double>(r.number), r.start_time_s, r.period_s, r.speed_rpm(),
                           static_cast<double>(r.segment), r.repaired ? 1.0 : 0.0, r.clipped ? 1.0 : 0.0};
    list_->row(item);
  }
  void commit() {
    if (samples_) samples_->commit();
    revolutions_->commit();
    list_->commit();
  }
  nlohmann::json layout() const {
    nlohmann::json j = {{"revolutions", revolutions_->layout("revolutions" + ext_)}};
    if (samples_) j["samples"] = samples_->layout("samples" + ext_);
    return j;
  }

 private:
  std::string ext_;
  std::unique_ptr<SeriesFile> samples_, revolutions_;
  std::unique_ptr<CsvWriter> list_;
  std::vector<double> row_;
};

nlohmann::json stats_json(const ChannelStats& s, const char* unit) {
  const std::string u = unit;
  return {{"min_" + u, s.min}, {"max_" + u, s.max}, {"mean_" + u, s.mean}, {"rms_" + u, s.rms},
          {"clipped_samples", s.clipped_samples}, {"first_clip_s", s.clipped_samples ? nlohmann::json(s.first_clip_s) : nlohmann::json()}};
}

/// `fourbar acquire REC` without --out: the whole acquisition, nothing written,
/// a summary on stdout and the warnings on stderr.
int check_recording(Reader& reader, const Manifest& m, int samples_per_rev, const TimeRange& range, bool quiet) {
  struct Discard final : AcquisitionSink {
    bool wants_grid() const override { return false; }
  } discard;
  AcquireOptions options;
  options.grid_points_per_rev = samples_per_rev;
  options.progress = !quiet;
  options.range = range;
  const AcquisitionReport rep = acquire(reader, m, options, discard);
  const RecordingInfo& ri = rep.recording;
  std::cout << ri.file.string() << ": " << ri.format << " " << ri.sample_format << ", " << ri.channels << " channels, "
            << format_number(ri.sample_rate_hz) << " Hz, " << format_number(ri.duration_s()) << " s; manifest "
            << m.file.string() << " (rig " << m.rig_file.string() << ", clearance "
            << format_number(units::m_to_mm(m.clearance_m)) << " mm)\n";
  for (std::size_t c = 0; c < rep.channels.size(); ++c) {
    const auto& ch = rep.channels[c];
    const ChannelStats& s = rep.channel_stats[c];
    std::cout << "  " << ch.name << " (" << to_string(ch.role) << ", channel " << ch.index << "): " << format_number(s.min)
              << " .. " << format_number(s.max) << " m/s^2, RMS " << format_number(s.rms)
              << (s.clipped_samples ? ", CLIPPED " + std::to_string(s.clipped_samples) + " samples" : "") << "\n";
  }
  std::size_t kept = 0;
  for (const auto& seg : rep.pulses.segments) kept += seg.size();
  std::cout << "  crank pulses ('" << rep.pulse_channel << "'): " << kept << " kept, " << rep.pulses.inserted_s.size()
            << " inserted, " << rep.pulses.removed_s.size() << " removed, " << rep.pulses.gaps.size() << " gaps\n"
            << "  " << rep.revolutions << " complete revolutions, " << format_number(rep.speed.mean_rpm) << " rpm mean (std "
            << format_number(rep.speed.std_rpm) << ", " << format_number(rep.speed.min_rpm) << " .. "
            << format_number(rep.speed.max_rpm) << ")" << (rep.revolutions_clipped ? ", " + std::to_string(rep.revolutions_clipped) + " clipped" : "")
            << "\n";
  for (const auto& w : rep.warnings) std::cerr << "fourbar: warning: " << w << "\n";
  std::cout << "checked: " << (rep.warnings.empty() ? "no warnings" : std::to_string(rep.warnings.size()) + " warning(s) on stderr")
            << "; nothing written (give --out DIR to write the samples and revolutions)\n";
  return 0;
}

}  // namespace

int run_acquire(const Invocation& inv) {
  std::string recording, manifest_file, out_dir;
  int samples_per_rev = 0;
  double start_s = 0, end_s = 0;
  bool no_samples = false, binary = false, csv_comments = false, quiet = false;
  po::options_description opts("options");
  opts.add_options()("recording", po::value(&recording)->required(), "the recording (WAV, FLAC, …, .mat, .tdms, .uff, CSV)")(
      "manifest,m", po::value(&manifest_file), "manifest TOML (default: the recording's name with .toml)")(
      "out,o", po::value(&out_dir)->implicit_value(""),
      "output folder (alone: out/<recording name>/acquire); without --out: check and summarise only")(
      "samples-per-rev,n", po::value(&samples_per_rev),
      "crank angles per revolution in revolutions.csv (default: the smallest multiple of 360 >= the samples "
      "per revolution)")("no-samples", po::bool_switch(&no_samples), "do not write samples.csv (long recordings)")(
      "binary", po::bool_switch(&binary),
      "write samples.f64 and revolutions.f64 (float64 little-endian rows, columns as the CSV; listed in "
      "summary.json) instead of CSV")(
      "start-s", po::value(&start_s), "only the turns from this recording time on (s; over the manifest's start_s)")(
      "end-s", po::value(&end_s), "only the turns up to this recording time (s; over the manifest's end_s)");
  add_csv_comments_option(opts, csv_comments);
  add_quiet_option(opts, quiet);
  po::positional_options_description pos;
  pos.add("recording", 1);
  po::variables_map vm;
  if (!parse_arguments("acquire", "REC [--manifest M] [--out [DIR]] [-n N] [--start-s T] [--end-s T] [--no-samples] [--binary] [--csv-comments] [-q]", kAcquireDetails, opts, pos,
                       inv, vm))
    return 0;
  const bool write = vm.count("out") > 0;
  if (write && out_dir.empty())
    out_dir = (std::filesystem::path("out") / std::filesystem::path(recording).stem() / "acquire").string();
  if (vm.count("samples-per-rev") && (samples_per_rev < 4 || samples_per_rev > 10'000'000))
    throw InputError("acquire: --samples-per-rev " + std::to_string(samples_per_rev) + " must be between 4 and 10000000");

  // Check every input before creating anything.
  OpenedRecording opened = open_with_manifest(recording, manifest_file);
  const Manifest& m = opened.manifest;
  TimeRange range;
  if (vm.count("start-s")) range.start_s = start_s;
  if (vm.count("end-s")) range.end_s = end_s;
  if (range.start_s && range.end_s && !(end_s > start_s))
    throw InputError("acquire: --end-s " + format_number(end_s) + " must be after --start-s " + format_number(start_s));
  if (!write) return check_recording(*opened.reader, m, samples_per_rev, range, quiet);
  ensure_output_dir(out_dir);
  const std::filesystem::path dir(out_dir);
  Provenance prov{inv.command_line, {recording, m.file, m.rig_file}, csv_comments};

  AcquireOptions options;
  options.grid_points_per_rev = samples_per_rev;
  options.progress = !quiet;
  options.range = range;
  std::vector<AcquiredChannel> channels;
  for (const auto& c : m.channels)
    if (is_accelerometer(c.role)) channels.push_back({c.name, c.role, *c.index, c.position_m, c.offset_m, c.ac_coupled, c.highpass_hz});
  CsvSink sink(dir, prov, channels, !no_samples, binary);
  const AcquisitionReport rep = acquire(*opened.reader, m, options, sink);

  // Pulse list and summary.
  CsvWriter pulses(dir / "pulses.csv", prov.csv_comment_lines(), {"time_s", "segment", "status"});
  {
    struct Item {
      double t;
      double segment;
      const char* status;
    };
    std::vector<Item> items;
    for (std::size_t s = 0; s < rep.pulses.segments.size(); ++s)
      for (const auto& p : rep.pulses.segments[s])
        items.push_back({p.time_s, static_cast<double>(s), p.inserted ? "inserted" : "detected"});
    for (double t : rep.pulses.removed_s) items.push_back({t, -1, "removed"});
    for (double t : rep.pulses.orphan_s) items.push_back({t, -1, "isolated"});
    std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.t < b.t; });
    for (const auto& it : items) {
      const double v[] = {it.t, it.segment, 0.0};
      pulses.row(std::span<const double>(v, 2), it.status);
    }
  }

  nlohmann::json j;
  j["provenance"] = prov.to_json();
  const RecordingInfo& ri = rep.recording;
  j["recording"] = {{"file", ri.file.string()}, {"format", ri.format}, {"sample_format", ri.sample_format},
                    {"channels", ri.channels}, {"sample_rate_hz", ri.sample_rate_hz}, {"frames", ri.frames},
                    {"start_time_s", ri.start_time_s}, {"duration_s", ri.duration_s()}};
  j["manifest"] = {{"file", m.file.string()}, {"rig", m.rig_file.string()},
                   {"clearance_mm", units::m_to_mm(m.clearance_m)}, {"full_scale_V", m.full_scale_V},
                   {"crank_direction", m.crank_direction > 0 ? "ccw" : "cw"}};
  j["channels"] = nlohmann::json::array();
  for (std::size_t c = 0; c < rep.channels.size(); ++c) {
    const auto& ch = rep.channels[c];
    nlohmann::json cj = {{"name", ch.name}, {"column", ch.column()}, {"role", to_string(ch.role)}, {"index", ch.index},
                         {"position_mm", units::m_to_mm(ch.position_m)}, {"offset_mm", units::m_to_mm(ch.offset_m)},
                         {"ac_coupled", ch.ac_coupled}, {"highpass_hz", ch.highpass_hz}};
    cj.update(stats_json(rep.channel_stats[c], "m_s2"));
    j["channels"].push_back(cj);
  }
  const auto& th = rep.thresholds;
  const auto& tr = rep.pulses;
  nlohmann::json gaps = nlohmann::json::array();
  for (const auto& g : tr.gaps) gaps.push_back({{"from_s", g.from_s}, {"to_s", g.to_s}, {"periods", g.periods}});
  std::size_t kept = 0;
  for (const auto& s : tr.segments) kept += s.size();
  j["pulses"] = {{"channel", rep.pulse_channel},
                 {"levels_V", {{"bottom", th.bottom_level}, {"top", th.top_level}, {"noise", th.noise}}},
                 {"edge_level_V", rep.edge_level_V},
                 {"thresholds_V", {{"low", th.low}, {"high", th.high}, {"automatic", th.automatic}}},
                 {"edges_detected", tr.edges},
                 {"edges_debounced", rep.edges_debounced},
                 {"pulses", kept},
                 {"segments", tr.segments.size()},
                 {"removed", {{"count", tr.removed_s.size()}, {"times_s", tr.removed_s}}},
                 {"inserted", {{"count", tr.inserted_s.size()}, {"times_s", tr.inserted_s}}},
                 {"isolated", {{"count", tr.orphan_s.size()}, {"times_s", tr.orphan_s}}},
                 {"gaps", gaps}};
  if (rep.wheel.positions_per_rev > 0) {
    const WheelReport& w = rep.wheel;
    nlohmann::json teeth = nlohmann::json::array();
    for (double e : w.tooth_error_deg) teeth.push_back(std::isnan(e) ? nlohmann::json() : nlohmann::json(e));
    j["wheel"] = {{"source", w.source},
                  {"positions_per_rev", w.positions_per_rev},
                  {"edges", w.edges},
                  {"turns_dropped", w.turns_cut},
                  {"count_direction", w.count_direction},
                  {"tooth_spacing_corrected", w.corrected},
                  {"tooth_error_deg", teeth},
                  {"tooth_error_rms_deg", w.tooth_error_rms_deg},
                  {"tooth_error_max_deg", w.tooth_error_max_deg},
                  {"tooth_error_standard_error_deg", w.tooth_error_standard_error_deg},
                  {"turns_averaged", w.turns_averaged},
                  {"once_per_turn_deg", w.once_per_turn_deg},
                  {"twice_per_turn_deg", w.twice_per_turn_deg}};
  }
  if (rep.smoothing.period_turns > 0) {
    const CrankSmoothingReport& sm = rep.smoothing;
    j["crank_smoothing"] = {{"method", "spline"},
                            {"period_turns", sm.period_turns},
                            {"knot_spacing_turns", sm.knot_spacing_turns},
                            {"edge_jitter_s", sm.fit.jitter_s},
                            {"residual_rms_s", sm.residual_rms_s},
                            {"shift_rms_s", sm.shift_rms_s},
                            {"shift_ratio_to_jitter", sm.shift_ratio},
                            {"worst_block", {{"from_s", sm.fit.worst_from_s},
                                             {"to_s", sm.fit.worst_to_s},
                                             {"residual_rms_s", sm.fit.worst_rms_s},
                                             {"residual_rms_deg", sm.fit.worst_rms_deg},
                                             {"ratio_to_jitter", sm.fit.worst_ratio}}}};
  }
  const double first_pulse = tr.segments.front().front().time_s, last_pulse = tr.segments.back().back().time_s;
  j["revolutions"] = {{"kept", rep.revolutions},
                      {"repaired", rep.revolutions_repaired},
                      {"clipped", rep.revolutions_clipped},
                      {"dropped_in_gaps", rep.revolutions_in_gaps},
                      {"range", {{"start_s", rep.range.start_s ? nlohmann::json(*rep.range.start_s) : nlohmann::json()},
                                 {"end_s", rep.range.end_s ? nlohmann::json(*rep.range.end_s) : nlohmann::json()}}},
                      {"dropped_partial_s", {first_pulse - ri.start_time_s, ri.start_time_s + ri.duration_s() - last_pulse}},
                      {"samples_per_revolution", rep.grid_points_per_rev},
                      {"recorded_samples_per_revolution", rep.frames_per_rev}};
  j["speed_rpm"] = {{"mean", rep.speed.mean_rpm}, {"std", rep.speed.std_rpm}, {"min", rep.speed.min_rpm},
                    {"max", rep.speed.max_rpm}};
  j["clipping_checked"] = rep.clipping_checked;
  j["warnings"] = rep.warnings;
  j["series"] = sink.layout();
  const std::string ext = binary ? ".f64" : ".csv";
  j["outputs"] = nlohmann::json::array({"revolutions" + ext, "revolution_list.csv", "pulses.csv", "summary.json"});
  if (!no_samples) j["outputs"].push_back("samples" + ext);

  // All complete: move into place.
  AtomicOutput summary(dir / "summary.json");
  summary.stream() << json_text(j, 2) << "\n";
  sink.commit();
  pulses.commit();
  summary.commit();

  for (const auto& w : rep.warnings) std::cerr << "fourbar: warning: " << w << "\n";
  std::cout << "acquired " << rep.revolutions << " revolutions (" << rep.speed.mean_rpm << " rpm mean, "
            << rep.grid_points_per_rev << " crank angles each) from " << recording << " into " << out_dir << "\n";
  return 0;
}

}  // namespace fourbar::cli
