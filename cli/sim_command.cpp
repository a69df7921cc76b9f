// `fourbar sim SCENE.toml --out DIR`: run a scene, write series.csv and summary.json.

#include <cmath>
#include <iostream>

#include "cli/command.hpp"
#include "common/atomic_output.hpp"
#include "common/csv_writer.hpp"
#include "common/provenance.hpp"
#include "common/units.hpp"
#include "sim/nominal/run.hpp"
#include "sim/outputs.hpp"
#include "sim/rig_report.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

namespace {

std::string outputs_help() {
  std::string s = "Outputs a scene may request (column names; crank_deg is always first):\n";
  for (const auto& o : nominal_outputs()) {
    s += "  " + std::string(o.name) + std::string(20 - std::min<std::size_t>(19, o.name.size()), ' ') +
         std::string(o.description) + "\n";
  }
  return s;
}

nlohmann::json column_stats(const SeriesTable& t) {
  nlohmann::json cols = nlohmann::json::object();
  for (std::size_t c = 1; c < t.names.size(); ++c) {
    const auto& v = t.columns[c];
    double mn = v[0], mx = v[0], sq = 0;
    for (double x : v) mn = std::min(mn, x), mx = std::max(mx, x), sq += x * x;
    cols[t.names[c]] = {{"min", mn}, {"max", mx}, {"rms", std::sqrt(sq / v.size())}};
  }
  return cols;
}

}  // namespace

int run_sim(const Invocation& inv) {
  std::string scene_file, out_dir;
  po::options_description opts("options");
  opts.add_options()("scene", po::value(&scene_file)->required(), "scene file (TOML)")(
      "out,o", po::value(&out_dir), "output folder (default: out/<scene name>)");
  po::positional_options_description pos;
  pos.add("scene", 1);
  po::variables_map vm;
  if (!parse_arguments("sim", "SCENE.toml [--out DIR]",
                       "Writes DIR/series.csv (crank_deg, then the scene's outputs, one row per\n"
                       "sample, revolutions*samples_per_revolution + 1 rows) and DIR/summary.json\n"
                       "(rig class, scene, min/max/rms of every column, provenance).\n\n" +
                           outputs_help(),
                       opts, pos, inv, vm))
    return 0;

  const Scene scene = load_scene(scene_file);
  if (out_dir.empty()) out_dir = (std::filesystem::path("out") / scene.source.stem()).string();
  ensure_output_dir(out_dir);

  const SeriesTable table = run_nominal(scene);

  Provenance prov{inv.command_line, {scene.source, scene.rig->source}};
  const std::filesystem::path csv_path = std::filesystem::path(out_dir) / "series.csv";
  {
    CsvWriter csv(csv_path, prov.comment_lines(), table.names);
    std::vector<double> row(table.names.size());
    for (std::size_t i = 0; i < table.rows(); ++i) {
      for (std::size_t c = 0; c < row.size(); ++c) row[c] = table.columns[c][i];
      csv.row(row);
    }
    csv.commit();
  }

  nlohmann::json summary;
  summary["provenance"] = prov.to_json();
  summary["rig"] = to_json(*scene.rig, report_rig(*scene.rig));
  summary["scene"] = {{"file", scene.source.string()},
                      {"model", "nominal"},
                      {"crank_speed_rpm", units::rad_s_to_rpm(scene.crank_speed_rad_s)},
                      {"start_angle_deg", units::rad_to_deg(scene.start_angle_rad)},
                      {"revolutions", scene.revolutions},
                      {"samples_per_revolution", scene.samples_per_revolution}};
  summary["series"] = {{"file", "series.csv"}, {"rows", table.rows()}, {"columns", column_stats(table)}};
  const std::filesystem::path json_path = std::filesystem::path(out_dir) / "summary.json";
  write_text_file(json_path, summary.dump(2) + "\n");

  std::cout << "wrote " << csv_path.string() << " (" << table.rows() << " rows x " << table.names.size()
            << " columns) and " << json_path.string() << "\n";
  return 0;
}

}  // namespace fourbar::cli
