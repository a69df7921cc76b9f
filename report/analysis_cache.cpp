#include "report/analysis_cache.hpp"

#include <cmath>
#include <fstream>

#include "common/atomic_output.hpp"
#include "report/setup_check_record.hpp"

namespace fourbar {

using nlohmann::json;

std::optional<json> read_cached_record(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  try {
    json j = json::parse(in);
    // An analysed record ("ok" or "check set-up") that holds the set-up check
    // and, per quantity, the orders its spectral magnification used, and the
    // views (older cache entries without them are recomputed).
    if (!j.is_object() || !is_analysed(j) || !j.contains("setup_check") || !j.contains("views") ||
        !j.contains("model_family"))
      return std::nullopt;
    if (j.contains("metrics") && j["metrics"].is_object())
      for (const json& m : j["metrics"])
        if (!m.contains("magnification") || !m["magnification"].contains("orders_used")) return std::nullopt;
    return j;
  } catch (const std::exception&) {
    // A damaged cache entry is recomputed.
  }
  return std::nullopt;
}

namespace {

/// JSON text reads back every value exactly (nlohmann writes the shortest
/// decimal that parses back to the same double, -0.0 included) except a NaN
/// or an infinity, which it writes as null.
bool all_numbers_finite(const json& j) {
  if (j.is_number_float()) return std::isfinite(j.get<double>());
  if (j.is_structured())
    for (const json& e : j)
      if (!all_numbers_finite(e)) return false;
  return true;
}

}  // namespace

bool write_cached_record(const std::filesystem::path& file, const json& record) {
  if (!all_numbers_finite(record)) return false;
  std::string text;
  try {
    text = record.dump();
  } catch (const json::exception&) {  // invalid UTF-8 in a string
    return false;
  }
  write_text_file(file, text);
  return true;
}

}  // namespace fourbar
