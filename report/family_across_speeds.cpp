#include "report/family_across_speeds.hpp"

#include <cmath>
#include <string>

#include "common/format.hpp"
#include "compare/model_family.hpp"

namespace fourbar {

using nlohmann::json;

namespace {

bool checked(const json& r) {
  return r.is_object() && r.contains("model_family") && r["model_family"].is_object() &&
         r["model_family"].value("checked", false) && r["model_family"].contains("bands");
}

/// Does `partner`'s check cover [low_hz, high_hz) and stand kExcessRatio
/// above its neighbours somewhere in it?
bool shows_at(const json& partner, double low_hz, double high_hz, bool& covers) {
  const json& bands = partner["model_family"]["bands"];
  if (bands.empty()) return false;
  covers = bands.front().value("low_hz", 0.0) <= low_hz && partner["model_family"].value("checked_up_to_hz", 0.0) >= high_hz;
  if (!covers) return false;
  for (const json& b : bands)
    if (b.value("high_hz", 0.0) > low_hz && b.value("low_hz", 0.0) < high_hz && b.value("ratio_to_neighbours", 0.0) >= kExcessRatio)
      return true;
  return false;
}

std::string rpm_text(double crank_hz) { return format_number(60 * crank_hz, 3) + " rpm"; }

}  // namespace

std::size_t set_aside_findings_that_move_with_speed(std::vector<json>& records) {
  std::size_t set_aside = 0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    json& r = records[i];
    if (!checked(r) || r["model_family"].value("unmodelled", json::array()).empty()) continue;
    json& mf = r["model_family"];
    const double crank_hz = mf.value("crank_hz", 0.0);
    json kept = json::array(), moved = json::array();
    std::string text;
    for (const json& u : mf["unmodelled"]) {
      const double lo = u.value("low_hz", 0.0), hi = u.value("high_hz", 0.0);
      // Link vibration placed by the elastic-link reference: the rig's modal
      // data, not a coincidence of this record's spectrum, says where it is.
      if (u.value("kind", std::string()) == "link vibration") {
        kept.push_back(u);
        continue;
      }
      bool any_partner = false, confirmed = false;
      std::string not_at;
      for (std::size_t k = 0; k < records.size() && !confirmed; ++k) {
        if (k == i || !checked(records[k])) continue;
        const double other_hz = records[k]["model_family"].value("crank_hz", 0.0);
        if (!(std::abs(other_hz - crank_hz) >= kOtherSpeedShare * crank_hz)) continue;
        bool covers = false;
        confirmed = shows_at(records[k], lo, hi, covers);
        if (covers) {
          any_partner = true;
          if (!confirmed) not_at += (not_at.empty() ? "" : ", ") + records[k].value("name", std::string("?")) + " (" + rpm_text(other_hz) + ")";
        }
      }
      if (!any_partner || confirmed) {
        kept.push_back(u);
        continue;
      }
      moved.push_back(u);
      ++set_aside;
      text += (text.empty() ? "" : " ") + std::string("Energy at ") + format_number(lo, 4) + "–" + format_number(hi, 4) + " Hz (peak " +
              format_number(u.value("peak_hz", 0.0), 4) + " Hz) at " + rpm_text(crank_hz) + " is not at the same frequency in " + not_at +
              ": it moves with the crank speed, so it is the clearance's own rhythm (which another e or μ shifts), not a structure the model lacks; set aside.";
    }
    if (moved.empty()) continue;
    mf["unmodelled"] = kept;
    mf["moves_with_speed"] = moved;
    mf["moves_with_speed_text"] = text;
    // The verdict fields from the first finding left (compare/model_family.cpp
    // stored each finding's own), or none.
    mf.erase("cannot_judge");
    if (kept.empty()) {
      mf["judged_below_hz"] = nullptr;
      mf["a_scatter_below"] = nullptr;
      mf["measured_scatter_below"] = 0.0;
      mf["model_scatter_below"] = 0.0;
    } else {
      const json& u = kept.front();
      mf["judged_below_hz"] = u.value("judged_below_hz", 0.0);
      mf["a_scatter_below"] = u.contains("a_scatter_below") ? u["a_scatter_below"] : json(nullptr);
      mf["measured_scatter_below"] = u.value("measured_scatter_below", 0.0);
      mf["model_scatter_below"] = u.value("model_scatter_below", 0.0);
      if (u.contains("cannot_judge")) mf["cannot_judge"] = u["cannot_judge"];
    }
    for (json& b : mf["bands"]) {  // the bands marked unmodelled: only those of findings kept
      if (!b.value("unmodelled", false)) continue;
      bool in_kept = false;
      for (const json& u : kept)
        in_kept = in_kept || (b.value("low_hz", 0.0) >= u.value("low_hz", 0.0) && b.value("high_hz", 0.0) <= u.value("high_hz", 0.0) + 1e-9);
      b["unmodelled"] = in_kept;
    }
  }
  return set_aside;
}

}  // namespace fourbar
