#include "report/html_report.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/json_text.hpp"
#include "report/html_blocks.hpp"
#include "report/html_fit.hpp"
#include "report/html_recording.hpp"
#include "report/html_summary.hpp"
#include "report/html_text.hpp"
#include "report/quantity_names.hpp"

namespace fourbar {

// report/assets/*, embedded at build time (cmake/embed_text.cmake).
extern const char* const report_css;
extern const char* const report_core_js;
extern const char* const report_recording_charts_js;
extern const char* const report_session_charts_js;
extern const char* const report_views_js;
extern const char* const report_views_css;
extern const char* const report_fit_charts_js;

namespace {

using nlohmann::json;

/// The report's scripts, in order, inside one function scope: core.js defines
/// R (the data) and chart(); the others draw into the page's chart boxes.
std::string report_script() {
  std::string s = "(function(){\n'use strict';\n";
  for (const char* part : {report_core_js, report_recording_charts_js, report_session_charts_js, report_views_js, report_fit_charts_js}) s += part;
  s += "scriptsDone = true; allDrawn();\n})();\n";  // charts drawn once all scripts ran (none: 0)
  return s;
}

/// The session's record on the first page: date, operator, rig and bearing
/// (session.toml), and the rig file(s) the recordings were analysed with.
void session_record_table(std::ostringstream& h, const json& data) {
  const json md = data.value("metadata", json::object());
  auto item = [&](const char* key) { return md.value(key, std::string()); };
  std::vector<std::string> rigs;
  for (const json& r : data["recordings"]) {
    const json& rig = r.contains("analysis") ? r["analysis"].value("rig", json()) : json();
    if (rig.is_string() && !rig.get<std::string>().empty() &&
        std::find(rigs.begin(), rigs.end(), rig.get<std::string>()) == rigs.end())
      rigs.push_back(rig.get<std::string>());
  }
  std::string rig_text;
  for (const std::string& r : rigs) rig_text += (rig_text.empty() ? "" : "; ") + r;
  auto or_missing = [](const std::string& v) {
    return v.empty() ? std::string("<span class=\"note\">not given (session.toml)</span>") : html_escape(v);
  };
  h << "<table class=\"session-record\"><tr><th class=\"l\">date</th><th class=\"l\">operator</th><th class=\"l\">rig</th>"
       "<th class=\"l\">bearing</th><th class=\"l\">rig file used</th></tr><tr><td class=\"l\">"
    << or_missing(item("date")) << "</td><td class=\"l\">" << or_missing(item("operator")) << "</td><td class=\"l\">"
    << or_missing(item("rig_id")) << "</td><td class=\"l\">" << or_missing(item("bearing")) << "</td><td class=\"l\">"
    << (rig_text.empty() ? std::string("–") : html_escape(rig_text)) << "</td></tr></table>";
}

}  // namespace

RecordingPage render_recording_page(json record, std::size_t index) {
  round_numbers(record);
  std::ostringstream h;
  recording_section(h, record, index);
  return {h.str(), json_safe(json_text(record))};
}

std::string render_html_report(const json& session) {
  std::vector<RecordingPage> pages;
  const json& recs = session["recordings"];
  for (std::size_t i = 0; i < recs.size(); ++i) pages.push_back(render_recording_page(recs[i], i));
  return render_html_report(session, pages);
}

std::string render_html_report(const json& session_in, const std::vector<RecordingPage>& pages) {
  const std::string js = without_source_maps(read_text(dygraphs_dir() / "dygraph.min.js"));
  const std::string css = without_source_maps(read_text(dygraphs_dir() / "dygraph.min.css"));
  json data = session_in;
  round_numbers(data);
  data["names"] = quantity_names_json();  // the scripts label charts from the same table as the tables
  const json& recs = data["recordings"];
  if (pages.size() != recs.size()) throw std::logic_error("render_html_report: one page part per recording");
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
       "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src 'unsafe-inline'; "
       "style-src 'unsafe-inline'; img-src data:\">"
       "<meta name=\"viewport\" content=\"width=device-width,initial-scale=1\"><title>"
    << html_escape(data["title"]) << " — fourbar report</title><style>" << css << "</style><style>" << report_css << "</style><style>" << report_views_css << "</style></head><body>";
  h << "<header><h1>" << html_escape(data["title"]) << "</h1><p class=\"note\">fourbar " << html_escape(data["version"]) << " · <code>"
    << html_escape(data["command"]) << "</code> · session folder <code>" << html_escape(data["session_dir"]) << "</code></p>";
  session_record_table(h, data);
  if (!data["notes"].get<std::string>().empty()) h << "<p>" << html_escape(data["notes"]) << "</p>";
  h << "<nav><a href=\"#summary\">summary</a><a href=\"#session\">session</a>";
  if (data.contains("fit")) h << "<a href=\"#fit\">fit</a>";
  for (std::size_t i = 0; i < recs.size(); ++i) h << "<a href=\"#rec" << i << "\">" << html_escape(recs[i]["name"]) << "</a>";
  h << "<a href=\"#settings\">settings</a><a href=\"#print-short\" title=\"then print: the summary, the verdicts and one "
       "overlay per recording\">short print</a><a href=\"#\">full print</a></nav></header>";
  // The short print (report.css): with #print-short in the address the print
  // keeps the summary, the verdicts and the α3 overlay of each recording.
  h << "<span id=\"print-short\"></span><main>";
  h << "<div id=\"js-errors\" class=\"err\"><b>Script errors</b><ul></ul></div>";
  summary_section(h, data);
  severity_section(h, data);
  fit_section(h, data);

  for (const RecordingPage& p : pages) h << p.section_html;

  // session.toml's record (title, date, operator, rig, bearing, notes) and its
  // file name are in the header and the files table below: on screen they stay
  // in the list, on paper (report.css) they are not printed twice.
  json settings = data["settings"], shown_elsewhere = json::object();
  for (const char* key : {"title", "notes", "date", "operator", "rig_id", "bearing", "file"})
    if (settings.contains(key)) shown_elsewhere[key] = settings[key], settings.erase(key);
  h << "<section id=\"settings\"><h2>Settings</h2><div class=\"settings-list\"><table><tr><th class=\"l\">setting</th>"
       "<th class=\"l\">value</th></tr>";
  settings_rows(h, settings, "");
  h << "<tbody class=\"shown-above\">";
  settings_rows(h, shown_elsewhere, "");
  h << "</tbody></table></div>";
  if (!data["settings_file"].is_null()) files_table(h, json::array({data["settings_file"]}));
  h << "</section></main><footer><p class=\"note\">Self-contained: data and Debian's dygraphs "
       "(MIT licence) are inlined; nothing is fetched.</p></footer>";
  // The data as json_text(data) would write it, with each recording's text
  // (already rounded and made safe) where the recordings array stands.
  h << "<script id=\"report-data\" type=\"application/json\">{";
  bool first = true;
  for (const auto& [key, value] : data.items()) {
    h << (first ? "" : ",") << json_safe(json_text(json(key))) << ':';
    first = false;
    if (key != "recordings") {
      h << json_safe(json_text(value));
      continue;
    }
    h << '[';
    for (std::size_t i = 0; i < pages.size(); ++i) h << (i ? "," : "") << pages[i].data_json;
    h << ']';
  }
  h << "}</script>";
  h << "<script>" << script_safe(js) << "</script><script>" << report_script() << "</script></body></html>\n";
  return h.str();
}

}  // namespace fourbar
