#pragma once
// The session report as one self-contained HTML file: opens offline and makes
// no network request. The data (the session record, numbers rounded to six
// significant digits) and Debian's dygraphs (libjs-dygraphs: JavaScript and
// CSS) are inlined; the polar plots of impact directions are inline SVG.
//
// Charts per recording: measured vs clearance model vs nominal (and the
// modified analytical response, thesis Fig. 8.4) for α3, ω3, α4, ω4, with the
// spread as a band, zoom (drag; range selector; double-click resets) and
// series toggles; deviation amplitudes per crank order and the magnification
// factor per order; the measured α spectrum; impact directions on pin and
// bushing (thesis Figs 8.11/8.12). Session charts: severity against
// clearance and against crank speed (Figs 7.10/7.11). Tables: metrics,
// operating points, every setting, every input file with its SHA-256.
// Print CSS puts each recording on its own page without the controls.
//
// Layout: html_summary (session sections), html_recording (one recording),
// html_blocks (chart boxes, polar SVG, tables), html_text (escaping and
// formatting); style and scripts live in report/assets/ and are embedded at
// build time.
//
// When every chart has drawn, the page sets data-charts-drawn (count) on
// <body>; script errors are counted in data-js-errors and listed on the page
// (the headless-browser test reads both).

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fourbar {

/// One recording's share of the page, made apart from the rest (by the
/// report's worker that made the recording, while others still compute):
/// its section and its entry of the page's data, numbers rounded.
struct RecordingPage {
  std::string section_html;
  std::string data_json;  ///< the record as JSON text, safe inside <script>
};

/// `record` (the whole record, series included) as the `index`-th recording
/// of the page. Takes the record by value: it is rounded in place.
RecordingPage render_recording_page(nlohmann::json record, std::size_t index);

/// The HTML text. RunError when dygraphs is not installed (names the package).
std::string render_html_report(const nlohmann::json& session);

/// The same text from the session record without its recordings' bulk
/// (`session["recordings"]` may hold the light records of summary_of: the
/// page reads only their names, verdicts and tables) and each recording's
/// page part in the same order: render_html_report(s) ==
/// render_html_report(light s, render_recording_page of each recording).
std::string render_html_report(const nlohmann::json& session, const std::vector<RecordingPage>& recordings);

}  // namespace fourbar
