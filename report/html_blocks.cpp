#include "report/html_blocks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "report/html_text.hpp"

namespace fourbar {

using nlohmann::json;

std::string polar_svg(const json& impacts, const char* key, const std::string& title) {
  const double size = 260, c = size / 2, r0 = 40, r1 = 110;
  double fmax = 0;
  for (const json& i : impacts) fmax = std::max(fmax, i["normal_impulse_Ns"].get<double>());
  std::ostringstream s;
  s << "<figure class=\"polar\"><svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size << "\" height=\"" << size
    << "\" viewBox=\"0 0 " << size << ' ' << size << "\" role=\"img\" aria-label=\"" << html_escape(title) << "\">"
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
  s << "</svg><figcaption>" << html_escape(title) << " — " << dots << " impacts; distance from the inner ring ∝ √F (largest "
    << fmt(json(fmax), "%.3g") << " N·s)</figcaption></figure>";
  return s.str();
}

void chart_box(std::ostringstream& h, const std::string& id, const std::string& title, bool small, bool controls) {
  h << "<div class=\"chart-box\"><h3>" << title << "</h3>";
  if (controls) h << "<div class=\"controls\" id=\"" << id << "-controls\"></div>";
  h << "<div class=\"chart" << (small ? " small" : "") << "\" id=\"" << id << "\"></div><div class=\"legend\" id=\"" << id
    << "-legend\"></div></div>";
}

std::string human_label(const std::string& key) {
  // Unit suffixes as a reader writes them; the longest first.
  static const std::pair<const char*, const char*> kUnits[] = {
      {"_rad_s2", " (rad/s²)"}, {"_rad_s", " (rad/s)"}, {"_m_s2", " (m/s²)"}, {"_rpm", " (rpm)"}, {"_deg", " (°)"},
      {"_pct", " (%)"},         {"_hz", " (Hz)"},       {"_Hz", " (Hz)"},     {"_mm", " (mm)"},   {"_Ns", " (N·s)"},
      {"_Nm", " (N·m)"},        {"_s", " (s)"},         {"_V", " (V)"},       {"_rel", " (relative)"}};
  std::string unit, stem = key;
  for (const auto& [suffix, text] : kUnits) {
    const std::string sfx = suffix;
    if (stem.size() > sfx.size() && stem.compare(stem.size() - sfx.size(), sfx.size(), sfx) == 0) {
      stem.resize(stem.size() - sfx.size());
      unit = text;
      break;
    }
  }
  for (char& c : stem)
    if (c == '_') c = ' ';
  return stem + unit;
}

void settings_rows(std::ostringstream& h, const json& j, const std::string& prefix) {
  for (const auto& [k, v] : j.items()) {
    // People read the labels: words and units, the parts joined by " › " (summary.json keeps the keys).
    const std::string key = prefix.empty() ? human_label(k) : prefix + " › " + human_label(k);
    if (v.is_object() && !v.empty()) settings_rows(h, v, key);
    else if ((v.is_object() || v.is_array()) && v.empty()) continue;  // nothing to show ("theory by recording {}")
    else h << "<tr><td class=\"l\">" << html_escape(key) << "</td><td class=\"l\">" << fmt(v, "%.6g") << "</td></tr>";
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

}  // namespace fourbar
