#include "report/setup_check_record.hpp"

#include <cmath>
#include <sstream>

#include "report/html_text.hpp"

namespace fourbar {

using nlohmann::json;

std::string analysed_status(const SetupCheck& check) { return check.findings.empty() ? "ok" : "check set-up"; }

bool is_analysed(const json& record) {
  const std::string s = record.value("status", "");
  return s == "ok" || s == "check set-up";
}

json setup_check_json(const SetupCheck& c, const std::string& manifest_file) {
  auto number = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  json findings = json::array();
  for (const SetupFinding& f : c.findings)
    findings.push_back({{"item", f.item},
                        {"channel", f.channel},
                        {"key", f.key},
                        {"manifest", f.manifest},
                        {"data", f.data},
                        {"confidence", f.confidence},
                        {"message", f.message}});
  json j = {{"status", c.status()}, {"manifest", manifest_file}, {"findings", findings}};
  if (!c.checked) {
    j["not_checked"] = c.not_checked;
    return j;
  }
  json channels = json::array();
  for (const ChannelSetupEstimate& e : c.channels)
    channels.push_back({{"channel", e.channel},
                        {"role", to_string(e.role)},
                        {"fitted_as", e.fitted_as},
                        {"scale", number(e.scale)},
                        {"position_mm", number(e.position_mm)},
                        {"position_confidence", number(e.position_confidence)},
                        {"fit", number(e.fit)},
                        {"fit_manifest", number(e.fit_manifest)}});
  json normal = json::object();
  for (const auto& [name, v] : c.normal_consistency) normal[name] = number(v);
  j["data"] = {{"crank_offset_deg", c.crank_offset_deg},
               {"crank_direction", c.crank_direction > 0 ? "ccw" : "cw"},
               {"swapped", c.swapped},
               {"channels", channels}};
  j["fit"] = number(c.fit);
  j["fit_manifest"] = number(c.fit_manifest);
  j["band_orders"] = c.band_orders;
  j["normal_consistency"] = normal;
  return j;
}

std::vector<std::string> setup_check_lines(const json& sc) {
  std::vector<std::string> lines;
  for (const json& f : sc.value("findings", json::array()))
    lines.push_back("check set-up: " + sc.value("manifest", std::string()) + ": " + f.value("message", std::string()));
  return lines;
}

std::string setup_check_html(const json& sc, const std::string& title) {
  if (sc.value("findings", json::array()).empty()) return {};
  std::ostringstream h;
  h << "<div class=\"warn setup\"><b>Check set-up: " << html_escape(title)
    << "</b> — the data contradict the manifest <code>" << html_escape(sc.value("manifest", std::string()))
    << "</code>; its results rest on it.<ul>";
  for (const json& f : sc["findings"]) {
    h << "<li>" << (f["channel"].get<std::string>().empty() ? "" : "channel <code>" + html_escape(f["channel"]) + "</code>: ")
      << "<b>" << html_escape(f["item"]) << "</b>: the manifest says " << html_escape(f["manifest"]) << ", the data say "
      << html_escape(f["data"]) << " (confidence " << std::lround(100 * f["confidence"].get<double>())
      << " %); change <code>" << html_escape(f["key"]) << "</code></li>";
  }
  h << "</ul></div>";
  return h.str();
}

}  // namespace fourbar
