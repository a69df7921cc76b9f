// `fourbar report SESSION_DIR [--out report.html]`: the main job — every
// recording of a session folder through acquire, analyze, the matched theory
// and the comparison, into one self-contained HTML report.

#include <iostream>

#include "cli/command.hpp"
#include "common/error.hpp"
#include "report/session_report.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

namespace {

constexpr const char* kReportDetails = R"(Every recording in SESSION_DIR (top level: .wav .w64 .rf64 .flac .caf .aiff
.aif .mat .csv .tsv .txt, except *.truth.csv), each with its manifest REC.toml
beside it, goes through acquire and analyze; the clearance model and the
nominal mechanism are simulated at its measured mean crank speed and its
manifest's clearance (e, mu from session.toml, default e = 0.5 smooth), on the
same crank-angle grid, and compared (docs/report.md).

Writes OUT (default SESSION_DIR/report/report.html), and beside it
summary.json, summary.csv (one row per recording: the verdict, the a it judges
by with its standard error and kind, then each verdict part's level first),
session_severity.csv (with each recording's status) and
series/<recording>*.csv (their provenance is in summary.json). Results are
cached in <out dir>/.fourbar-cache by the SHA-256 of the inputs and settings:
a second run with unchanged inputs does not recompute. Any other file in
the folder, and a manifest without its recording, is named in a warning.

Optional SESSION_DIR/session.toml (strict; unknown keys are errors):
  title, notes; date, operator, rig_id, bearing (text, on the first page);
  [analysis] grid_points_per_rev, low_hz, high_hz, mains_hz, mains_width_hz,
             window ("kaiser:8"), transition_hz, guard_revolutions,
             integration ("spectral" | "closed_trapezoid" | "trapezoid");
  [theory]   model ("three-mode" | "compliant"), restitution,
             contact ("smooth" | "rough" | "stick-slip"; three-mode),
             friction_coefficient, warmup_revolutions (20),
             averaged_revolutions (20), tolerance (1e-8), max_order (50);
             with model = "compliant" instead of contact the scene's compliant
             keys: damping, contact_stiffness_N_per_m_n (absent: from the
             recording's rig bearing), contact_exponent,
             friction_stick_speed_mm_s, friction_slip_speed_mm_s,
             damping_floor_speed_mm_s (README "Compliant contact");
  [model_family] band_width_hz (20), max_frequency_hz (default: the analysis
             filter's upper corner; above a recording's Nyquist frequency:
             exit 2): the check for energy the model lacks (link vibration,
             sensor resonance; docs/verdict.md "Model family");
  [[recording]] file = "REC.flac" and any [theory] key for that recording.

With a `fourbar fit` result (--fit FIT.json, or SESSION_DIR/fit/fit.json,
where `fourbar fit` writes by default, when it exists; --no-fit leaves it
out), each recording's theory is simulated a second time at the fitted e, mu
and the report gets the section "Fitted bearing parameters": the fitted
values with their intervals, measured vs the model at the prior and at the
fitted values (a, RMS difference, correlation: before -> after) and the
objective's profiles (docs/fit.md).

A recording whose set-up check (docs/setup-check.md) finds a likely
manifest mistake gets status "check set-up" instead of "ok": its findings are
warned on stderr and shown at the top of the report and in summary.json.

Exit status: 0 every recording analysed; 1 the report was written but some
recordings failed (each named on stderr and in the report), or the run
failed; 2 bad arguments, session.toml or session folder (nothing written),
or with --strict a recording to check set-up (the report is written).
)";

}  // namespace

int run_report(const Invocation& inv) {
  std::string dir, out, cache, fit;
  bool no_cache = false, quiet = false, strict = false, csv_comments = false, no_fit = false;
  int jobs = 0;
  po::options_description opts("options");
  opts.add_options()("session", po::value(&dir)->required(), "session folder with the recordings and manifests")(
      "out,o", po::value(&out), "report to write (default SESSION_DIR/report/report.html)")(
      "cache", po::value(&cache), "cache folder (default: .fourbar-cache beside the report)")(
      "no-cache", po::bool_switch(&no_cache), "recompute everything; read and write no cache")(
      "jobs,j", po::value(&jobs), "cores to use (default: every core): that many recordings at once, or fewer "
                                  "recordings each on its share of the cores; the outputs do not depend on it")(
      "fit", po::value(&fit), "fit.json of `fourbar fit` (default SESSION_DIR/fit/fit.json when it exists)")(
      "no-fit", po::bool_switch(&no_fit), "no fitted theory, even when SESSION_DIR/fit/fit.json exists")(
      "strict", po::bool_switch(&strict), "a likely set-up mistake in a recording is an error (exit 2; the report is written)");
  add_csv_comments_option(opts, csv_comments);
  add_quiet_option(opts, quiet);
  po::positional_options_description pos;
  pos.add("session", 1);
  po::variables_map vm;
  if (!parse_arguments("report", "SESSION_DIR [--out report.html] [--cache DIR] [--no-cache] [--jobs N] [--fit FIT.json | --no-fit] [--strict]", kReportDetails, opts, pos, inv,
                       vm))
    return 0;
  ReportOptions o;
  o.session_dir = dir;
  o.out_html = out.empty() ? std::filesystem::path(dir) / "report" / "report.html" : std::filesystem::path(out);
  o.cache_dir = cache;
  o.use_cache = !no_cache;
  o.progress = !quiet;
  if (jobs < 0) throw InputError("report: --jobs " + std::to_string(jobs) + " must be 1 or more (or 0 for every core)");
  o.jobs = static_cast<std::size_t>(jobs);
  o.command_line = inv.command_line;
  o.csv_comments = csv_comments;
  if (!fit.empty() && no_fit) throw InputError("report: --fit and --no-fit exclude each other; give one");
  o.fit_json = fit;
  o.use_fit = !no_fit;
  const ReportOutcome r = run_session_report(o);
  std::cout << "wrote " << r.html.string() << " and " << r.summary.string() << ": " << r.recordings << " recordings, "
            << r.failed << " failed, " << r.from_cache << " from the cache";
  if (r.check_setup > 0) std::cout << ", " << r.check_setup << " to check set-up";
  if (!r.fit.empty()) std::cout << "; fitted theory from " << r.fit.string();
  std::cout << "\n" << r.verdict_table;
  if (strict && r.check_setup > 0)
    throw InputError("report: --strict: the set-up check found likely manifest mistakes in " +
                     std::to_string(r.check_setup) + (r.check_setup == 1 ? " recording" : " recordings") + " (named above and at the top of " + r.html.string() +
                     "); fix the keys named (docs/setup-check.md), or run without --strict");
  return r.failed > 0 ? 1 : 0;
}

}  // namespace fourbar::cli
