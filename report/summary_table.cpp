#include "report/summary_table.hpp"

#include <algorithm>
#include <string_view>

#include "common/csv_writer.hpp"
#include "report/setup_check_record.hpp"
#include "report/verdict.hpp"

namespace fourbar {

namespace {

using nlohmann::json;

/// The value at `path` ("metrics/alpha3_rad_s2/correlation_simulated") or null.
const json& at(const json& r, std::string_view path) {
  static const json kNull;
  const json* j = &r;
  while (!path.empty()) {
    const auto slash = path.find('/');
    const std::string key(path.substr(0, slash));
    if (!j->is_object() || !j->contains(key)) return kNull;
    j = &(*j)[key];
    path = slash == std::string_view::npos ? std::string_view() : path.substr(slash + 1);
  }
  return *j;
}

/// A number in shortest round-trip form; empty for null (no value).
std::string number(const json& v) {
  if (v.is_number()) return format_double(v.get<double>());
  return {};
}

std::string text(const json& v) { return v.is_string() ? v.get<std::string>() : std::string(); }

std::string count(const json& v) { return v.is_array() ? std::to_string(v.size()) : std::string(); }

template <std::size_t N>
struct Path {
  char text[N];
  constexpr Path(const char (&s)[N]) { std::copy_n(s, N, text); }
};

/// The number at a fixed path of an analysed recording (a failed one has
/// none), as a function pointer for the table.
template <Path P>
std::string analysed_number_at(const json& r) {
  return is_analysed(r) ? number(at(r, P.text)) : std::string();
}

std::vector<SummaryColumn> make_columns() {
  std::vector<SummaryColumn> c = {
    {"id", "", [](const json& r) { return std::filesystem::path(text(r["name"])).stem().string(); }},
    {"file", "", [](const json& r) { return text(r["name"]); }},
    {"status", "", [](const json& r) { return text(at(r, "status")); }},
    // The verdict and the one a it judges by (report/verdict.hpp).
    {"verdict", "", [](const json& r) { return text(at(r, "verdict/overall")); }},
    {"a", "", [](const json& r) { return number(at(r, "verdict/a")); }},
    {"a_standard_error", "", [](const json& r) { return number(at(r, "verdict/a_standard_error")); }},
    {"a_kind", "", [](const json& r) { return text(at(r, "verdict/a_from")); }},
  };
  for (const VerdictPartInfo& p : verdict_parts()) {
    const std::string key = p.key;
    c.push_back({"verdict_" + key, "", [key](const json& r) { return text(at(r, "verdict/" + key + "/level")); }});
  }
  const SummaryColumn rest[] = {
    {"speed", "rpm", analysed_number_at<"operating_point/speed_rpm">},
    {"speed_std", "rpm", analysed_number_at<"acquisition/speed_rpm/std">},
    // The manifest's clearance, written as the manifest gives it (0.0254, not
    // 0.025400000000000002 after mm -> m -> mm).
    {"clearance", "mm",
     [](const json& r) {
       const json& v = at(r, "operating_point/clearance_mm");
       return is_analysed(r) && v.is_number() ? format_input_decimal(v.get<double>()) : std::string();
     }},
    {"direction", "", [](const json& r) { return text(at(r, "operating_point/direction")); }},
    {"revolutions_averaged", "", analysed_number_at<"operating_point/revolutions_averaged">},
    {"revolutions_clipped", "", analysed_number_at<"acquisition/revolutions_clipped">},
    {"a_time", "", analysed_number_at<"metrics/alpha3_rad_s2/magnification/time_domain">},
    {"a_spectral", "", analysed_number_at<"metrics/alpha3_rad_s2/magnification/spectral">},
    {"alpha3_measured_fluctuation_rms", "rad_s2",
     analysed_number_at<"metrics/alpha3_rad_s2/magnification/measured_deviation_rms">},
    {"alpha3_model_fluctuation_rms", "rad_s2",
     analysed_number_at<"metrics/alpha3_rad_s2/magnification/simulated_deviation_rms">},
    {"alpha3_rms_difference_model", "rad_s2", analysed_number_at<"metrics/alpha3_rad_s2/rms_difference_simulated">},
    {"alpha3_rms_difference_nominal", "rad_s2", analysed_number_at<"metrics/alpha3_rad_s2/rms_difference_nominal">},
    {"alpha3_correlation_model", "", analysed_number_at<"metrics/alpha3_rad_s2/correlation_simulated">},
    {"alpha3_correlation_nominal", "", analysed_number_at<"metrics/alpha3_rad_s2/correlation_nominal">},
    {"alpha4_a_time", "", analysed_number_at<"metrics/alpha4_rad_s2/magnification/time_domain">},
    {"alpha4_correlation_model", "", analysed_number_at<"metrics/alpha4_rad_s2/correlation_simulated">},
    {"model_impacts_per_rev", "", analysed_number_at<"theory/severity/impacts_per_rev">},
    {"model_sum_normal_impulse_per_rev", "Ns", analysed_number_at<"theory/severity/sum_normal_impulse_per_rev_Ns">},
    {"model_impact_index", "Ns", analysed_number_at<"theory/severity/impact_index_Ns">},
    {"setup_check", "", [](const json& r) { return text(at(r, "setup_check/status")); }},
    {"setup_findings", "", [](const json& r) { return count(at(r, "setup_check/findings")); }},
    {"warnings", "", [](const json& r) { return count(at(r, "warnings")); }},
    {"error", "", [](const json& r) { return text(at(r, "error")); }},
  };
  c.insert(c.end(), std::begin(rest), std::end(rest));
  return c;
}

}  // namespace

std::span<const SummaryColumn> summary_columns() {
  static const std::vector<SummaryColumn> kColumns = make_columns();
  return kColumns;
}

void write_summary_table(const json& session, const std::filesystem::path& out_dir,
                         const std::vector<std::string>& comments) {
  std::vector<std::string> headers;
  const auto columns = summary_columns();
  for (const SummaryColumn& c : columns) headers.push_back(c.header());
  CsvWriter csv(out_dir / "summary.csv", comments, headers);
  std::vector<std::string> cells(headers.size());
  for (const json& r : session["recordings"]) {
    for (std::size_t c = 0; c < cells.size(); ++c) cells[c] = columns[c].cell(r);
    csv.text_row(cells);
  }
  csv.commit();
}

}  // namespace fourbar
