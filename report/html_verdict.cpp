#include "report/html_verdict.hpp"

#include <vector>

#include "report/html_text.hpp"
#include "report/verdict.hpp"
#include "report/verdict_table.hpp"

namespace fourbar {

using nlohmann::json;

namespace {

std::string level_span(const json& level, const std::string& text) {
  const std::string l = level.is_string() ? level.get<std::string>() : "not_judged";
  std::string cls = l;
  for (char& c : cls)
    if (c == ' ') c = '_';
  return "<span class=\"v-" + html_escape(cls) + "\">" + html_escape(text) + "</span>";
}

}  // namespace

void verdict_summary_table(std::ostringstream& h, const json& records) {
  h << "<table class=\"verdict\"><tr><th class=\"l\">recording</th><th class=\"l\">verdict</th><th class=\"l\">a (judged by)</th>";
  for (const VerdictPartInfo& p : verdict_parts()) h << "<th class=\"l\">" << p.label << "</th>";
  h << "</tr>";
  for (std::size_t i = 0; i < records.size(); ++i) {
    const json& r = records[i];
    h << "<tr><td class=\"l\"><a href=\"#rec" << i << "\">" << html_escape(r.value("name", "")) << "</a></td>";
    if (!r.contains("verdict")) {
      h << "<td class=\"l\" colspan=\"" << verdict_parts().size() + 2 << "\">" << level_span("problem", "failed: not analysed")
        << "</td></tr>";
      continue;
    }
    const json& v = r["verdict"];
    h << "<td class=\"l\">" << level_span(v["overall"], v["overall"].get<std::string>()) << "</td><td class=\"l num\">"
      << html_escape(verdict_a_text(v)) << "</td>";
    for (const VerdictPartInfo& p : verdict_parts())
      h << "<td class=\"l\">" << level_span(v[p.key]["level"], v[p.key]["words"].get<std::string>()) << "</td>";
    h << "</tr>";
  }
  h << "</table>";
}

std::string verdict_box(const json& r) {
  if (!r.contains("verdict")) return {};
  const json& v = r["verdict"];
  std::ostringstream h;
  h << "<div class=\"verdict\"><b>Verdict: " << level_span(v["overall"], v["overall"].get<std::string>())
    << "</b> — a " << html_escape(verdict_a_text(v)) << "<table>";
  for (const VerdictPartInfo& p : verdict_parts())
    h << "<tr><td class=\"l\">" << p.label << "</td><td class=\"l\">" << level_span(v[p.key]["level"], v[p.key]["level"].get<std::string>())
      << "</td><td class=\"l\">" << html_escape(v[p.key]["sentence"].get<std::string>()) << "</td></tr>";
  h << "</table></div>";
  return h.str();
}

std::string spectral_orders_note(const json& mg) {
  auto list = [](const std::vector<int>& v) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v[i]);
    return s;
  };
  std::vector<int> used, mains;
  for (const json& k : mg.value("orders_used", json::array())) used.push_back(k.get<int>());
  for (const json& o : mg.value("orders", json::array()))
    if (o.value("mains", false)) mains.push_back(o["order"].get<int>());
  const int band = mg.value("nominal_band_orders", 0);
  std::string s = used.empty() ? "a (spectral): no order qualifies" : "a (spectral) from orders " + list(used);
  std::string out;
  if (band > 0) out += "orders 1 … " + std::to_string(band) + " (the nominal response's band)";
  if (!mains.empty()) out += (out.empty() ? "orders " : "; orders ") + list(mains) + " (mains hum)";
  return s + (out.empty() ? "." : "; left out: " + out + ".");
}

}  // namespace fourbar
