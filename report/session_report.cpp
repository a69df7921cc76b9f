#include "report/session_report.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <fstream>
#include <future>
#include <iostream>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "acquire/manifest.hpp"
#include "common/atomic_output.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/json_text.hpp"
#include "common/progress.hpp"
#include "common/build_id.hpp"
#include "common/version.hpp"
#include "report/analysis_cache.hpp"
#include "report/family_across_speeds.hpp"
#include "report/comparison_record.hpp"
#include "report/file_hash.hpp"
#include "report/fit_record.hpp"
#include "report/html_report.hpp"
#include "report/recording_job.hpp"
#include "report/series_files.hpp"
#include "report/session_settings.hpp"
#include "report/setup_check_record.hpp"
#include "report/verdict.hpp"
#include "report/verdict_table.hpp"

namespace fourbar {

namespace {

using nlohmann::json;

json file_entry(const std::string& role, const std::filesystem::path& p, const std::filesystem::path& base) {
  json f = {{"role", role}, {"path", std::filesystem::proximate(p, base).string()}};
  try {
    f["sha256"] = sha256_file(p);
    f["bytes"] = std::filesystem::file_size(p);
  } catch (const std::exception&) {
    f["sha256"] = nullptr;
    f["missing"] = true;
  }
  return f;
}

/// The recording, its manifest and the manifest's rig, with checksums.
json input_files(const std::filesystem::path& rec, const std::filesystem::path& base) {
  json files = json::array({file_entry("recording", rec, base)});
  const std::filesystem::path manifest = sidecar_manifest_path(rec);
  if (!std::filesystem::exists(manifest)) return files;
  files.push_back(file_entry("manifest", manifest, base));
  try {
    files.push_back(file_entry("rig", load_manifest(manifest).rig_file, base));
  } catch (const std::exception&) {
    // The manifest is broken: the recording fails with the reason.
  }
  return files;
}

}  // namespace

std::size_t default_jobs() { return std::max(1u, std::thread::hardware_concurrency()); }

namespace {

/// The record without what only the page and the series files read.
json light_record(const json& r) {
  json light = json::object();
  for (const auto& [key, value] : r.items())
    if (key != "series" && key != "spectra" && key != "impacts" && key != "grid") light[key] = value;
  if (light.contains("fitted_theory")) light["fitted_theory"].erase("series");
  return light;
}

}  // namespace

json summary_of(const json& session) {
  json s = session;
  for (json& r : s["recordings"]) r = light_record(r);
  return s;
}

namespace {

/// Nothing in the folder is passed over in silence: a manifest without its
/// recording and a file that is neither are named.
void warn_left_out(const SessionFiles& files) {
  for (const auto& m : files.orphan_manifests)
    std::cerr << "fourbar: warning: report: " << m.filename().string() << " has no recording beside it (no "
              << m.stem().string() << ".wav, .flac, .mat, .csv, ...); left out: add the recording or remove the manifest\n";
  for (const auto& f : files.other_files)
    std::cerr << "fourbar: warning: report: " << f.filename().string()
              << " is not a recording (.wav .w64 .rf64 .flac .caf .aiff .aif .mat .csv .tsv .txt) nor a manifest; left out\n";
}

/// The fit the report shows: --fit, else the one `fourbar fit` wrote into the
/// session folder (fit/fit.json), else none; its warnings said.
std::optional<ReportFit> find_fit(const ReportOptions& o, const SessionFiles& files) {
  std::optional<ReportFit> fit;
  if (o.use_fit) {
    const std::filesystem::path found = o.session_dir / "fit" / "fit.json";
    if (!o.fit_json.empty()) fit = load_report_fit(o.fit_json, files.recordings);
    else if (std::filesystem::exists(found)) fit = load_report_fit(found, files.recordings);
    if (fit)
      for (const std::string& w : fit->warnings) std::cerr << "fourbar: warning: report: " << fit->file.string() << ": " << w << "\n";
  }

  return fit;
}

/// Runs step(i) for i in [0, n) on `jobs` workers (this thread one of them),
/// a progress line when `show`; the first exception stops every worker and
/// is rethrown.
template <class Step>
void in_parallel(std::size_t n, std::size_t jobs, bool show, const Step& step) {
  std::atomic<std::size_t> next{0}, done{0};
  Progress bar("report", n, show);
  std::mutex io;
  std::exception_ptr failure;
  auto worker = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < n;) {
      try {
        step(i);
      } catch (...) {  // an output that cannot be written: stop every worker, rethrow below
        const std::lock_guard lock(io);
        if (!failure) failure = std::current_exception();
        next = n;
      }
      {
        const std::lock_guard lock(io);
        bar.set_label("report: " + std::to_string(done.fetch_add(1) + 1) + "/" + std::to_string(n) + " recordings");
        bar.update(done.load());
      }
    }
  };
  std::vector<std::jthread> pool;
  for (std::size_t t = 1; t < jobs; ++t) pool.emplace_back(worker);
  worker();
  pool.clear();  // joins
  if (failure) std::rethrow_exception(failure);
}

/// The records in the folder's order, counted into `out` (recordings, from
/// the cache, failed, with set-up findings); a failed recording, a set-up
/// finding and energy the model lacks said on stderr.
json tally_records(std::vector<json>& computed, ReportOutcome& out) {
  json records = json::array();
  for (json& r : computed) {
    ++out.recordings;
    out.from_cache += r["from_cache"].get<bool>();
    if (!is_analysed(r)) {
      ++out.failed;
      std::cerr << "fourbar: report: " << r["name"].get<std::string>() << ": " << r["error"].get<std::string>() << "\n";
    }
    if (r.contains("setup_check") && !r["setup_check"]["findings"].empty()) {
      ++out.check_setup;
      for (const std::string& line : setup_check_lines(r["setup_check"]))
        std::cerr << "fourbar: warning: report: " << r["name"].get<std::string>() << ": " << line << "\n";
    }
    if (const auto f = verdict_family(r); f && !f->unmodelled.empty())
      std::cerr << "fourbar: warning: report: " << r["name"].get<std::string>() << ": energy the model lacks: "
                << unmodelled_text(f->unmodelled.front()) << "; model agreement judged below "
                << format_number(f->judged_below_hz.value_or(f->unmodelled.front().low_hz), 4) << " Hz only\n";
    records.push_back(std::move(r));
  }

  return records;
}

/// summary.json's session record (the light records, without the fit).
json session_record(const ReportOptions& o, const SessionSettings& settings, const json& settings_json,
                    const SessionFiles& files, json records, int failed) {
  json orphans = json::array();
  for (const auto& m : files.orphan_manifests) orphans.push_back(m.filename().string());
  json others = json::array();
  for (const auto& f : files.other_files) others.push_back(f.filename().string());
  return {{"tool", "fourbar"},
          {"version", kVersion},
          {"command", o.command_line},
          {"session_dir", o.session_dir.string()},
          {"title", settings.title},
          {"notes", settings.notes},
          {"metadata",
           {{"date", settings.date}, {"operator", settings.operator_name}, {"rig_id", settings.rig_id}, {"bearing", settings.bearing}}},
          {"settings", settings_json},
          {"settings_file", settings.file.empty() ? json(nullptr) : file_entry("session", settings.file, o.session_dir)},
          {"recordings", records},
          {"recordings_failed", failed},
          {"orphan_manifests", orphans},
          {"other_files", others},
          {"severity", severity_record(records)}};
}

}  // namespace

ReportOutcome run_session_report(const ReportOptions& o) {
  const SessionSettings settings = load_session_settings(o.session_dir);
  const SessionFiles files = find_session_files(o.session_dir);
  if (files.recordings.empty())
    throw InputError(o.session_dir.string() +
                     ": no recordings (.wav .w64 .rf64 .flac .caf .aiff .aif .mat .csv .tsv .txt) in this folder");
  warn_left_out(files);
  // The fit: given, or the one `fourbar fit` wrote into the session folder.
  const std::optional<ReportFit> fit = find_fit(o, files);

  const std::filesystem::path out_dir = o.out_html.has_parent_path() ? o.out_html.parent_path() : ".";
  ensure_output_dir(out_dir);
  const std::filesystem::path cache_dir = o.cache_dir.empty() ? out_dir / ".fourbar-cache" : o.cache_dir;
  if (o.use_cache) ensure_output_dir(cache_dir);

  AnalyzeOptions analysis = settings.analysis;
  analysis.progress = false;  // one line per recording instead
  const json settings_json = settings.to_json();
  const std::size_t n = files.recordings.size();

  // One recording: its inputs, the cache key, and the record (from the cache
  // or computed). Independent of every other recording, so the workers may
  // take them in any order; the records are put back in the folder's order.
  auto record_of = [&](std::size_t i) {
    const std::filesystem::path& rec = files.recordings[i];
    const std::string name = rec.filename().string();
    const TheorySettings& theory = settings.theory_for(name);
    std::optional<TheorySettings> fitted;
    if (fit)
      if (const auto c = fit->for_recording(name)) fitted = with_fitted_contact(theory, *c);
    const json inputs = input_files(rec, o.session_dir);
    const std::string key = sha256_text(std::string(kVersion) + " " + build_id() + "\n" + json_text(inputs) + "\n" +
                                        json_text(settings_json["analysis"]) + "\n" + json_text(theory_settings_json(theory)) +
                                        (fitted ? "\nfitted " + json_text(theory_settings_json(*fitted)) : std::string()) +
                                        "\nmodel family " + json_text(settings_json["model_family"]));
    const std::filesystem::path cache_file = cache_dir / (key + ".json");
    std::optional<json> record = o.use_cache ? read_cached_record(cache_file) : std::nullopt;
    const bool cached = record.has_value();
    if (!record) {
      record = process_recording(rec, analysis, theory, fitted ? &*fitted : nullptr, settings.model_family);
      if (o.use_cache && is_analysed(*record)) write_cached_record(cache_file, *record);
    }
    json& r = *record;
    if (r.contains("acquisition")) check_band_limit(settings, name, r["acquisition"].value("sample_rate_hz", 0.0));
    r["name"] = name;
    r["files"] = inputs;
    r["cache_key"] = key;
    r["from_cache"] = cached;
    return std::move(r);
  };
  // The verdict in words of every analysed recording (never cached: a fit may
  // come later), with the fit the report shows (--fit, or SESSION_DIR/fit/fit.json).
  const std::string fit_name = fit ? std::filesystem::proximate(fit->file, o.session_dir).string() : std::string();
  // Per recording, kept to the end: the record without its bulk (summary.json
  // and the session's tables), its row of the fit section and its page part.
  // The bulk is read in the second pass below (series files, verdict, fit
  // row, page) and freed there.
  const std::string made_by = series_made_by(kVersion, o.command_line);
  ensure_output_dir(out_dir / "series");
  std::vector<json> computed(n);
  std::vector<std::optional<json>> fit_rows(n);
  std::vector<RecordingPage> pages(n);
  auto finish = [&](std::size_t i, json record) {
    write_recording_series(record, out_dir, made_by, o.csv_comments);
    if (is_analysed(record)) record["verdict"] = verdict_json(verdict_of(verdict_inputs(record, fit ? &fit->fit : nullptr, fit_name)));
    if (fit) fit_rows[i] = fit_report_row(*fit, record);
    computed[i] = light_record(record);
    pages[i] = render_recording_page(std::move(record), i);
  };
  // `jobs` is the number of cores to use: as many recordings at once (at
  // most all of them), each analysed on its share of the cores, so that
  // fewer recordings than cores (one long recording) still use them all and
  // no more than `jobs` compute at once.
  const std::size_t cores = o.jobs > 0 ? o.jobs : default_jobs();
  const std::size_t jobs = std::clamp<std::size_t>(cores, 1, n);
  analysis.threads = static_cast<unsigned>(std::max<std::size_t>(1, cores / jobs));
  // Two passes over the recordings, each on `jobs` workers: the records
  // (analysis, theory, model-family check), then, after the session's
  // cross-speed look at the model-family findings
  // (report/family_across_speeds.hpp), each record's series, verdict and
  // page. Between the two every record is held whole (its series included).
  std::vector<json> full(n);
  in_parallel(n, jobs, o.progress, [&](std::size_t i) { full[i] = record_of(i); });
  set_aside_findings_that_move_with_speed(full);
  in_parallel(n, jobs, false, [&](std::size_t i) { finish(i, std::exchange(full[i], json())); });

  ReportOutcome out;
  json records = tally_records(computed, out);

  json session = session_record(o, settings, settings_json, files, std::move(records), out.failed);
  if (fit) {
    std::vector<json> rows;
    for (auto& row : fit_rows)
      if (row) rows.push_back(std::move(*row));
    session["fit"] = fit_report_record(*fit, rows, o.session_dir);
    out.fit = fit->file;
  }

  // Outputs: each recording's series as it finished (above), then the
  // session's tables, the summary, the report last (each written whole or not
  // at all). With more than one core the page is put together on a thread of
  // its own while the tables and the summary are written (the same text either way).
  // `session` holds the light records: it is the summary as it stands.
  std::future<std::string> html;
  if (cores > 1) html = std::async(std::launch::async, [&session, &pages] { return render_html_report(session, pages); });
  write_session_series(session, out_dir, o.csv_comments);
  out.summary = out_dir / "summary.json";
  write_text_file(out.summary, json_text(session, 2) + "\n");
  write_text_file(o.out_html, html.valid() ? html.get() : render_html_report(session, pages));
  out.html = o.out_html;
  out.verdict_table = verdict_text_table(session["recordings"]);
  return out;
}

}  // namespace fourbar
