#include "report/quantity_names.hpp"

#include <array>

namespace fourbar {

namespace {

constexpr std::array<QuantityName, 12> kNames{{
    {"alpha3_rad_s2", "α3", "coupler angular acceleration", "rad/s²"},
    {"omega3_rad_s", "ω3", "coupler angular velocity", "rad/s"},
    {"alpha4_rad_s2", "α4", "rocker angular acceleration", "rad/s²"},
    {"omega4_rad_s", "ω4", "rocker angular velocity", "rad/s"},
    {"crank_deg", "θ2", "crank angle", "deg"},
    {"speed_rpm", "", "crank speed", "rpm"},
    {"clearance_mm", "ξ", "radial clearance", "mm"},
    {"measured_alpha3_fluctuation_rms", "", "RMS of α3 − nominal, measured", "rad/s²"},
    {"simulated_alpha3_fluctuation_rms", "", "RMS of α3 − nominal, clearance model", "rad/s²"},
    {"impacts_per_rev", "n", "impacts per turn", ""},
    {"sum_normal_impulse_per_rev_Ns", "ΣF", "sum of normal impulses per turn", "N·s"},
    {"impact_index_Ns", "I_n", "impact index ΣF/n", "N·s"},
}};

std::string with_unit(std::string text, const QuantityName& n) {
  if (*n.unit) text += std::string(" (") + n.unit + ")";
  return text;
}

}  // namespace

const QuantityName* find_quantity_name(const std::string& key) {
  for (const QuantityName& n : kNames)
    if (key == n.key) return &n;
  return nullptr;
}

std::string quantity_label(const std::string& key) {
  const QuantityName* n = find_quantity_name(key);
  if (!n) return key;
  return with_unit(std::string(n->description) + (*n->symbol ? std::string(" ") + n->symbol : ""), *n);
}

std::string quantity_axis_label(const std::string& key) {
  const QuantityName* n = find_quantity_name(key);
  if (!n) return key;
  return with_unit(*n->symbol ? n->symbol : n->description, *n);
}

nlohmann::json quantity_names_json() {
  nlohmann::json j = nlohmann::json::object();
  for (const QuantityName& n : kNames)
    j[n.key] = {{"symbol", n.symbol}, {"description", n.description}, {"unit", n.unit},
                {"label", quantity_label(n.key)}, {"axis", quantity_axis_label(n.key)}};
  return j;
}

}  // namespace fourbar
