#include "report/session_report.hpp"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iostream>

#include "acquire/manifest.hpp"
#include "common/atomic_output.hpp"
#include "common/error.hpp"
#include "common/json_text.hpp"
#include "common/version.hpp"
#include "report/analysis_cache.hpp"
#include "report/comparison_record.hpp"
#include "report/file_hash.hpp"
#include "report/html_report.hpp"
#include "report/recording_job.hpp"
#include "report/series_files.hpp"
#include "report/session_settings.hpp"

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

json summary_of(const json& session) {
  json s = session;
  for (json& r : s["recordings"]) {
    r.erase("series");
    r.erase("spectra");
    r.erase("impacts");
    r.erase("grid");
  }
  return s;
}

ReportOutcome run_session_report(const ReportOptions& o) {
  const SessionSettings settings = load_session_settings(o.session_dir);
  const SessionFiles files = find_session_files(o.session_dir);
  if (files.recordings.empty())
    throw InputError(o.session_dir.string() +
                     ": no recordings (.wav .w64 .rf64 .flac .caf .aiff .aif .csv .tsv .txt) in this folder");
  const std::filesystem::path out_dir = o.out_html.has_parent_path() ? o.out_html.parent_path() : ".";
  ensure_output_dir(out_dir);
  const std::filesystem::path cache_dir = o.cache_dir.empty() ? out_dir / ".fourbar-cache" : o.cache_dir;
  if (o.use_cache) ensure_output_dir(cache_dir);
  const bool tty = o.progress && isatty(STDERR_FILENO);

  AnalyzeOptions analysis = settings.analysis;
  analysis.progress = false;  // one line per recording instead
  const json settings_json = settings.to_json();
  ReportOutcome out;
  json records = json::array();
  const std::size_t n = files.recordings.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::filesystem::path& rec = files.recordings[i];
    const std::string name = rec.filename().string();
    if (tty) std::fprintf(stderr, "\rreport: [%zu/%zu] %s ...\033[K", i + 1, n, name.c_str());
    const TheorySettings& theory = settings.theory_for(name);
    const json inputs = input_files(rec, o.session_dir);
    const std::string key = sha256_text(std::string(kVersion) + "\n" + json_text(inputs) + "\n" +
                                        json_text(settings_json["analysis"]) + "\n" + json_text(theory_settings_json(theory)));
    const std::filesystem::path cache_file = cache_dir / (key + ".json");
    std::optional<json> record = o.use_cache ? read_cached_record(cache_file) : std::nullopt;
    const bool cached = record.has_value();
    if (!record) {
      record = process_recording(rec, analysis, theory);
      if (o.use_cache && (*record)["status"] == "ok") write_cached_record(cache_file, *record);
    }
    json& r = *record;
    r["name"] = name;
    r["files"] = inputs;
    r["cache_key"] = key;
    r["from_cache"] = cached;
    ++out.recordings;
    out.from_cache += cached;
    if (r["status"] != "ok") {
      ++out.failed;
      if (tty) std::fprintf(stderr, "\r\033[K");
      std::cerr << "fourbar: report: " << name << ": " << r["error"].get<std::string>() << "\n";
    }
    records.push_back(std::move(r));
  }
  if (tty) std::fprintf(stderr, "\r\033[K");

  json orphans = json::array();
  for (const auto& m : files.orphan_manifests) orphans.push_back(m.filename().string());
  json session = {{"tool", "fourbar"},
                  {"version", kVersion},
                  {"command", o.command_line},
                  {"session_dir", o.session_dir.string()},
                  {"title", settings.title},
                  {"notes", settings.notes},
                  {"settings", settings_json},
                  {"settings_file", settings.file.empty() ? json(nullptr) : file_entry("session", settings.file, o.session_dir)},
                  {"recordings", records},
                  {"recordings_failed", out.failed},
                  {"orphan_manifests", orphans},
                  {"severity", severity_record(records)}};

  // Outputs: series first, the report last (each written whole or not at all).
  write_series_files(session, out_dir);
  out.summary = out_dir / "summary.json";
  write_text_file(out.summary, json_text(summary_of(session), 2) + "\n");
  write_text_file(o.out_html, render_html_report(session));
  out.html = o.out_html;
  return out;
}

}  // namespace fourbar
