#include "report/series_files.hpp"

#include <string>
#include <vector>

#include "common/atomic_output.hpp"
#include "common/csv_writer.hpp"
#include "report/setup_check_record.hpp"
#include "report/summary_table.hpp"

namespace fourbar {

namespace {

using nlohmann::json;

/// "alpha3_rad_s2" → {"alpha3", "rad_s2"}.
std::pair<std::string, std::string> split_unit(const std::string& column) {
  const auto p = column.find('_');
  return {column.substr(0, p), column.substr(p + 1)};
}

std::vector<std::string> comments(const std::string& made_by, const json& r) {
  std::vector<std::string> c{made_by};
  for (const json& f : r["files"])
    c.push_back("input: " + f["path"].get<std::string>() + " sha256 " +
                (f["sha256"].is_null() ? std::string("-") : f["sha256"].get<std::string>()));
  return c;
}

/// A cell: the number in shortest round-trip form, a flag as 1 or 0, empty
/// for null (a value that does not exist, e.g. no factor where the measured
/// amplitude is 0) — never a made-up 0.
std::string cell(const json& v) {
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  if (v.is_number()) return format_double(v.get<double>());
  return {};
}

void write_recording(const std::string& made_by, const json& r, const std::filesystem::path& dir, bool csv_comments) {
  const std::string stem = std::filesystem::path(r["name"].get<std::string>()).stem().string();
  const auto notes = csv_comments ? comments(made_by, r) : std::vector<std::string>{};

  // Per-angle series.
  std::vector<std::string> cols{"crank_deg"};
  std::vector<const std::vector<double>*> data;
  std::vector<std::vector<double>> store;
  store.reserve(64);
  store.push_back(r["grid"]["crank_deg"].get<std::vector<double>>());
  for (const auto& [q, s] : r["series"].items()) {
    const auto [name, unit] = split_unit(q);
    for (const char* part : {"measured", "measured_std", "clearance", "clearance_std", "nominal", "modified"}) {
      if (!s.contains(part) || s[part].empty()) continue;
      cols.push_back(name + "_" + part + "_" + unit);
      store.push_back(s[part].get<std::vector<double>>());
    }
  }
  CsvWriter series(dir / (stem + ".csv"), notes, cols);
  std::vector<double> row(cols.size());
  for (std::size_t k = 0; k < store[0].size(); ++k) {
    for (std::size_t c = 0; c < store.size(); ++c) row[c] = store[c][k];
    series.row(row);
  }

  // Per-order magnification.
  std::vector<std::string> ocols{"order"};
  std::vector<const json*> orders;
  for (const auto& [q, m] : r["metrics"].items()) {
    const auto [name, unit] = split_unit(q);
    for (const std::string part : {"measured_dev_amplitude_", "simulated_dev_amplitude_", "measured_floor_"})
      ocols.push_back(name + "_" + part + unit);
    ocols.push_back(name + "_significant");
    ocols.push_back(name + "_factor");
    orders.push_back(&m["magnification"]["orders"]);
  }
  CsvWriter ord(dir / (stem + "_orders.csv"), notes, ocols);
  const std::size_t n_orders = orders.empty() ? 0 : orders[0]->size();
  for (std::size_t k = 0; k < n_orders; ++k) {
    std::vector<std::string> v{std::to_string(k + 1)};
    for (const json* o : orders) {
      const json& e = (*o)[k];
      for (const char* key : {"measured_amplitude", "simulated_amplitude", "measured_floor", "significant", "factor"})
        v.push_back(cell(e[key]));
    }
    ord.text_row(v);
  }

  // Impacts.
  CsvWriter imp(dir / (stem + "_impacts.csv"), notes,
                {"crank_deg", "revolution", "normal_impulse_Ns", "pin_deg", "bushing_deg", "global_deg"});
  for (const json& i : r["impacts"]) {
    const std::vector<double> v{i["crank_deg"], i["revolution"], i["normal_impulse_Ns"], i["pin_deg"],
                                i["bushing_deg"], i["global_deg"]};
    imp.row(v);
  }
  series.commit();
  ord.commit();
  imp.commit();
}

}  // namespace

std::string series_made_by(const std::string& version, const std::string& command) {
  return "made by fourbar " + version + ": " + command;
}

void write_recording_series(const json& r, const std::filesystem::path& out_dir, const std::string& made_by,
                            bool csv_comments) {
  if (is_analysed(r)) write_recording(made_by, r, out_dir / "series", csv_comments);
}

void write_session_series(const json& session, const std::filesystem::path& out_dir, bool csv_comments) {
  std::vector<std::string> c;
  if (csv_comments)
    c.push_back("made by fourbar " + session["version"].get<std::string>() + ": " + session["command"].get<std::string>());
  write_summary_table(session, out_dir, c);
  CsvWriter sev(out_dir / "session_severity.csv", c,
                {"clearance_mm", "speed_rpm", "measured_alpha3_fluctuation_rms_rad_s2",
                 "measured_alpha4_fluctuation_rms_rad_s2", "simulated_alpha3_fluctuation_rms_rad_s2",
                 "impacts_per_rev", "sum_normal_impulse_per_rev_Ns", "impact_index_Ns", "magnification_alpha3",
                 "recording", "status"});
  // Each point's recording status: "ok", or "check set-up" when the set-up
  // check found a likely manifest mistake (its numbers are not to be trusted).
  auto status_of = [&session](const std::string& name) {
    for (const json& r : session["recordings"])
      if (r.value("name", "") == name) return r.value("status", "");
    return std::string();
  };
  for (const json& g : session["severity"]["by_speed"])
    for (const json& p : g["points"]) {
      // The clearance as the manifest gives it (0.0254, not 0.025400000000000002 after mm -> m -> mm).
      std::vector<std::string> v{format_input_decimal(p["clearance_mm"].get<double>())};
      for (const char* key : {"speed_rpm", "measured_alpha3_fluctuation_rms", "measured_alpha4_fluctuation_rms",
                              "simulated_alpha3_fluctuation_rms", "impacts_per_rev", "sum_normal_impulse_per_rev_Ns",
                              "impact_index_Ns", "magnification_alpha3"})
        v.push_back(cell(p[key]));
      v.push_back(p["recording"].get<std::string>());
      v.push_back(status_of(v.back()));
      sev.text_row(v);
    }
  sev.commit();
}

}  // namespace fourbar
