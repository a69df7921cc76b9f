#include "report/html_report.hpp"
#include "report/setup_check_record.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "common/error.hpp"
#include "common/json_text.hpp"

#ifndef FOURBAR_DYGRAPHS_DIR
#define FOURBAR_DYGRAPHS_DIR "/usr/share/javascript/dygraphs"
#endif

namespace fourbar {

namespace {

using nlohmann::json;

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in)
    throw RunError(p.string() + ": cannot be read; the report inlines Debian's dygraphs: install libjs-dygraphs "
                                "(scripts/install-deps.sh) or set FOURBAR_DYGRAPHS_DIR");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Drops source-map comments (they would make developer tools fetch a file).
std::string without_source_maps(std::string text) {
  for (const char* marker : {"//# sourceMappingURL=", "/*# sourceMappingURL="}) {
    for (auto p = text.find(marker); p != std::string::npos; p = text.find(marker)) {
      auto e = text.find('\n', p);
      if (std::string(marker).starts_with("/*")) e = text.find("*/", p) + 2;
      text.erase(p, e == std::string::npos ? std::string::npos : e - p);
    }
  }
  return text;
}

/// JavaScript inside <script>: only "</script" (any case) ends the element;
/// "<\/script" means the same in JavaScript strings and regular expressions.
std::string script_safe(std::string text) {
  for (std::size_t p = 0; (p = text.find("</", p)) != std::string::npos; ++p) {
    std::string ahead = text.substr(p, 8);
    for (char& c : ahead) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ahead == "</script") text.insert(p + 1, "\\");
  }
  return text;
}

/// JSON inside <script>: every "<" (only in strings) as \u003c.
std::string json_safe(const std::string& text) {
  std::string o;
  o.reserve(text.size());
  for (char c : text) {
    if (c == '<') o += "\\u003c";
    else o += c;
  }
  return o;
}

std::string esc(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

/// Six significant digits: the embedded data stays small, the plots identical.
void round_numbers(json& j) {
  if (j.is_number_float()) {
    const double v = j.get<double>();
    if (!std::isfinite(v)) {
      j = nullptr;
      return;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    j = std::strtod(buf, nullptr);
  } else if (j.is_structured()) {
    for (auto& e : j) round_numbers(e);
  }
}

/// j[k1][k2]…, or null when any step is missing.
const json& at(const json& j, std::initializer_list<const char*> keys) {
  static const json null_value;
  const json* p = &j;
  for (const char* k : keys) {
    if (!p->is_object() || !p->contains(k)) return null_value;
    p = &(*p)[k];
  }
  return *p;
}

std::string fmt(const json& v, const char* f = "%.4g") {
  if (v.is_null()) return "–";
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_string()) return esc(v.get<std::string>());
  if (!v.is_number()) return esc(json_text(v));
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v.get<double>());
  return buf;
}

/// Inline SVG: impact directions on a part, dots at the contact angle, radius by impulse.
std::string polar_svg(const json& impacts, const char* key, const std::string& title) {
  const double size = 260, c = size / 2, r0 = 40, r1 = 110;
  double fmax = 0;
  for (const json& i : impacts) fmax = std::max(fmax, i["normal_impulse_Ns"].get<double>());
  std::ostringstream s;
  s << "<figure class=\"polar\"><svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size << "\" height=\"" << size
    << "\" viewBox=\"0 0 " << size << ' ' << size << "\" role=\"img\" aria-label=\"" << esc(title) << "\">"
    << "<circle cx=\"" << c << "\" cy=\"" << c << "\" r=\"" << r1 << "\" class=\"ring\"/>"
    << "<circle cx=\"" << c << "\" cy=\"" << c << "\" r=\"" << r0 << "\" class=\"ring\"/>"
    << "<line x1=\"" << c << "\" y1=\"" << c << "\" x2=\"" << c + r1 + 8 << "\" y2=\"" << c << "\" class=\"axis\"/>"
    << "<text x=\"" << c + r1 - 6 << "\" y=\"" << c - 4 << "\" class=\"lbl\">0°</text>"
    << "<text x=\"" << c - 8 << "\" y=\"" << c - r1 - 4 << "\" class=\"lbl\">90°</text>";
  std::size_t dots = 0;
  for (const json& i : impacts) {
    const double a = i[key].get<double>() * M_PI / 180.0;
    const double f = fmax > 0 ? i["normal_impulse_Ns"].get<double>() / fmax : 0;
    const double rr = r0 + (r1 - r0) * std::sqrt(f);
    char buf[160];
    std::snprintf(buf, sizeof buf, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"2.2\" class=\"dot\"/>", c + rr * std::cos(a),
                  c - rr * std::sin(a));
    s << buf;
    ++dots;
  }
  s << "</svg><figcaption>" << esc(title) << " — " << dots << " impacts; distance from the inner ring ∝ √F (largest "
    << fmt(json(fmax), "%.3g") << " N·s)</figcaption></figure>";
  return s.str();
}

const char* kCss = R"CSS(
body{font:14px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,sans-serif;margin:0;color:#1c2430;background:#fafbfc}
header,main,footer{max-width:1180px;margin:0 auto;padding:0 18px}
header{padding-top:16px}
h1{font-size:24px;margin:8px 0}h2{font-size:19px;margin:28px 0 8px;border-bottom:2px solid #d8dee6;padding-bottom:4px}
h3{font-size:15px;margin:18px 0 6px}
table{border-collapse:collapse;margin:6px 0 12px;font-size:13px;background:#fff}
th,td{border:1px solid #d8dee6;padding:3px 7px;text-align:right;vertical-align:top}
th{background:#eef2f6}td.l,th.l{text-align:left}
.ok{color:#17683a;font-weight:600}.failed{color:#b3261e;font-weight:600}
.err{background:#fdecea;border:1px solid #f1aeb5;padding:8px 12px;border-radius:4px}
.warn{background:#fff8e1;border:1px solid #f4d27a;padding:6px 12px;border-radius:4px}
.chart-box{background:#fff;border:1px solid #d8dee6;border-radius:4px;padding:8px;margin:8px 0}
.chart{width:100%;height:300px}.chart.small{height:240px}
.legend{font-size:12px;min-height:1.3em}
.controls label{margin-right:14px;font-size:12px;white-space:nowrap}
.grid2{display:grid;grid-template-columns:1fr 1fr;gap:10px}
.polar{display:inline-block;margin:4px 18px 4px 0;font-size:12px;max-width:280px}
.polar .ring{fill:none;stroke:#9aa7b4;stroke-width:1}.polar .axis{stroke:#9aa7b4}
.polar .dot{fill:#c0392b;fill-opacity:.55}.polar .lbl{font-size:10px;fill:#5b6875}
.hash{font-family:ui-monospace,monospace;font-size:11px;word-break:break-all}
nav{font-size:13px;margin:6px 0 0}nav a{margin-right:12px}
.note{color:#5b6875;font-size:12px}
#js-errors{display:none}
@media (max-width:800px){.grid2{grid-template-columns:1fr}}
@media print{
  body{background:#fff;font-size:11px}nav,.controls,.dygraph-rangesel-fgcanvas,.dygraph-rangesel-bgcanvas,.dygraph-rangesel-zoomhandle{display:none!important}
  section.recording{break-before:page}.chart-box{break-inside:avoid;border:none;padding:0}
  .grid2{grid-template-columns:1fr 1fr}table{break-inside:avoid}a{color:inherit;text-decoration:none}
}
)CSS";

const char* kScript = R"JS(
(function(){
  'use strict';
  var errors = [];
  function recordError(msg){ errors.push(String(msg)); document.body.setAttribute('data-js-errors', errors.length);
    var box = document.getElementById('js-errors'); box.style.display='block';
    var li = document.createElement('li'); li.textContent = String(msg); box.querySelector('ul').appendChild(li); }
  window.addEventListener('error', function(e){ recordError(e.message || e); });
  document.addEventListener('securitypolicyviolation', function(e){ recordError('blocked request: ' + e.blockedURI); });
  var origError = console.error; console.error = function(){ recordError(Array.prototype.join.call(arguments,' ')); origError.apply(console, arguments); };
  document.body.setAttribute('data-js-errors', 0);

  var R = JSON.parse(document.getElementById('report-data').textContent);
  var expected = document.querySelectorAll('div.chart').length, drawn = 0;
  function ready(div, g){
    if (div.getAttribute('data-drawn')) return;
    var rows = g.numRows(), finite = 0;
    for (var i = 0; i < rows; i++) for (var c = 1; c < g.numColumns(); c++) { var v = g.getValue(i, c);
      if (Array.isArray(v)) v = v[1]; if (v !== null && isFinite(v)) { finite++; break; } }
    div.setAttribute('data-drawn', finite);
    if (finite === 0) recordError('chart ' + div.id + ' has no data');
    drawn++;
    if (drawn === expected) document.body.setAttribute('data-charts-drawn', drawn);
  }
  function toggles(div, g, labels){
    var box = document.getElementById(div.id + '-controls'); if (!box) return;
    labels.slice(1).forEach(function(l, i){
      var lab = document.createElement('label'), cb = document.createElement('input');
      cb.type = 'checkbox'; cb.checked = true; cb.onchange = function(){ g.setVisibility(i, cb.checked); };
      lab.appendChild(cb); lab.appendChild(document.createTextNode(' ' + l)); box.appendChild(lab); });
  }
  function chart(id, data, labels, opts){
    var div = document.getElementById(id);
    var base = {labels: labels, legend: 'always', labelsDiv: id + '-legend', labelsSeparateLines: false,
      highlightSeriesOpts: null, animatedZooms: false, connectSeparatedPoints: true,
      drawCallback: function(g, initial){ if (initial) ready(div, g); }};
    for (var k in opts) base[k] = opts[k];
    var g = new Dygraph(div, data, base);
    toggles(div, g, labels);
    return g;
  }
  var colors = {measured:'#1f5fbf', clearance:'#c0392b', nominal:'#2e7d32', modified:'#8e44ad'};
  var names = {alpha3_rad_s2:['α3','rad/s²'], omega3_rad_s:['ω3','rad/s'], alpha4_rad_s2:['α4','rad/s²'], omega4_rad_s:['ω4','rad/s']};

  R.recordings.forEach(function(rec, ri){
    if (rec.status !== 'ok' && rec.status !== 'check set-up') return;
    var x = rec.grid.crank_deg;
    Object.keys(rec.series).forEach(function(q){
      var s = rec.series[q], id = 'r' + ri + '-' + q; if (!document.getElementById(id)) return;
      var labels = ['crank angle (deg)'], cols = [], col = [];
      function band(m, sd){ return function(i){ var d = sd ? sd[i] : 0; return [m[i]-d, m[i], m[i]+d]; }; }
      if (s.measured){ labels.push('measured (mean ± std)'); cols.push(band(s.measured, s.measured_std)); col.push(colors.measured); }
      labels.push('clearance model (mean ± std)'); cols.push(band(s.clearance, s.clearance_std)); col.push(colors.clearance);
      labels.push('nominal'); cols.push(band(s.nominal)); col.push(colors.nominal);
      if (s.modified && s.modified.length){ labels.push('modified analytical (÷ a)'); cols.push(band(s.modified)); col.push(colors.modified); }
      var data = x.map(function(xv, i){ return [xv].concat(cols.map(function(f){ return f(i); })); });
      chart(id, data, labels, {customBars: true, colors: col, strokeWidth: 1.2, showRangeSelector: true, rangeSelectorHeight: 28,
        xlabel: 'crank angle θ2 (deg)', ylabel: names[q][0] + ' (' + names[q][1] + ')'});
    });
    // Deviation amplitudes per crank order and the magnification factor per order.
    var m = rec.metrics.alpha3_rad_s2 || rec.metrics.alpha4_rad_s2, mq = rec.metrics.alpha3_rad_s2 ? 'α3' : 'α4';
    if (m && document.getElementById('r' + ri + '-orders')){
      var o = m.magnification.orders, pos = function(v){ return v > 0 ? v : null; };
      chart('r' + ri + '-orders', o.map(function(e){ return [e.order, pos(e.measured_amplitude), pos(e.simulated_amplitude), pos(e.measured_floor)]; }),
        ['order', 'measured − nominal', 'clearance model − nominal', 'measurement floor'],
        {logscale: true, drawPoints: true, pointSize: 2.5, strokeWidth: 1, colors: [colors.measured, colors.clearance, '#9aa7b4'],
         xlabel: 'crank order', ylabel: mq + ' deviation amplitude'});
      var td = m.magnification.time_domain, sp = m.magnification.spectral;
      chart('r' + ri + '-factor', o.map(function(e){ return [e.order, e.significant ? pos(e.factor) : null, td, sp]; }),
        ['order', 'a per significant order', 'a, time domain', 'a, spectral (band)'],
        {logscale: true, drawPoints: true, pointSize: 3, strokeWidth: 1, colors: ['#d35400', '#34495e', '#16a085'],
         xlabel: 'crank order', ylabel: 'magnification a'});
    }
    if (rec.spectra && document.getElementById('r' + ri + '-spectrum')){
      var keys = Object.keys(rec.spectra), ax = rec.spectra[keys[0]].order;
      chart('r' + ri + '-spectrum', ax.map(function(ov, i){ return [ov].concat(keys.map(function(k){ var v = rec.spectra[k].amplitude[i]; return v > 0 ? v : null; })); }),
        ['order'].concat(keys.map(function(k){ return 'measured ' + names[k][0] + ' (before the filter)'; })),
        {logscale: true, strokeWidth: 1, colors: [colors.measured, '#e67e22'], xlabel: 'crank order', ylabel: 'amplitude (rad/s²)'});
    }
  });

  // Session: severity against clearance (one line per speed) and against speed (one per clearance).
  function severity(id, groups, xkey, xlabel, ykeys, ylabels, yunit, groupLabel, y2){
    if (!document.getElementById(id)) return;
    var xs = [];
    groups.forEach(function(g){ g.points.forEach(function(p){ if (xs.indexOf(p[xkey]) < 0) xs.push(p[xkey]); }); });
    xs.sort(function(a, b){ return a - b; });
    var labels = [xlabel], series = {};
    groups.forEach(function(g){ ykeys.forEach(function(k, j){ var l = ylabels[j] + ' @ ' + groupLabel(g.value); labels.push(l);
      if (y2 && j === ykeys.length - 1) series[l] = {axis: 'y2'}; }); });
    var data = xs.map(function(xv){ var row = [xv];
      groups.forEach(function(g){ ykeys.forEach(function(k){ var p = g.points.filter(function(p){ return p[xkey] === xv; })[0];
        row.push(p && p[k] !== null ? p[k] : null); }); }); return row; });
    var opts = {drawPoints: true, pointSize: 4, strokeWidth: 1.5, xlabel: xlabel, ylabel: yunit, series: series};
    if (y2) opts.y2label = y2;
    chart(id, data, labels, opts);
  }
  var S = R.severity;
  var rpm = function(v){ return v.toFixed(0) + ' rpm'; }, mm = function(v){ return v.toFixed(4) + ' mm'; };
  severity('sev-clearance', S.by_speed, 'clearance_mm', 'radial clearance (mm)', ['measured_alpha3_fluctuation_rms', 'simulated_alpha3_fluctuation_rms'],
           ['measured', 'clearance model'], 'RMS of α3 − nominal (rad/s²)', rpm);
  severity('sev-clearance-sim', S.by_speed, 'clearance_mm', 'radial clearance (mm)', ['sum_normal_impulse_per_rev_Ns', 'impacts_per_rev'],
           ['ΣF per turn', 'n per turn'], 'ΣF per turn (N·s)', rpm, 'impacts per turn n');
  severity('sev-speed', S.by_clearance, 'speed_rpm', 'crank speed (rpm)', ['measured_alpha3_fluctuation_rms', 'simulated_alpha3_fluctuation_rms'],
           ['measured', 'clearance model'], 'RMS of α3 − nominal (rad/s²)', mm);
  severity('sev-speed-sim', S.by_clearance, 'speed_rpm', 'crank speed (rpm)', ['sum_normal_impulse_per_rev_Ns', 'impacts_per_rev'],
           ['ΣF per turn', 'n per turn'], 'ΣF per turn (N·s)', mm, 'impacts per turn n');
  if (expected === 0) document.body.setAttribute('data-charts-drawn', 0);
})();
)JS";

void chart_box(std::ostringstream& h, const std::string& id, const std::string& title, bool small = false,
               bool controls = false) {
  h << "<div class=\"chart-box\"><h3>" << title << "</h3>";
  if (controls) h << "<div class=\"controls\" id=\"" << id << "-controls\"></div>";
  h << "<div class=\"chart" << (small ? " small" : "") << "\" id=\"" << id << "\"></div><div class=\"legend\" id=\"" << id
    << "-legend\"></div></div>";
}

void settings_rows(std::ostringstream& h, const json& j, const std::string& prefix) {
  for (const auto& [k, v] : j.items()) {
    const std::string key = prefix.empty() ? k : prefix + "." + k;
    if (v.is_object() && !v.empty()) settings_rows(h, v, key);
    else h << "<tr><td class=\"l\">" << esc(key) << "</td><td class=\"l\">" << fmt(v, "%.6g") << "</td></tr>";
  }
}

void files_table(std::ostringstream& h, const json& files) {
  h << "<table><tr><th class=\"l\">role</th><th class=\"l\">file</th><th>bytes</th><th class=\"l\">SHA-256</th></tr>";
  for (const json& f : files)
    h << "<tr><td class=\"l\">" << fmt(f["role"]) << "</td><td class=\"l\">" << fmt(f["path"]) << "</td><td>"
      << (f.contains("bytes") ? fmt(f["bytes"], "%.0f") : "missing") << "</td><td class=\"l hash\">" << fmt(f["sha256"])
      << "</td></tr>";
  h << "</table>";
}

void recording_section(std::ostringstream& h, const json& r, std::size_t ri) {
  const std::string name = r["name"];
  const bool ok = is_analysed(r);
  h << "<section class=\"recording\" id=\"rec" << ri << "\"><h2>" << esc(name) << " <span class=\""
    << (!ok ? "failed\">failed" : r["status"] == "ok" ? "ok\">analysed" : "failed\">analysed: check set-up") << "</span>"
    << (r.value("from_cache", false) ? " <span class=\"note\">(from cache)</span>" : "") << "</h2>";
  if (ok) h << setup_check_html(r.value("setup_check", json::object()), name);
  if (!ok) {
    h << "<p class=\"err\"><b>" << (r["error_kind"] == "input" ? "Bad input" : "Run failed") << ":</b> " << esc(r["error"])
      << "</p><h3>Input files</h3>";
    files_table(h, r["files"]);
    h << "</section>";
    return;
  }
  const json& op = r["operating_point"];
  const json& th = r["theory"];
  const json& sv = th["severity"];
  h << "<table><tr><th class=\"l\">crank speed</th><th class=\"l\">clearance</th><th class=\"l\">revolutions averaged</th>"
       "<th class=\"l\">theory</th><th class=\"l\">simulated n / ΣF / I_n per turn</th></tr><tr><td class=\"l\">"
    << fmt(op["speed_rpm"], "%.2f") << " rpm (" << fmt(op["direction"]) << ", std " << fmt(at(r, {"acquisition", "speed_rpm", "std"}), "%.2f")
    << ")</td><td class=\"l\">" << fmt(op["clearance_mm"], "%.4g") << " mm</td><td class=\"l\">" << fmt(op["revolutions_averaged"], "%.0f")
    << "</td><td class=\"l\">e = " << fmt(th["settings"]["restitution"]) << ", " << fmt(th["settings"]["contact"])
    << ", μ = " << fmt(th["settings"]["friction_coefficient"]) << "; " << fmt(th["settings"]["warmup_revolutions"], "%.0f")
    << " warm-up + " << fmt(th["settings"]["averaged_revolutions"], "%.0f") << " averaged turns</td><td class=\"l\">"
    << fmt(sv["impacts_per_rev"], "%.1f") << " / " << fmt(sv["sum_normal_impulse_per_rev_Ns"], "%.3g") << " N·s / "
    << fmt(sv["impact_index_Ns"], "%.3g") << " N·s</td></tr></table>";
  if (!at(r, {"warnings"}).empty()) {
    h << "<div class=\"warn\"><b>Warnings</b><ul>";
    for (const json& w : r["warnings"]) h << "<li>" << esc(w) << "</li>";
    h << "</ul></div>";
  }
  // Metrics.
  h << "<h3>Theory over measurement</h3><table><tr><th class=\"l\">quantity</th><th>RMS measured</th><th>RMS clearance model</th>"
       "<th>RMS nominal</th><th>RMS(meas − model)</th><th>corr. model</th><th>corr. nominal</th><th>peak ratio meas/model</th>"
       "<th>a (time)</th><th>a (spectral)</th><th class=\"l\">largest deviations from nominal, θ2 (deg): measured | model</th></tr>";
  for (const auto& [q, m] : r["metrics"].items()) {
    auto angles = [](const json& a) {
      std::string s;
      for (const json& v : a) s += (s.empty() ? "" : ", ") + fmt(v, "%.1f");
      return s;
    };
    h << "<tr><td class=\"l\">" << esc(q) << "</td><td>" << fmt(m["measured_rms"]) << "</td><td>" << fmt(m["simulated_rms"])
      << "</td><td>" << fmt(m["nominal_rms"]) << "</td><td>" << fmt(m["rms_difference_simulated"]) << "</td><td>"
      << fmt(m["correlation_simulated"], "%.3f") << "</td><td>" << fmt(m["correlation_nominal"], "%.3f") << "</td><td>"
      << fmt(m["peak_ratio_simulated"], "%.3f") << "</td><td>" << fmt(m["magnification"]["time_domain"], "%.3g") << "</td><td>"
      << fmt(m["magnification"]["spectral"], "%.3g") << "</td><td class=\"l\">" << angles(m["measured_bursts_deg"]) << " | "
      << angles(m["simulated_bursts_deg"]) << "</td></tr>";
  }
  h << "</table>";
  // Overlays.
  h << "<div class=\"grid2\">";
  for (const auto& [q, s] : r["series"].items()) {
    if (!s.contains("measured")) continue;
    chart_box(h, "r" + std::to_string(ri) + "-" + q, esc(q) + ": measured vs clearance model vs nominal", false, true);
  }
  h << "</div>";
  if (!r["metrics"].empty()) {
    h << "<div class=\"grid2\">";
    chart_box(h, "r" + std::to_string(ri) + "-orders", "Deviation from the nominal response per crank order", true, true);
    chart_box(h, "r" + std::to_string(ri) + "-factor", "Magnification factor a per order (thesis eq. 8.1.2)", true, true);
    h << "</div><p class=\"note\">" << esc(r["metrics"].begin().value()["magnification"]["spectral_method"].get<std::string>())
      << ". An order is significant when the measured amplitude is 3× above the floor between the order lines.</p>";
  }
  if (!at(r, {"spectra"}).empty()) chart_box(h, "r" + std::to_string(ri) + "-spectrum", "Spectrum of the measured angular acceleration", true, true);
  h << "<h3>Impact directions in the clearance model (thesis Figs 8.11/8.12)</h3><div>"
    << polar_svg(r["impacts"], "pin_deg", "on the pin (coupler frame: 0° along the coupler, A→B)")
    << polar_svg(r["impacts"], "bushing_deg", "on the bushing (rocker frame: 0° along the rocker, O4→C)") << "</div>";
  h << "<h3>Analysis</h3><table>";
  settings_rows(h, at(r, {"analysis"}), "");
  settings_rows(h, at(r, {"acquisition"}), "acquisition");
  h << "<tr><td class=\"l\">theory energy balance residual (rel.)</td><td class=\"l\">" << fmt(th["energy_residual_rel"]) << "</td></tr></table>";
  h << "<h3>Input files</h3>";
  files_table(h, r["files"]);
  h << "</section>";
}

}  // namespace

std::string html_escape(const std::string& s) { return esc(s); }

std::filesystem::path dygraphs_dir() {
  if (const char* env = std::getenv("FOURBAR_DYGRAPHS_DIR")) return env;
  return FOURBAR_DYGRAPHS_DIR;
}

std::string render_html_report(const json& session_in) {
  const std::string js = without_source_maps(read_text(dygraphs_dir() / "dygraph.min.js"));
  const std::string css = without_source_maps(read_text(dygraphs_dir() / "dygraph.min.css"));
  json data = session_in;
  round_numbers(data);
  const json& recs = data["recordings"];
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
       "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src 'unsafe-inline'; "
       "style-src 'unsafe-inline'; img-src data:\">"
       "<meta name=\"viewport\" content=\"width=device-width,initial-scale=1\"><title>"
    << esc(data["title"]) << " — fourbar report</title><style>" << css << "</style><style>" << kCss << "</style></head><body>";
  h << "<header><h1>" << esc(data["title"]) << "</h1><p class=\"note\">fourbar " << esc(data["version"]) << " · <code>"
    << esc(data["command"]) << "</code> · session folder <code>" << esc(data["session_dir"]) << "</code></p>";
  if (!data["notes"].get<std::string>().empty()) h << "<p>" << esc(data["notes"]) << "</p>";
  h << "<nav><a href=\"#summary\">summary</a><a href=\"#session\">session</a>";
  for (std::size_t i = 0; i < recs.size(); ++i) h << "<a href=\"#rec" << i << "\">" << esc(recs[i]["name"]) << "</a>";
  h << "<a href=\"#settings\">settings</a></nav></header><main>";
  h << "<div id=\"js-errors\" class=\"err\"><b>Script errors</b><ul></ul></div>";

  // Summary table.
  const int failed = data["recordings_failed"];
  h << "<section id=\"summary\"><h2>Summary</h2>";
  for (const json& r : recs)
    if (is_analysed(r)) h << setup_check_html(r.value("setup_check", json::object()), r["name"]);
  h << "<p>" << recs.size() << " recordings, "
    << (failed ? "<span class=\"failed\">" + std::to_string(failed) + " failed</span>" : std::string("all analysed"))
    << ". Theory: clearance model and nominal mechanism at each recording's measured mean crank speed and clearance. "
       "a = RMS(model − nominal) / RMS(measured − nominal) on α3 (thesis sec. 8.1): how many times more violent the model is "
       "than the measurement.</p><table><tr><th class=\"l\">recording</th><th class=\"l\">status</th><th>speed (rpm)</th>"
       "<th>clearance (mm)</th><th>revolutions</th><th>a time</th><th>a spectral</th><th>corr. α3 meas/model</th>"
       "<th>n per turn</th><th>ΣF per turn (N·s)</th><th>I_n (N·s)</th></tr>";
  for (std::size_t i = 0; i < recs.size(); ++i) {
    const json& r = recs[i];
    h << "<tr><td class=\"l\"><a href=\"#rec" << i << "\">" << esc(r["name"]) << "</a></td>";
    if (!is_analysed(r)) {
      h << "<td class=\"l failed\" colspan=\"10\">failed: " << esc(r["error"]) << "</td></tr>";
      continue;
    }
    const json m = r["metrics"].contains("alpha3_rad_s2") ? r["metrics"]["alpha3_rad_s2"] : json::object();
    auto mm = [&](const char* a, const char* b, const char* f) {
      return m.empty() ? std::string("–") : fmt(b ? m[a][b] : m[a], f);
    };
    const json& sv = r["theory"]["severity"];
    h << (r["status"] == "ok" ? "<td class=\"l ok\">ok" : "<td class=\"l failed\">check set-up") << "</td><td>"
      << fmt(r["operating_point"]["speed_rpm"], "%.2f") << "</td><td>"
      << fmt(r["operating_point"]["clearance_mm"], "%.4g") << "</td><td>" << fmt(r["operating_point"]["revolutions_averaged"], "%.0f")
      << "</td><td>" << mm("magnification", "time_domain", "%.3g") << "</td><td>" << mm("magnification", "spectral", "%.3g")
      << "</td><td>" << mm("correlation_simulated", nullptr, "%.3f") << "</td><td>" << fmt(sv["impacts_per_rev"], "%.1f")
      << "</td><td>" << fmt(sv["sum_normal_impulse_per_rev_Ns"], "%.3g") << "</td><td>" << fmt(sv["impact_index_Ns"], "%.3g")
      << "</td></tr>";
  }
  h << "</table>";
  if (!data["orphan_manifests"].empty()) {
    h << "<p class=\"warn\">Manifests without a recording beside them (ignored):";
    for (const json& o : data["orphan_manifests"]) h << " " << esc(o);
    h << "</p>";
  }
  if (data.contains("other_files") && !data["other_files"].empty()) {
    h << "<p class=\"warn\">Files in the session folder that are neither a recording nor a manifest (ignored):";
    for (const json& o : data["other_files"]) h << " " << esc(o);
    h << "</p>";
  }
  h << "</section>";

  // Session severity.
  h << "<section id=\"session\"><h2>Severity against clearance and crank speed</h2><p class=\"note\">Measured: RMS of the "
       "averaged α3 about the nominal response (thesis Figs 7.9–7.17). Clearance model: the same, and the impacts per turn n, "
       "the sum of normal impulses per turn ΣF and I_n = ΣF/n (thesis Figs 7.10/7.11).</p><div class=\"grid2\">";
  chart_box(h, "sev-clearance", "Fluctuation against clearance", true, true);
  chart_box(h, "sev-clearance-sim", "Simulated impacts against clearance", true, true);
  chart_box(h, "sev-speed", "Fluctuation against crank speed", true, true);
  chart_box(h, "sev-speed-sim", "Simulated impacts against crank speed", true, true);
  h << "</div></section>";

  for (std::size_t i = 0; i < recs.size(); ++i) recording_section(h, recs[i], i);

  h << "<section id=\"settings\"><h2>Settings</h2><table><tr><th class=\"l\">setting</th><th class=\"l\">value</th></tr>";
  settings_rows(h, data["settings"], "");
  h << "</table>";
  if (!data["settings_file"].is_null()) files_table(h, json::array({data["settings_file"]}));
  h << "</section></main><footer><p class=\"note\">Self-contained: data and Debian's dygraphs "
       "(MIT licence) are inlined; nothing is fetched.</p></footer>";
  h << "<script id=\"report-data\" type=\"application/json\">" << json_safe(json_text(data)) << "</script>";
  h << "<script>" << script_safe(js) << "</script><script>" << kScript << "</script></body></html>\n";
  return h.str();
}

}  // namespace fourbar
