// `fourbar fit SESSION_DIR [--out DIR]`: the bearing's contact parameters
// (restitution e, Coulomb μ) identified from a session's recordings
// (docs/fit.md).

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <thread>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "cli/command.hpp"
#include "cluster/case_queue.hpp"
#include "cluster/mpi_session.hpp"
#include "common/atomic_output.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/progress.hpp"
#include "fit/fit_json.hpp"
#include "fit/linkage_statistics.hpp"
#include "fit/session_fit.hpp"
#include "fit/simulation_cache.hpp"
#include "report/session_settings.hpp"
#include "report/verdict_family.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

namespace {

constexpr const char* kFitDetails = R"(Every recording in SESSION_DIR goes through acquire and analyze with the
session's settings (session.toml, as `fourbar report` does). For each, the
turn-to-turn statistics of the coupler and rocker alpha (spread over turns,
per-turn deviation, per-turn peak deviation, averaged deviation; each with its
standard error from the recorded turns) are compared with the same statistics
of the clearance model at the recording's measured speed and clearance. The
restitution e and the stick-slip friction coefficient mu (mu = 0: smooth) that
make them agree are searched over the box: NLopt DIRECT-L, then BOBYQA; the
interval of each parameter is where the objective stays within its noise
(docs/fit.md).

With --model elastic the fitted theory is the linkage model (sim scenes'
model = "linkage") with the rig file's [coupler.elastic] / [rocker.elastic]
links and a compliant contact at the coupler-rocker joint: e sets the
contact's damping, mu its Coulomb friction, and the model's alpha is what the
recording's tangential accelerometers read on the elastic links (rigid +
vibration), converted as analyze converts them. Same statistics; about 20x
the three-mode model's cost per turn with 2+2 modes, 100x with 4+4
(docs/fit.md "The elastic-link model").

Writes DIR/fit.json (default SESSION_DIR/fit/fit.json): parameters ->
restitution, friction_coefficient -> value, low, high, identifiable, profile;
chi2 per recording at the fit and at session.toml's prior; model;
evaluations, simulations, turns, time (simulation_cpu_seconds,
simulation_idle_wall_seconds: what the simulations would take on --jobs idle
cores).

Exit status: 0 fitted; 1 no clearance effect measurable above the noise floor
(nothing fitted) or the run failed; 2 bad arguments or session (nothing
written), e.g. --band-top-hz above a recording's Nyquist frequency, or
--model elastic on a rig file without the links' modal data.
)";

std::pair<double, double> parse_box(const std::string& option, const std::string& text) {
  const auto colon = text.find(':');
  try {
    if (colon == std::string::npos) throw std::invalid_argument("no colon");
    std::size_t used_lo = 0, used_hi = 0;
    const std::string lo_text = text.substr(0, colon), hi_text = text.substr(colon + 1);
    const double lo = std::stod(lo_text, &used_lo), hi = std::stod(hi_text, &used_hi);
    if (used_lo != lo_text.size() || used_hi != hi_text.size()) throw std::invalid_argument("trailing text");
    return {lo, hi};
  } catch (const std::exception&) {
    throw InputError("fit: --" + option + " '" + text + "': write LOW:HIGH, e.g. --" + option + " 0:1");
  }
}

/// What the simulations of each target depend on, in exact hexadecimal:
/// equal on every rank, or the ranks would simulate different things.
std::string operating_points(const std::vector<RecordingTarget>& targets) {
  std::string text;
  for (const RecordingTarget& t : targets) {
    char line[512];
    std::snprintf(line, sizeof line, "%a %a %zu %a %a | %d %a %a %a %a %d %a %a | %d %zu %zu %d %d %d %d\n",
                  t.clearance_m, t.crank_speed_rad_s, t.grid.grid_points_per_rev, t.grid.start_rad, t.grid.direction,
                  static_cast<int>(t.filter.band), t.filter.low_hz, t.filter.high_hz, t.filter.mains_hz,
                  t.filter.mains_width_hz, static_cast<int>(t.filter.window.type), t.filter.window.parameter,
                  t.filter.transition_hz, t.band_filter.has_value() ? 1 : 0, t.band_grid_points_per_rev, t.turns,
                  t.measured[0].has_value() ? 1 : 0, t.measured[1].has_value() ? 1 : 0,
                  t.measured_band[0].has_value() ? 1 : 0, t.measured_band[1].has_value() ? 1 : 0);
    text += t.name + " " + line;
    for (const auto& m : t.sensor)
      if (m) {
        std::snprintf(line, sizeof line, "sensor %a %a %a\n", m->r_m, m->h_m, m->sign);
        text += line;
      }
    if (t.band_filter) {
      std::snprintf(line, sizeof line, "band %a %a\n", t.band_filter->low_hz, t.band_filter->high_hz);
      text += line;
    }
  }
  return text;
}

/// The session's recordings as fit targets: each analysed (and, for the
/// band, analysed again up to --band-top-hz); one that cannot be analysed is
/// said and left out; a --band-top-hz above a recording's Nyquist frequency
/// and a rig that cannot carry the elastic model are bad input.
struct FitTargets {
  std::vector<RecordingTarget> targets;
  std::vector<std::vector<double>> measured_turns;  ///< α3 (else α4) per target: the model-family check
  std::size_t max_turns = 0;
};

FitTargets analyse_for_fit(const SessionFiles& files, const SessionSettings& settings, const AnalyzeOptions& analysis,
                           double band_top_hz, bool band_top_given, const FitOptions& o, bool leader, bool quiet) {
  const bool elastic = o.model.kind == FitModelKind::elastic;
  FitTargets ft;
  Progress bar("fit: analysing", files.recordings.size(), !quiet);
  for (const auto& rec : files.recordings) {
    auto manifest = rec;
    manifest.replace_extension(".toml");
    bar.set_label("fit: analysing " + rec.filename().string());
    bar.update(static_cast<std::uint64_t>(&rec - files.recordings.data()));
    double sample_rate_hz = 0;
    std::optional<RecordingTarget> target;
    try {
      const RecordingAnalysis a = analyze_recording(rec, manifest, analysis);
      sample_rate_hz = a.acquisition.recording.sample_rate_hz;
      if (!(band_top_given && band_top_hz > 0.5 * sample_rate_hz)) {  // else bad input, said below
        std::optional<RecordingAnalysis> band;
        if (const auto bo = band_analysis_options(a, analysis, band_top_hz)) band = analyze_recording(rec, manifest, *bo);
        target = make_recording_target(a, band ? &*band : nullptr, rec.filename().string());
        ft.measured_turns.push_back(a.coupler ? a.coupler->alpha_grid : a.rocker ? a.rocker->alpha_grid : std::vector<double>{});
      }
    } catch (const std::exception& e) {
      if (leader) std::cerr << "fourbar: " << rec.string() << ": " << e.what() << " (left out of the fit)\n";
    }
    check_band_limit(settings, rec.filename().string(), sample_rate_hz);
    if (band_top_given && sample_rate_hz > 0 && band_top_hz > 0.5 * sample_rate_hz)
      throw InputError("fit: --band-top-hz " + format_number(band_top_hz, 6) + " is above the Nyquist frequency of " +
                       rec.string() + " (sample rate " + format_number(sample_rate_hz, 6) + " Hz, Nyquist " +
                       format_number(0.5 * sample_rate_hz, 6) +
                       " Hz): the recording holds nothing there. Give --band-top-hz at most " +
                       format_number(0.5 * sample_rate_hz, 6) + " (the band stops at 0.3x the sample rate, " +
                       format_number(kBandTopPerSampleRate * sample_rate_hz, 6) +
                       " Hz, anyway), or leave it out (default 3840)");
    if (!target) continue;
    if (elastic)  // the rig cannot carry the elastic model: bad input, the whole fit stops
      check_elastic_fit_rig(*target->rig, o.model, target->clearance_m);
    // The elastic model, and the link-vibration check of a rig with modes, read the recording's sensors.
    if (elastic || target->rig->coupler_elastic || target->rig->rocker_elastic) attach_sensors(*target, manifest);
    ft.targets.push_back(std::move(*target));
    ft.max_turns = std::max(ft.max_turns, ft.targets.back().turns);
  }
  bar.finish();
  return ft;
}

/// The model-family check at the fitted parameters (compare/model_family.hpp)
/// on the recordings `which`: a recording with energy the model lacks rejects
/// the family.
void check_fit_family(FitResult& f, const std::vector<std::size_t>& which, const std::vector<RecordingTarget>& targets,
                      const std::vector<std::vector<double>>& measured_turns, const FitOptions& o,
                      const ModelFamilySettings& family) {
  const bool elastic = o.model.kind == FitModelKind::elastic;
  std::string vibration_not_checked;
  for (std::size_t r : which) {
    if (measured_turns[r].empty()) continue;
    const int kept = std::max(20, static_cast<int>(targets[r].turns));
    // Against the model fitted: with --model elastic its ringing links are in the theory.
    const ModelFamilyCheck c =
        elastic ? elastic_family_check_at(targets[r], measured_turns[r], f.best, o.warmup_turns, kept, o.tolerance,
                                          o.model, family)
                : family_check_at(targets[r], measured_turns[r], f.best, o.warmup_turns, kept, family,
                                  &vibration_not_checked);
    if (c.checked) {
      f.model_family.spectral_model = std::string(name_of(o.model.kind));
      ++f.model_family.spectral_recordings;
    }
    if (!c.unmodelled.empty())
      reject_model_family(f, targets[r].name + " holds energy the model lacks: " + unmodelled_text(c.unmodelled.front()), o);
  }
  // The rig gives the links' modes but their vibration could not be checked:
  // the resonance test alone does not see an elastic link's broad ringing.
  if (!vibration_not_checked.empty())
    f.notes.push_back("the links' vibration was not checked against the rig file's modal data (the spectral check "
                      "finds narrow resonances, not an elastic link's broad ringing): " + vibration_not_checked);
}

/// The fit's summary on stdout: the model family's verdict, the parameters
/// with their intervals, χ² against the prior's, the magnifications, notes.
void print_fit(const std::string& label, const FitResult& f) {
  if (f.model_family.rejected) {
    std::cout << "model family rejected: " << f.model_family.reasons.front()
              << (f.model_family.reasons.size() > 1 ? " (and " + std::to_string(f.model_family.reasons.size() - 1) + " more reasons in fit.json)" : std::string())
              << "; no parameter is identifiable, the values are effective ones and the intervals are widened by the model error ("
              << format_number(f.model_family.error_scale, 3) << "x)\n";
  }
  std::cout << label << ": ";
  for (const ParameterEstimate& p : f.parameters)
    std::cout << p.name << " = " << format_number(p.value, 3) << " [" << format_number(p.low, 3) << ", "
              << format_number(p.high, 3) << "]" << (p.lower_bound_only ? " (not identifiable: only the lower bound)" : p.identifiable ? "" : " (not identifiable)") << "  ";
  std::cout << "chi2/term " << format_number(f.chi2 / std::max(1, f.terms), 3) << " (prior "
            << format_number(f.chi2_prior / std::max(1, f.terms), 3) << "), " << f.simulations << " simulations, "
            << format_number(f.seconds, 3) << " s\n";
  // The prior inside the fit's own noise: χ² at the prior less than Δ (the
  // 95 % threshold that bounds the intervals) above the fit's.
  if (f.interval_delta > 0 && f.chi2_prior - f.chi2 < f.interval_delta)
    std::cout << "  the fitted chi2 is within noise of the prior's (prior - fit = " << format_number(f.chi2_prior - f.chi2, 3)
              << " < " << format_number(f.interval_delta, 3)
              << ", the 95 % threshold of the intervals): the prior fits these recordings as well; a lower or higher "
                 "chi2 or RMS after the fit is noise, not a better or worse model\n";
  for (const ParameterEstimate& p : f.parameters)
    if (!p.identifiable) std::cout << "  " << parameter_advice(p) << "\n";
  // a with its standard error: from a few dozen turns it is noise-limited.
  for (std::size_t r = 0; r < f.recordings.size() && r < f.magnification_fitted.size(); ++r) {
    const auto &af = f.magnification_fitted[r], &ap = f.magnification_prior[r];
    if (!af) continue;
    std::cout << "  " << f.recordings[r].name << ": magnification a = " << format_number(af->value, 3) << " ± "
              << format_number(af->standard_error, 2);
    if (ap) std::cout << " (prior " << format_number(ap->value, 3) << " ± " << format_number(ap->standard_error, 2) << ")";
    std::cout << "\n";
  }
  for (const std::string& n : f.notes) std::cout << "  note: " << n << "\n";
}

/// fit.json with the model family's verdict first: whoever reads the
/// parameter block reads first whether its values measure anything.
void write_fit_json(const nlohmann::json& result, const std::filesystem::path& file) {
  nlohmann::ordered_json ordered;
  if (result.contains("model_family")) ordered["model_family"] = nlohmann::ordered_json::parse(result["model_family"].dump());
  for (const auto& [key, value] : result.items())
    if (key != "model_family") ordered[key] = nlohmann::ordered_json::parse(value.dump());
  write_text_file(file, ordered.dump(2) + "\n");
}

}  // namespace

int run_fit(const Invocation& inv) {
#ifdef __GLIBC__
  // Every simulation allocates and frees buffers of tens of MB (its samples,
  // the band's FFT): above glibc's mmap threshold (at most 32 MB) each came
  // fresh from the kernel and was faulted in page by page: 3.5 million page
  // faults, 30 of 156 s CPU in the kernel for the sample session (docs/fit.md
  // "Search and cost"). Kept in the heap they are reused.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
  std::string dir, out, restitution_box, friction_box, model_name = "three-mode";
  bool per_recording = false, smooth_only = false, quiet = false;
  int jobs = 0, turns = 0, warmup = 20;
  double band_top_hz = kBandTopHz;
  FitOptions o;
  po::options_description opts("options");
  opts.add_options()("session", po::value(&dir)->required(), "session folder with the recordings and manifests")(
      "out,o", po::value(&out), "output folder for fit.json (default SESSION_DIR/fit)")(
      "per-recording", po::bool_switch(&per_recording), "fit each recording alone (shows whether e, mu are shared)")(
      "smooth", po::bool_switch(&smooth_only), "fit e only, with the smooth contact law (no friction)")(
      "restitution", po::value(&restitution_box), "box for e, LOW:HIGH (default 0:1)")(
      "friction", po::value(&friction_box), "box for mu, LOW:HIGH (default 0:0.5)")(
      "turns", po::value(&turns), "simulated turns per simulation kept (default: 2x the measured turns, at least 40)")(
      "warmup", po::value(&warmup), "simulated turns discarded before them (default 20)")(
      "band-top-hz", po::value(&band_top_hz),
      "upper edge of the band above the averaging filter whose energy carries e (default 3840: where rigid and "
      "0.1-0.3 ms compliant impacts agree, docs/fit.md \"Band top\"; the band stops at 0.3x the sample rate; "
      "a value above a recording's Nyquist frequency, half its sample rate, is bad input: exit 2)")(
      "band-offset-sigma", po::value(&o.modelling_offset_sigma.band),
      "width (log) of the shared offset the model's band energy may carry from modelling choices, profiled out "
      "(default 0.26; 0: none; docs/fit.md \"Modelling choices\")")(
      "spread-offset-sigma", po::value(&o.modelling_offset_sigma.statistic[index_of(ResponseStatistic::spread)]),
      "the same for the spread over turns (default 0.022)")(
      "model", po::value(&model_name),
      "the theory fitted: three-mode (default: the rigid clearance model) or elastic (the linkage model with the "
      "rig's [coupler.elastic]/[rocker.elastic] links and a compliant contact; the accelerometers read rigid + "
      "elastic motion; docs/fit.md \"The elastic-link model\")")(
      "elastic-modes", po::value(&o.model.elastic_modes),
      "with --model elastic: bending modes per elastic link, 1-4 (default: the rig table's modes; the cost grows "
      "about 8x from 2 to 4)")(
      "contact-stiffness", po::value(&o.model.contact_stiffness_N_per_m_n),
      "with --model elastic: the compliant contact's K in N/m^1.5 (default: from the rig's bearing keys)")(
      "orbit-scan", po::bool_switch(&o.orbit_scan),
      "when the family is rejected and a recording's turns repeat every few turns while the model's do not: look "
      "for a stable motion of that period in the model at every 0.05 of the box's e, not only at the best point "
      "(10-30 s a point and recording, 21 points a contact law with the default box; docs/fit.md \"A periodic recording\")")(
      "jobs,j", po::value(&jobs), "simulations (and analysis chunks) at once (default: every core; under MPI one per rank)");
  add_quiet_option(opts, quiet);
  po::positional_options_description pos;
  pos.add("session", 1);
  po::variables_map vm;
  if (!parse_arguments("fit", "SESSION_DIR [--out DIR] [--per-recording] [--smooth] [--restitution LO:HI] [--friction LO:HI]",
                       kFitDetails, opts, pos, inv, vm))
    return 0;

  if (!restitution_box.empty()) std::tie(o.box.restitution_low, o.box.restitution_high) = parse_box("restitution", restitution_box);
  if (!friction_box.empty()) std::tie(o.box.friction_low, o.box.friction_high) = parse_box("friction", friction_box);
  o.fit_friction = !smooth_only;
  o.warmup_turns = warmup;
  if (jobs < 0) throw InputError("fit: --jobs " + std::to_string(jobs) + " must be 1 or more (or 0 for every core)");
  o.threads = jobs > 0 ? static_cast<unsigned>(jobs) : std::max(1u, std::thread::hardware_concurrency());
  o.simulated_turns = turns > 0 ? turns : 40;  // checked again below once the measured turns are known
  if (turns < 0) throw InputError("fit: --turns " + std::to_string(turns) + " must be 8 or more");
  validate_fit_options(o);
  if (!(band_top_hz > 0))
    throw InputError("fit: --band-top-hz " + format_number(band_top_hz, 6) +
                     " must be above 0 (e.g. --band-top-hz 3840; at most 0.3x the sample rate is used)");
  const bool band_top_given = vm.count("band-top-hz") > 0;
  o.model.kind = fit_model_kind(model_name);
  const bool elastic = o.model.kind == FitModelKind::elastic;
  if (!elastic && (vm.count("elastic-modes") || vm.count("contact-stiffness")))
    throw InputError(std::string("fit: --") + (vm.count("elastic-modes") ? "elastic-modes" : "contact-stiffness") +
                     " belongs to the elastic-link model; add --model elastic or leave it out");
  if (elastic && o.orbit_scan)
    throw InputError("fit: --orbit-scan searches the three-mode model's turn map; leave out --model elastic or "
                     "--orbit-scan");
  if (vm.count("elastic-modes") && !(o.model.elastic_modes >= 1 && o.model.elastic_modes <= 4))
    throw InputError("fit: --elastic-modes " + std::to_string(o.model.elastic_modes) + " must be 1 to 4");
  if (vm.count("contact-stiffness") && !(o.model.contact_stiffness_N_per_m_n > 0))
    throw InputError("fit: --contact-stiffness " + format_number(o.model.contact_stiffness_N_per_m_n, 6) +
                     " must be above 0 (N/m^1.5, e.g. 1e10)");
  // The linkage model's tolerance is on its scaled state (docs/linkage-model.md);
  // 1e-6 is where bench/elastic_linkage_work_precision puts its cost at
  // 0.06 s/turn (2+2 modes). The compliant contact needs e > 0 (e = 0: infinite damping).
  if (elastic) {
    o.tolerance = 1e-6;
    if (restitution_box.empty()) o.box.restitution_low = 0.05;
  }

  const std::filesystem::path session = dir;
  const SessionSettings settings = load_session_settings(session);
  // fit varies the three-mode model's e and μ; a compliant theory would be fitted as another model.
  bool compliant = settings.theory.model == ClearanceKind::compliant;
  for (const auto& [name, t] : settings.theory_by_recording) compliant = compliant || t.model == ClearanceKind::compliant;
  if (compliant)
    throw InputError("fit: " + settings.file.string() + ": [theory] model = \"compliant\": fourbar fit fits the "
                     "three-mode model's restitution and friction only (the compliant contact is not fitted); "
                     "remove model (and the compliant keys) from session.toml to fit, or use fourbar report");
  const SessionFiles files = find_session_files(session);
  if (files.recordings.empty())
    throw InputError("fit: " + session.string() + ": no recordings (.wav .flac .csv ...) in the folder");
  // Under MPI every rank analyses the recordings (each needs the targets to
  // simulate them), each with one thread (a rank per core); only rank 0
  // talks, searches and writes. The ranks check that they got the same
  // operating points before any simulation relies on it.
  const MpiSession& mpi = MpiSession::get();
  if (!mpi.leader()) quiet = true;
  if (mpi.distributed()) o.threads = static_cast<unsigned>(mpi.size());  // simulations at once
  AnalyzeOptions analysis = settings.analysis;
  analysis.keep_revolutions = true;
  analysis.progress = false;
  analysis.threads = mpi.distributed() ? 1 : o.threads;  // (before the search: the cores are free)
  FitTargets ft = analyse_for_fit(files, settings, analysis, band_top_hz, band_top_given, o, mpi.leader(), quiet);
  std::vector<RecordingTarget>& targets = ft.targets;
  const std::vector<std::vector<double>>& measured_turns = ft.measured_turns;
  const std::size_t max_turns = ft.max_turns;
  if (targets.empty()) throw RunError("fit: no recording of " + session.string() + " could be analysed");
  if (!mpi.same_on_every_rank(operating_points(targets)))
    throw RunError("fit: the MPI ranks analysed the recordings of " + session.string() +
                   " to different operating points (different hardware or fourbar builds on the nodes?); run every "
                   "rank with the same build on the same kind of node");
  if (turns == 0) o.simulated_turns = std::max<int>(40, static_cast<int>(2 * max_turns));

  const double effect = clearance_effect_ratio(targets);
  if (effect < kEffectRatio)
    throw RunError("fit: " + session.string() +
                   ": no clearance effect measurable above the noise floor (the turn-to-turn variation of alpha "
                   "stands at most " + format_number(effect, 2) +
                   "x above the sensor-noise floor; impacts need " + format_number(kEffectRatio, 2) +
                   "x): nothing to fit. Record at a larger clearance or higher speed, or check the sensors");

  if (!mpi.leader()) {  // the simulations rank 0 hands out, until its search is done
    serve_described_cases(
        [&](const std::string& description) { return SimulationCache::simulate_described(targets, description); });
    return 0;
  }

  const TheorySettings& t = settings.theory;
  const ContactParameters prior{t.restitution, t.contact, t.friction_coefficient};
  // Progress through the simulations (the search's, the profile's, the runs for a):
  // the total is the usual count, the label the count so far.
  const std::size_t expected = expected_simulations(per_recording ? 1 : targets.size(), o) * (per_recording ? targets.size() : 1);
  Progress sims("fit: simulations", expected, !quiet);
  std::size_t simulated = 0;
  o.on_simulation = [&] {
    ++simulated;
    sims.set_label("fit: " + std::to_string(simulated) + " simulations (about " + std::to_string(expected) + ")");
    sims.update(std::min(simulated, expected > 0 ? expected - 1 : 0));
  };
  nlohmann::json result;
  if (per_recording) {
    result["per_recording"] = nlohmann::json::array();
    for (const RecordingTarget& tg : targets) {
      const std::vector<RecordingTarget> one{tg};
      FitResult f = fit_contact_parameters(one, prior, o);
      check_fit_family(f, {static_cast<std::size_t>(&tg - targets.data())}, targets, measured_turns, o,
                       settings.model_family);
      print_fit(tg.name, f);
      nlohmann::json j = fit_to_json(f, one, prior, o);
      j["file"] = tg.name;
      if (f.model_family.rejected) {
        if (!result.contains("model_family")) result["model_family"] = {{"verdict", "rejected"}, {"reasons", nlohmann::json::array()}};
        for (const std::string& why : f.model_family.reasons) result["model_family"]["reasons"].push_back(tg.name + ": " + why);
      }
      result["per_recording"].push_back(j);
    }
  } else {
    FitResult f = fit_contact_parameters(targets, prior, o);
    sims.finish();
    std::vector<std::size_t> all(targets.size());
    for (std::size_t r = 0; r < all.size(); ++r) all[r] = r;
    check_fit_family(f, all, targets, measured_turns, o, settings.model_family);
    print_fit("session", f);
    result = fit_to_json(f, targets, prior, o);
  }
  sims.finish();
  end_described_cases();  // the other ranks stop serving
  result["mpi_ranks"] = mpi.size();
  result["session"] = session.string();
  result["clearance_effect_ratio"] = effect;
  result["command_line"] = inv.command_line;
  const std::filesystem::path out_dir = out.empty() ? session / "fit" : std::filesystem::path(out);
  ensure_output_dir(out_dir);
  write_fit_json(result, out_dir / "fit.json");
  std::cout << "wrote " << (out_dir / "fit.json").string() << "\n";
  return 0;
}

}  // namespace fourbar::cli
