// `fourbar analyze REC [--manifest M] [--out DIR]`: coupler and rocker angular
// acceleration and velocity from a recording's accelerometers, averaged over
// the revolutions with their spread, spectra and a JSON summary.

#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <thread>

#include "analyze/analysis_defaults.hpp"
#include "analyze/pipeline.hpp"
#include "analyze/window.hpp"
#include "cli/command.hpp"
#include "common/atomic_output.hpp"
#include "common/csv_writer.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/json_text.hpp"
#include "common/provenance.hpp"
#include "common/units.hpp"
#include "report/recording_job.hpp"
#include "report/setup_check_record.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

namespace {

constexpr const char* kDetailsBeforeDefaults = R"(Acquires the recording (as 'fourbar acquire': manifest, crank pulses, crank
angle per sample) and turns its tangential accelerometers into the coupler's
and rocker's angular acceleration: the measured crank speed and acceleration,
the sensor position and offset, gravity and an AC-coupled sensor's high-pass
are taken into account (docs/analysis.md). Each channel is band-pass
filtered (zero phase, FFT), put on a crank-angle grid of N points per
revolution, integrated revolution by revolution to the angular velocity
(periodic: no drift) and averaged over the revolutions. A normal channel on
the same link checks |omega| independently. Long recordings are analysed in
chunks of revolutions in bounded memory; the result does not depend on it.
Writes into DIR (default out/<recording name>/analyze):
  averaged.csv       crank_deg, omega2_rad_s (crank speed), alpha3_rad_s2,
                     alpha3_std_rad_s2, omega3_rad_s, omega3_std_rad_s, the
                     same for alpha4/omega4 (when the manifest has a
                     rocker_tangential channel), and per normal channel
                     omegaN_sq_normal_rad2_s2, omegaN_sq_integrated_rad2_s2,
                     omegaN_abs_normal_rad_s (the check: |omega| from the
                     centripetal term); mean over the revolutions, std =
                     spread per angle
  per_revolution.csv (--per-revolution) crank_deg, revolution, averaged
                     (0: a guard or clipped revolution), omega2_rad_s,
                     alpha3_rad_s2, omega3_rad_s, alpha4_rad_s2, omega4_rad_s
  spectra.csv        frequency_Hz, order (multiples of the mean crank
                     frequency), filter_gain (the alpha filter's response),
                     alpha3_amplitude_rad_s2, alpha4_amplitude_rad_s2:
                     amplitude of the converted alpha before the filter
                     (Hann segments, 50 % overlap, RMS-averaged)
  summary.json       provenance, recording and acquisition summary (pulses,
                     revolutions, rpm), settings (filter, kernel taps, grid,
                     conversion, integration), RMS of the averaged curves and
                     of their spread, whether the turns repeat every 2-4
                     turns (alpha_turns_repeat; a line on the terminal when
                     they do; docs/analysis.md), normal-channel check,
                     warnings, setup_check (status "ok" or "check set-up",
                     findings); the provenance of the CSV files
)";

// The defaults paragraph of the details, its numbers from analyze/analysis_defaults.hpp.
std::string details_defaults() {
  namespace d = analysis_defaults;
  return "Defaults: band-pass from " + format_number(d::kLowCornerPerCrankHz) + " x the mean crank frequency to " +
         format_number(d::kHighCornerCapHz) + " Hz\n(at most " + format_number(d::kHighCornerMaxPerSampleRate) +
         " x the sample rate), Kaiser window (beta 8), transition " + format_number(d::kTransitionPerCrankHz) +
         " x the crank\nfrequency, no mains comb (give --mains-hz 50 or 60), N = " + std::to_string(d::kGridPoints) +
         " (more when the\nband needs it), spectral integration, chunks that fill a 2^" +
         std::to_string(d::kChunkFftFramesLog2) + "-sample FFT\n(about 2^" + std::to_string(d::kIdealChunkFramesLog2) +
         " samples with the ideal filter).\n";
}

constexpr const char* kDetailsAfterDefaults = R"(--thesis: the thesis's processing for comparison (thesis eq. 7.2.1-6/7.2.2-1
at the mean crank speed, sensor at the joint, no gravity, no AC correction;
ideal rectangular band-pass; running trapezoid in time, eq. 7.2.1-8).
Options given with --thesis override its settings.
Set-up check: from the data alone, the axis sign, calibration scale and
position of each accelerometer, the crank offset and direction of rotation,
and whether the coupler and rocker channels are swapped, compared with the
manifest; a likely mistake is a warning naming the key to change (and in
summary.json's setup_check; docs/setup-check.md).
Errors (exit 2, nothing written): no coupler_tangential channel, a sensor
outside its link, a corner at or above the Nyquist frequency, a window
parameter out of range (tukey 0..1, kaiser 0..50), a record too short; with
--strict, a likely set-up mistake.
)";

BandType parse_band(const std::string& s) {
  if (s == "bandpass") return BandType::bandpass;
  if (s == "lowpass") return BandType::lowpass;
  if (s == "highpass") return BandType::highpass;
  if (s == "bandstop") return BandType::bandstop;
  if (s == "none" || s == "allpass") return BandType::all_pass;
  throw InputError("analyze: --band '" + s + "' is not one of bandpass, lowpass, highpass, bandstop, none");
}

IntegrationMethod parse_integration(const std::string& s) {
  if (s == "spectral") return IntegrationMethod::spectral;
  if (s == "periodic") return IntegrationMethod::periodic;
  if (s == "closed-trapezoid") return IntegrationMethod::closed_trapezoid;
  if (s == "trapezoid") return IntegrationMethod::trapezoid;
  throw InputError("analyze: --integration '" + s + "' is not one of spectral, periodic, closed-trapezoid, trapezoid");
}

const char* link_index(SensedLink l) { return l == SensedLink::coupler ? "3" : "4"; }

/// Streams per-revolution rows to per_revolution.csv as they are analysed.
class RevolutionCsv final : public RevolutionObserver {
 public:
  RevolutionCsv(std::filesystem::path dir, Provenance prov) : dir_(std::move(dir)), prov_(std::move(prov)) {}
  void on_start(const RecordingAnalysis& a) override {
    ensure_output_dir(dir_);
    crank_deg_ = a.crank_deg;
    std::vector<std::string> cols{"crank_deg", "revolution", "averaged", "omega2_rad_s"};
    for (const auto* l : {&a.coupler, &a.rocker})
      if (*l) {
        const std::string i = link_index((*l)->link);
        cols.push_back("alpha" + i + "_rad_s2"), cols.push_back("omega" + i + "_rad_s");
      }
    row_.resize(cols.size());
    csv_ = std::make_unique<CsvWriter>(dir_ / "per_revolution.csv", prov_.csv_comment_lines(), std::move(cols));
  }
  void on_revolution(const AnalyzedRevolution& r) override {
    for (std::size_t k = 0; k < crank_deg_.size(); ++k) {
      std::size_t c = 0;
      row_[c++] = crank_deg_[k];
      row_[c++] = static_cast<double>(r.number);
      row_[c++] = r.averaged ? 1.0 : 0.0;
      row_[c++] = r.crank_speed_rad_s[k];
      for (const auto* s : {&r.alpha3_rad_s2, &r.omega3_rad_s, &r.alpha4_rad_s2, &r.omega4_rad_s})
        if (!s->empty()) row_[c++] = (*s)[k];
      csv_->row(row_);
    }
  }
  void commit() {
    if (csv_) csv_->commit();
  }

 private:
  std::filesystem::path dir_;
  Provenance prov_;
  std::vector<double> crank_deg_, row_;
  std::unique_ptr<CsvWriter> csv_;
};

nlohmann::json link_json(const LinkResult& l) {
  auto peak = [](const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
  };
  nlohmann::json j = {{"channel", l.channel},
                      {"revolutions", l.alpha_rad_s2.revolutions},
                      {"alpha_rms_rad_s2", l.alpha_rms_rad_s2},
                      {"alpha_peak_rad_s2", peak(l.alpha_rad_s2.mean)},
                      {"alpha_std_rms_rad_s2", l.alpha_std_rms_rad_s2},
                      {"omega_rms_rad_s", l.omega_rms_rad_s},
                      {"omega_peak_rad_s", peak(l.omega_rad_s.mean)},
                      {"omega_std_rms_rad_s", l.omega_std_rms_rad_s}};
  const TurnRepeat& r = l.alpha_repeat;
  j["alpha_turns_repeat"] = {{"turns", r.turns},
                             {"period_turns", r.period},
                             {"unconfirmed_period_turns", r.unconfirmed_period},
                             {"ratio", r.ratio()},
                             {"neighbours", r.neighbours()},
                             {"by_lag", std::vector<double>(r.by_lag.begin(), r.by_lag.end())}};
  if (l.normal)
    j["normal_check"] = {{"channel", l.normal->channel},
                         {"ac_coupled", l.normal->ac_coupled},
                         {"omega_sq_rel_rms_difference", l.normal->rel_rms_difference},
                         {"note", l.normal->ac_coupled
                                      ? "AC-coupled: the mean of omega^2 comes from the nominal model, only its "
                                        "variation is measured"
                                      : "omega^2 from the centripetal term, against the integrated omega squared"}};
  return j;
}

nlohmann::json filter_json(const FilterSpec& f) {
  return {{"description", describe(f)},  {"low_hz", f.low_hz},       {"high_hz", f.high_hz},
          {"mains_hz", f.mains_hz},      {"mains_width_hz", f.mains_width_hz}, {"window", to_string(f.window)},
          {"transition_hz", f.transition_hz}};
}

}  // namespace

int run_analyze(const Invocation& inv) {
  std::string recording, manifest_file, out_dir, band = "bandpass", window, integration;
  double low = 0, high = 0, mains = 0, mains_width = 1, transition = 0;
  double start_s = 0, end_s = 0;
  std::size_t points = 0, guard = 0, spectrum_segment = 0, chunk = 0;
  int jobs = 0;
  bool thesis = false, per_revolution = false, strict = false, csv_comments = false, quiet = false;
  namespace d = analysis_defaults;
  const std::string low_help =
      "lower corner in Hz (default: " + format_number(d::kLowCornerPerCrankHz) + " x the mean crank frequency)";
  const std::string high_help = "upper corner in Hz (default: " + format_number(d::kHighCornerCapHz) + ", at most " +
                                format_number(d::kHighCornerMaxPerSampleRate) + " x the sample rate)";
  const std::string transition_help = "transition width in Hz (default " + format_number(d::kTransitionPerCrankHz) +
                                      " x the crank frequency); 0: ideal bin-wise filter (rectangular)";
  const std::string chunk_help = "revolutions per processing chunk (default: as many as fill a 2^" +
                                 std::to_string(d::kChunkFftFramesLog2) + "-sample FFT; about 2^" +
                                 std::to_string(d::kIdealChunkFramesLog2) + " samples with the ideal filter)";
  po::options_description opts("options");
  opts.add_options()("recording", po::value(&recording)->required(), "the recording (WAV, FLAC, ..., CSV)")(
      "manifest,m", po::value(&manifest_file), "manifest TOML (default: the recording's name with .toml)")(
      "out,o", po::value(&out_dir), "output folder (default: out/<recording name>/analyze)")(
      "band", po::value(&band), "filter band: bandpass (default), lowpass, highpass, bandstop, none")(
      "low-hz", po::value(&low), low_help.c_str())(
      "high-hz", po::value(&high), high_help.c_str())(
      "mains-hz", po::value(&mains), "mains comb: notches at k x this frequency (50 or 60; default 0: none)")(
      "mains-width-hz", po::value(&mains_width), "width of each mains notch in Hz (default 1)")(
      "window", po::value(&window),
      "kernel window: rectangular, hann, tukey:ALPHA (0..1), kaiser:BETA (0..50) (default kaiser:8)")(
      "transition-hz", po::value(&transition),
      transition_help.c_str())(
      "integration", po::value(&integration),
      "alpha to omega, each revolution on its own: spectral (default; keeps the revolution's mean slope, follows "
      "crank-speed changes), periodic (strictly periodic, rejects a constant alpha offset), closed-trapezoid; or "
      "trapezoid (thesis: running in time, drifts)")("points,n", po::value(&points),
                                  "crank angles per revolution N (default 720, more when the band needs it)")(
      "guard-revolutions", po::value(&guard), "revolutions left out of the averages at each end of a pulse-train "
                                              "segment (default 0)")(
      "per-revolution", po::bool_switch(&per_revolution), "also write per_revolution.csv (every revolution)")(
      "strict", po::bool_switch(&strict), "a likely set-up mistake (the set-up check) is an error: exit 2, nothing written")(
      "spectrum-segment", po::value(&spectrum_segment),
      "samples per spectrum segment (default: a power of two >= 8 revolutions)")(
      "chunk-revolutions", po::value(&chunk), chunk_help.c_str())(
      "jobs,j", po::value(&jobs), "chunks analysed at once, one per core (default 0: every core); the outputs do not "
                                  "depend on it")(
      "thesis", po::bool_switch(&thesis), "the thesis's processing, for comparison (see below)")(
      "start-s", po::value(&start_s), "analyse only the turns from this recording time on (s; over the manifest's start_s)")(
      "end-s", po::value(&end_s), "analyse only the turns up to this recording time (s; over the manifest's end_s)");
  add_csv_comments_option(opts, csv_comments);
  add_quiet_option(opts, quiet);
  const std::string details = kDetailsBeforeDefaults + details_defaults() + kDetailsAfterDefaults;
  po::positional_options_description pos;
  pos.add("recording", 1);
  po::variables_map vm;
  if (!parse_arguments("analyze", "REC [--manifest M] [--out DIR] [options]", details, opts, pos, inv, vm)) return 0;
  if (out_dir.empty()) out_dir = (std::filesystem::path("out") / std::filesystem::path(recording).stem() / "analyze").string();

  AnalyzeOptions o = thesis ? AnalyzeOptions::thesis_method() : AnalyzeOptions{};
  o.filter.band = parse_band(band);
  if (vm.count("low-hz")) o.filter.low_hz = low;
  if (vm.count("high-hz")) o.filter.high_hz = high;
  o.filter.mains_hz = mains;
  o.filter.mains_width_hz = mains_width;
  if (vm.count("window")) o.filter.window = parse_window(window, "--window");
  if (vm.count("transition-hz")) o.filter.transition_hz = transition;
  if (vm.count("integration")) o.integration = parse_integration(integration);
  o.grid_points_per_rev = points;
  if (vm.count("start-s")) o.range.start_s = start_s;
  if (vm.count("end-s")) o.range.end_s = end_s;
  if (o.range.start_s && o.range.end_s && !(end_s > start_s))
    throw InputError("analyze: --end-s " + format_number(end_s) + " must be after --start-s " + format_number(start_s));
  o.guard_revolutions = guard;
  o.spectrum_segment = spectrum_segment;
  o.chunk_revolutions = chunk;
  if (jobs < 0) throw InputError("analyze: --jobs " + std::to_string(jobs) + " must be 1 or more (or 0 for every core)");
  o.threads = jobs > 0 ? static_cast<unsigned>(jobs) : std::max(1u, std::thread::hardware_concurrency());
  o.keep_revolutions = false;
  o.progress = !quiet;
  validate_options(o);

  const std::filesystem::path dir(out_dir);
  Provenance prov{inv.command_line, {recording}, csv_comments};
  RevolutionCsv per_rev(dir, prov);
  RecordingAnalysis a = analyze_recording(recording, manifest_file, o, per_revolution ? &per_rev : nullptr);
  prov.inputs = {recording, a.manifest_file, a.rig_file};
  const nlohmann::json setup =
      a.setup_check ? setup_check_json(*a.setup_check, a.manifest_file.string()) : nlohmann::json(nullptr);
  const std::vector<std::string> setup_lines = a.setup_check ? setup_check_lines(setup) : std::vector<std::string>{};
  if (strict && !setup_lines.empty()) {
    std::string msg = "analyze: --strict: the set-up check of " + recording + " found likely mistakes in its manifest: ";
    for (const std::string& line : setup_lines) msg += line + "; ";
    throw InputError(msg + "fix the keys named (docs/setup-check.md), or run without --strict");
  }
  ensure_output_dir(dir);

  // averaged.csv
  const std::size_t N = a.grid_points_per_rev;
  std::vector<std::string> cols{"crank_deg", "omega2_rad_s"};
  std::vector<const std::vector<double>*> series{&a.crank_deg, &a.crank_speed_rad_s.mean};
  for (const auto* l : {&a.coupler, &a.rocker}) {
    if (!*l) continue;
    const LinkResult& r = **l;
    const std::string i = link_index(r.link);
    cols.insert(cols.end(), {"alpha" + i + "_rad_s2", "alpha" + i + "_std_rad_s2", "omega" + i + "_rad_s",
                             "omega" + i + "_std_rad_s"});
    series.insert(series.end(), {&r.alpha_rad_s2.mean, &r.alpha_rad_s2.std, &r.omega_rad_s.mean, &r.omega_rad_s.std});
  }
  for (const auto* l : {&a.coupler, &a.rocker}) {
    if (!*l || !(*l)->normal) continue;
    const std::string i = link_index((*l)->link);
    cols.insert(cols.end(), {"omega" + i + "_sq_normal_rad2_s2", "omega" + i + "_sq_integrated_rad2_s2",
                             "omega" + i + "_abs_normal_rad_s"});
    series.insert(series.end(), {&(*l)->normal->omega_sq_rad2_s2.mean, &(*l)->normal->omega_sq_integrated_rad2_s2,
                                 &(*l)->normal->omega_abs_rad_s});
  }
  CsvWriter averaged(dir / "averaged.csv", prov.csv_comment_lines(), cols);
  std::vector<double> row(series.size());
  for (std::size_t k = 0; k < N; ++k) {
    for (std::size_t c = 0; c < series.size(); ++c) row[c] = (*series[c])[k];
    averaged.row(row);
  }

  // spectra.csv
  std::vector<std::string> scols{"frequency_Hz", "order", "filter_gain"};
  std::vector<const std::vector<double>*> sseries{&a.spectra.frequency_hz, &a.spectra.order, &a.spectra.filter_gain};
  for (const auto* l : {&a.coupler, &a.rocker})
    if (*l) {
      scols.push_back(std::string("alpha") + link_index((*l)->link) + "_amplitude_rad_s2");
      sseries.push_back(&(*l)->alpha_amplitude);
    }
  CsvWriter spectra(dir / "spectra.csv", prov.csv_comment_lines(), scols);
  if (a.spectra.segments > 0) {
    std::vector<double> srow(sseries.size());
    for (std::size_t k = 0; k < a.spectra.frequency_hz.size(); ++k) {
      for (std::size_t c = 0; c < sseries.size(); ++c) srow[c] = (*sseries[c])[k];
      spectra.row(srow);
    }
  }

  // summary.json
  const AcquisitionReport& rep = a.acquisition;
  const RecordingInfo& ri = rep.recording;
  nlohmann::json j;
  j["provenance"] = prov.to_json();
  j["recording"] = {{"file", ri.file.string()}, {"format", ri.format}, {"sample_format", ri.sample_format},
                    {"channels", ri.channels}, {"sample_rate_hz", ri.sample_rate_hz}, {"frames", ri.frames},
                    {"duration_s", ri.duration_s()}};
  j["manifest"] = {{"file", a.manifest_file.string()}, {"rig", a.rig_file.string()},
                   {"clearance_mm", units::m_to_mm(a.clearance_m)},
                   {"crank_direction", a.crank_direction > 0 ? "ccw" : "cw"}};
  j["acquisition"] = {{"revolutions_kept", rep.revolutions},
                      {"revolutions_repaired", rep.revolutions_repaired},
                      {"revolutions_clipped", rep.revolutions_clipped},
                      {"revolutions_dropped_in_gaps", rep.revolutions_in_gaps},
                      {"segments", rep.pulses.segments.size()},
                      {"range", {{"start_s", rep.range.start_s ? nlohmann::json(*rep.range.start_s) : nlohmann::json()},
                                 {"end_s", rep.range.end_s ? nlohmann::json(*rep.range.end_s) : nlohmann::json()}}},
                      {"pulses_inserted", rep.pulses.inserted_s.size()},
                      {"pulses_removed", rep.pulses.removed_s.size()},
                      {"clipping_checked", rep.clipping_checked},
                      {"speed_rpm",
                       {{"mean", rep.speed.mean_rpm}, {"std", rep.speed.std_rpm}, {"min", rep.speed.min_rpm},
                        {"max", rep.speed.max_rpm}}}};
  j["settings"] = {{"conversion", to_string(o.conversion)},
                   {"integration", to_string(o.integration)},
                   {"points_per_rev", N},
                   {"filter", filter_json(a.filter)},
                   {"kernel_taps", a.kernel_taps},
                   {"normal_filter", describe(a.normal_filter)},
                   {"guard_revolutions", o.guard_revolutions},
                   {"chunk_revolutions", a.chunk_revolutions},
                   {"spectrum", {{"segment_length", a.spectra.segment_length},
                                 {"segments", a.spectra.segments},
                                 {"resolution_hz", ri.sample_rate_hz / double(a.spectra.segment_length)},
                                 {"window", "hann"},
                                 {"overlap", 0.5}}}};
  j["revolutions"] = {{"averaged", a.revolutions}, {"clipped_left_out", a.revolutions_clipped}};
  j["crank_speed"] = {{"mean_rad_s", a.mean_crank_speed_rad_s},
                      {"mean_rpm", units::rad_s_to_rpm(std::abs(a.mean_crank_speed_rad_s))}};
  j["links"] = nlohmann::json::object();
  if (a.coupler) j["links"]["coupler"] = link_json(*a.coupler);
  if (a.rocker) j["links"]["rocker"] = link_json(*a.rocker);
  j["warnings"] = a.warnings;
  j["setup_check"] = setup;
  j["one_pulse_per_turn"] = unseen_speed_json(a);
  j["outputs"] = nlohmann::json::array({"averaged.csv", "spectra.csv", "summary.json"});
  if (per_revolution) j["outputs"].push_back("per_revolution.csv");

  AtomicOutput summary(dir / "summary.json");
  summary.stream() << json_text(j, 2) << "\n";
  averaged.commit();
  spectra.commit();
  per_rev.commit();
  summary.commit();

  for (const auto& w : a.warnings) std::cerr << "fourbar: warning: " << w << "\n";
  for (const auto& line : setup_lines) std::cerr << "fourbar: warning: " << line << "\n";
  std::cout << "analysed " << a.revolutions << " revolutions (" << units::rad_s_to_rpm(std::abs(a.mean_crank_speed_rad_s))
            << " rpm mean, " << N << " crank angles each) of " << recording << " into " << out_dir << ": alpha3 RMS "
            << a.coupler->alpha_rms_rad_s2 << " rad/s^2, omega3 RMS " << a.coupler->omega_rms_rad_s << " rad/s\n";
  // A periodic motion is worth a line: averages and scatter then describe
  // alternating patterns, not one repeated turn or irregular ones.
  for (const LinkResult* l : {a.coupler ? &*a.coupler : nullptr, a.rocker ? &*a.rocker : nullptr})
    if (l && l->alpha_repeat.period >= 2)
      std::cout << (l->link == SensedLink::coupler ? "alpha3" : "alpha4") << "'s turns repeat every " << l->alpha_repeat.period
                << " turns (turn i against turn i + " << l->alpha_repeat.period << ": " << format_number(l->alpha_repeat.ratio(), 2)
                << " of what irregular turns give, " << format_number(l->alpha_repeat.neighbours(), 2)
                << " for neighbouring turns): a periodic motion of the mechanism\n";
    else if (l && l->alpha_repeat.unconfirmed_period >= 2)
      std::cout << (l->link == SensedLink::coupler ? "alpha3" : "alpha4") << "'s turns may repeat every "
                << l->alpha_repeat.unconfirmed_period << " turns (" << format_number(l->alpha_repeat.by_lag[l->alpha_repeat.unconfirmed_period - 1], 2)
                << " of what irregular turns give), but " << l->alpha_repeat.turns << " turns are too few to tell (at least "
                << 2 * l->alpha_repeat.unconfirmed_period + 4 << ", the first and last " << kTurnRepeatEdgeTurns
                << " of each pulse-train segment not counted): record more turns\n";
  return 0;
}

}  // namespace fourbar::cli
