#include "report/html_views.hpp"

#include <string>

#include "report/html_blocks.hpp"
#include "report/html_text.hpp"

namespace fourbar {

using nlohmann::json;

namespace {

std::string unit_of(const json& c) { return c.value("unit", ""); }

/// "min … max unit", or "–".
std::string span(const json& lohi, const std::string& unit) {
  if (!lohi.is_object()) return "–";
  return fmt(lohi["min"], "%.4g") + " … " + fmt(lohi["max"], "%.4g") + " " + html_escape(unit);
}

std::string sensitivity(const json& c) {
  if (c.contains("volts_per_m_s2")) return fmt(c["volts_per_m_s2"], "%.4g") + " V/(m/s²)";
  if (c.contains("thresholds")) {
    const json& t = c["thresholds"];
    return std::string(c["thresholds"].value("automatic", true) ? "automatic" : "manifest") + " thresholds " +
           fmt(t["low_V"], "%.3g") + " / " + fmt(t["high_V"], "%.3g") + " V" +
           (t.value("follows_baseline", false) ? " (relative to the local mid-level)" : "") + "; levels " +
           fmt(t["bottom_level_V"], "%.3g") + " / " + fmt(t["top_level_V"], "%.3g") + " V";
  }
  return "–";
}

std::string mount(const json& c) {
  if (!c.contains("position_mm")) return c.contains("crank_offset_deg") ? "crank offset " + fmt(c["crank_offset_deg"], "%.4g") + "°" : "–";
  std::string s = fmt(c["position_mm"], "%.4g") + " / " + fmt(c["offset_mm"], "%.4g");
  if (c.value("ac_coupled", false)) s += "; AC-coupled, " + fmt(c["highpass_hz"], "%.3g") + " Hz";
  return s;
}

std::string range_use(const json& c) {
  const json& rec = at(c, {"recorded"});
  const json& in = at(c, {"input_range"});
  if (!rec.is_object() || !in.is_object()) return "–";
  const double full = in["max"].get<double>() - in["min"].get<double>();
  if (!(full > 0)) return "–";
  return fmt(json(100.0 * (rec["max"].get<double>() - rec["min"].get<double>()) / full), "%.0f") + " %";
}

std::string clipping(const json& c) {
  const json& rec = at(c, {"recorded"});
  if (!rec.is_object()) return "–";
  if (!rec.value("clipping_checked", false)) return c.contains("volts_per_m_s2") ? "not checked" : "–";
  const double n = rec["clipped_samples"].get<double>();
  if (n == 0) return "none";
  return "<span class=\"failed\">" + fmt(rec["clipped_samples"], "%.0f") + " samples, first at " + fmt(rec["first_clip_s"], "%.4g") + " s</span>";
}

std::string check(const json& c) {
  const json& sc = at(c, {"setup_check"});
  if (!sc.is_object()) return "–";
  std::string s = html_escape(sc.value("status", ""));
  if (sc["status"] == "check set-up") s = "<span class=\"failed\">" + s + "</span>";
  if (sc.contains("fit")) s += "; fit " + fmt(sc["fit_manifest"], "%.2f") + " (manifest) / " + fmt(sc["fit"], "%.2f") + " (data)";
  if (sc.contains("scale") && !sc["scale"].is_null()) s += ", scale " + fmt(sc["scale"], "%.3g");
  if (sc.contains("crank_offset_deg"))
    s += "; data: offset " + fmt(sc["crank_offset_deg"], "%.4g") + "°, " + fmt(sc["crank_direction"]);
  for (const json& f : sc.value("findings", json::array())) s += "<br>" + html_escape(f.get<std::string>());
  if (sc.contains("note")) s += "<br>" + html_escape(sc["note"].get<std::string>());
  return s;
}

void channel_table(std::ostringstream& h, const json& sheet) {
  h << "<h3>Channels and calibration</h3><table class=\"views-sheet\"><tr><th class=\"l\">channel</th><th class=\"l\">role</th>"
       "<th class=\"l\">sensitivity</th><th>axis sign</th><th class=\"l\">position / offset (mm)</th><th class=\"l\">input range</th>"
       "<th class=\"l\">recorded min … max</th><th>RMS</th><th>range used</th><th class=\"l\">clipping</th><th class=\"l\">set-up check</th></tr>";
  for (const json& c : sheet["channels"]) {
    const std::string u = unit_of(c);
    const json& rec = at(c, {"recorded"});
    h << "<tr><td class=\"l\">" << html_escape(c["name"]) << " <span class=\"note\">#" << fmt(c["index"], "%.0f") << "</span></td><td class=\"l\">"
      << html_escape(c["role"]) << "</td><td class=\"l\">" << sensitivity(c) << "</td><td>"
      << (c.contains("axis_sign") ? fmt(c["axis_sign"], "%+.0f") : "–") << "</td><td class=\"l\">" << mount(c) << "</td><td class=\"l\">"
      << span(at(c, {"input_range"}), u) << "</td><td class=\"l\">" << span(rec, u) << "</td><td>"
      << (rec.is_object() ? fmt(rec["rms"], "%.4g") + " " + html_escape(u) : "–") << "</td><td>" << range_use(c) << "</td><td class=\"l\">"
      << clipping(c) << "</td><td class=\"l\">" << check(c) << "</td></tr>";
  }
  h << "</table><p class=\"note\">Sensitivity and mount as the manifest gives them (full scale " << fmt(sheet["full_scale_V"], "%.4g")
    << " V per recorded unit, " << html_escape(sheet.value("sample_format", "")) << " at " << fmt(sheet["sample_rate_hz"], "%.6g")
    << " Hz); recorded values calibrated (m/s², axis sign applied) or in volts. The set-up check compares each channel's reading "
       "with the nominal mechanism: fit = share of the reading explained with the manifest's values and with the data's best ones.</p>";
}

}  // namespace

void views_section(std::ostringstream& h, const json& r, std::size_t ri) {
  const json& v = at(r, {"views"});
  if (!v.is_object()) return;
  const std::string id = "r" + std::to_string(ri) + "-view-";
  if (v["channels"].is_object()) channel_table(h, v["channels"]);
  const json& x = v["excerpt"];
  if (x.is_object()) {
    h << "<div class=\"grid2\">";
    chart_box(h, id + "pulse", "Crank signal as recorded, with the detected pulses and the trigger thresholds", true);
    chart_box(h, id + "accel", "Accelerometer signals as recorded (calibrated), same revolutions", true);
    h << "</div><p class=\"note\">" << x["pulse_s"].size()
      << " pulses in " << fmt(x["start_s"], "%.4g") << " … " << fmt(x["end_s"], "%.4g") << " s (the middle of the recording). "
      << (x["bucket_frames"].get<int>() > 1 ? "Shown as the minimum and maximum of every " + fmt(x["bucket_frames"], "%.0f") + " samples. " : "Every sample shown. ")
      << "Vertical lines: accepted pulses (dashed: inserted for a missed one; grey: edges judged spurious).</p>";
  }
  if (v["speed"].is_object() && !v["speed"]["rpm"].empty()) {
    chart_box(h, id + "speed", "Crank speed over the recording", true);
    h << "<p class=\"note\">" << html_escape(v["speed"].value("source", "")) << "; " << html_escape(v["speed"].value("rule", ""))
      << ". Mean " << fmt(v["speed"]["mean_rpm"], "%.2f") << " rpm, std " << fmt(v["speed"]["std_rpm"], "%.3g") << " rpm.</p>";
  }
  const json& m = v["map"];
  if (m.is_object()) {
    const std::string what = m["quantity"] == "alpha3_rad_s2" ? "coupler α3" : "rocker α4";
    h << "<div class=\"chart-box\"><h3>Where the " << what << " deviates from the nominal response, revolution by revolution</h3>"
      << "<div class=\"chart map\" id=\"" << id << "map\"></div><p class=\"note\">Colour: measured − nominal " << what
      << " (rad/s²), blue below and red above the nominal. " << html_escape(m.value("rule", ""))
      << ". Vertical stripes: impacts that repeat at the same crank angle every turn; scattered spots: impacts that wander.</p></div>";
  }
}

}  // namespace fourbar
