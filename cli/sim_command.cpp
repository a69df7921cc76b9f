// `fourbar sim SCENE.toml --out DIR`: run a scene, write series.csv and summary.json.

#include <cmath>
#include <iostream>
#include <memory>

#include "cli/command.hpp"
#include "cli/sim_help.hpp"
#include "common/atomic_output.hpp"
#include "common/csv_writer.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/number_text.hpp"
#include "common/json_text.hpp"
#include "common/provenance.hpp"
#include "common/units.hpp"
#include "sim/run/run.hpp"
#include "sim/run/linkage_run.hpp"
#include "sim/nominal/run.hpp"
#include "sim/outputs.hpp"
#include "mechanism/rig_report.hpp"

namespace po = boost::program_options;

namespace fourbar::cli {

namespace {

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

// The writers below return their file written but not committed: the
// caller commits every file of a run together at the end, so an interrupted
// or failed run leaves none of them new beside old ones.
using PendingFile = std::unique_ptr<CsvWriter>;

PendingFile write_series(const std::filesystem::path& csv_path, const Provenance& prov, const SeriesTable& table) {
  auto csv = std::make_unique<CsvWriter>(csv_path, prov.csv_comment_lines(), table.names);
  std::vector<double> row(table.names.size());
  for (std::size_t i = 0; i < table.rows(); ++i) {
    for (std::size_t c = 0; c < row.size(); ++c) row[c] = table.columns[c][i];
    csv->row(row);
  }
  return csv;
}

/// Three-mode impacts: one row per impact faster than the settle speed. A
/// rebound slower than the settle speed is stopped by a plastic (pulling)
/// impulse; the row's impulse, loss and motor impulse are the totals with it.
PendingFile write_impacts(const std::filesystem::path& path, const Provenance& prov, const ClearanceRun& run) {
  auto csv = std::make_unique<CsvWriter>(path, prov.csv_comment_lines(), std::vector<std::string>
                {"crank_deg", "time_s", "revolution", "normal_impulse_Ns", "tangential_impulse_Ns", "eta_deg",
                 "approach_speed_m_s", "rebound_speed_m_s", "slip_speed_before_m_s", "slip_speed_after_m_s",
                 "stuck", "energy_loss_J", "motor_impulse_Nms", "mode_after"});
  for (const ImpactRecord& r : run.impacts) {
    const ImpactResult& x = r.result;
    const double row[] = {units::rad_to_deg(r.crank_angle_rad), r.time_s, static_cast<double>(r.revolution),
                          x.normal_impulse_Ns + r.settle_normal_impulse_Ns, x.tangential_impulse_Ns,
                          units::rad_to_deg(r.eta_rad), x.normal_speed_before_m_s, -x.normal_speed_after_m_s,
                          x.tangential_speed_before_m_s, x.tangential_speed_after_m_s, x.stuck ? 1.0 : 0.0,
                          x.energy_loss_J + r.settle_energy_loss_J, x.motor_impulse_Nms + r.settle_motor_impulse_Nms,
                          r.mode_after == ContactMode::following ? 1.0 : 0.0};
    csv->row(row);
  }
  return csv;
}

/// Compliant contacts: one row per contact, onset to release.
PendingFile write_contacts(const std::filesystem::path& path, const Provenance& prov, const ClearanceRun& run) {
  auto csv = std::make_unique<CsvWriter>(path, prov.csv_comment_lines(), std::vector<std::string>
                {"crank_deg", "time_s", "revolution", "normal_impulse_Ns", "contact_impulse_Ns",
                 "tangential_impulse_Ns", "eta_deg", "approach_speed_m_s", "rebound_speed_m_s", "peak_force_N",
                 "contact_duration_s", "max_penetration_mm", "energy_loss_J", "mode_after"});
  for (const ImpactRecord& r : run.impacts) {
    const ImpactResult& x = r.result;
    const double row[] = {units::rad_to_deg(r.crank_angle_rad), r.time_s, static_cast<double>(r.revolution),
                          x.normal_impulse_Ns, r.contact_impulse_Ns, x.tangential_impulse_Ns,
                          units::rad_to_deg(r.eta_rad), x.normal_speed_before_m_s, -x.normal_speed_after_m_s,
                          r.peak_force_N, r.contact_duration_s, units::m_to_mm(r.max_penetration_m), x.energy_loss_J,
                          r.mode_after == ContactMode::following ? 1.0 : 0.0};
    csv->row(row);
  }
  return csv;
}

PendingFile write_revolutions(const std::filesystem::path& path, const Provenance& prov, const ClearanceRun& run,
                              double start_angle_rad, double direction) {
  auto csv = std::make_unique<CsvWriter>(path, prov.csv_comment_lines(), std::vector<std::string>
                {"crank_deg", "revolution", "impacts", "sum_normal_impulse_Ns", "impact_index_Ns", "contact_losses",
                 "following_share", "free_flight_share", "alpha3_deviation_rms_rad_s2"});
  for (const RevolutionRecord& r : run.revolutions) {
    const double span = r.end_time_s - r.start_time_s;
    const double row[] = {units::rad_to_deg(start_angle_rad + direction * units::kTwoPi * r.index),
                          static_cast<double>(r.index), static_cast<double>(r.impacts), r.sum_normal_impulse_Ns,
                          r.impacts ? r.sum_normal_impulse_Ns / r.impacts : 0.0, static_cast<double>(r.contact_losses),
                          r.following_time_s / span, r.free_time_s / span, r.alpha3_deviation_rms_rad_s2};
    csv->row(row);
  }
  return csv;
}

nlohmann::json clearance_json(const Scene& scene, const ClearanceRun& run) {
  const ClearanceSettings& c = scene.clearance;
  const ClearanceDiagnostics& d = run.diagnostics;
  nlohmann::json j;
  j["settings"] = {{"radial_mm", units::m_to_mm(run.clearance_m)},
                   {"restitution", c.restitution},
                   {"contact", to_string(c.contact)},
                   {"friction_coefficient", c.friction_coefficient},
                   {"following_friction", c.following_friction},
                   {"tolerance", c.tolerance},
                   {"integrator", to_string(c.integrator)},
                   {"settle_speed_mm_s", c.settle_speed_m_s * 1e3},
                   {"steady_state", c.steady_state},
                   {"steady_criterion", to_string(c.steady_criterion)},
                   {"statistical_window", c.statistical_window},
                   {"statistical_tolerance", c.statistical_tolerance},
                   {"max_revolutions", c.max_revolutions}};
  if (c.model == ClearanceKind::compliant) {
    const CompliantSettings& k = c.compliant;
    for (const char* key : {"contact", "following_friction", "integrator", "settle_speed_mm_s"}) j["settings"].erase(key);
    j["settings"]["model"] = "compliant";
    j["settings"]["integrator"] = "cvode-bdf";
    j["settings"]["damping"] = to_string(k.damping);
    j["settings"]["contact_stiffness_N_per_m_n"] = k.stiffness_N_per_m_n;
    j["settings"]["contact_stiffness_source"] = k.stiffness_given ? "given" : "rig bearing (conformal cylinders)";
    j["settings"]["contact_exponent"] = k.exponent;
    j["settings"]["friction_stick_speed_mm_s"] = k.friction_stick_speed_m_s * 1e3;
    j["settings"]["friction_slip_speed_mm_s"] = k.friction_slip_speed_m_s * 1e3;
    j["settings"]["damping_floor_speed_mm_s"] = k.damping_floor_speed_m_s * 1e3;
    j["settings"]["settle_speed_mm_s"] = c.settle_speed_m_s * 1e3;
    if (k.film.viscosity_Pa_s > 0) {
      j["settings"]["lubricant_viscosity_Pa_s"] = k.film.viscosity_Pa_s;
      j["settings"]["film"] = to_string(k.film.extent);
      j["settings"]["film_break_eccentricity"] = k.film.break_eccentricity;
      j["settings"]["journal_radius_mm"] = k.film.radius_m * 1e3;
      j["settings"]["bearing_length_mm"] = k.film.length_m * 1e3;
    }
  }
  // Which criterion fired: "periodic with period k", "statistically steady
  // after N turns", or none within max_revolutions.
  const StationarityResult& st = run.statistics;
  const bool compared = st.worst_relative_difference < 1e300;
  nlohmann::json windows = nlohmann::json::object();
  if (compared)
    for (std::size_t q = 0; q < TurnQuantities::kCount; ++q)
      windows[TurnQuantities::kNames[q]] = {{"earlier_mean", st.earlier_mean[q]}, {"later_mean", st.later_mean[q]}};
  std::string verdict = "none within max_revolutions";
  if (run.steady_found == SteadyFound::periodic)
    verdict = "periodic with period " + std::to_string(run.steady_period) + " after " +
              std::to_string(run.first_output_revolution) + " turns";
  if (run.steady_found == SteadyFound::statistical)
    verdict = "statistically steady after " + std::to_string(run.first_output_revolution) + " turns";
  j["steady_state"] = {{"requested", c.steady_state},
                       {"reached", run.steady_state_reached},
                       {"criterion_fired", to_string(run.steady_found)},
                       {"verdict", c.steady_state ? verdict : "not requested"},
                       {"statistical",
                        {{"window_revolutions", c.statistical_window},
                         {"worst_relative_difference", compared ? nlohmann::json(st.worst_relative_difference)
                                                                : nlohmann::json(nullptr)},
                         {"worst_relative_standard_error", compared ? nlohmann::json(st.worst_relative_standard_error)
                                                                    : nlohmann::json(nullptr)},
                         {"window_means", windows}}},
                       {"period_revolutions", run.steady_period},
                       {"last_difference", c.steady_state ? run.steady_difference : 0.0},
                       {"first_output_revolution", run.first_output_revolution},
                       {"revolutions_simulated", run.revolutions_simulated}};
  j["events"] = {{"impacts", d.impacts},
                 {"touches_below_settle_speed", d.touches},
                 {"contact_losses", d.contact_losses},
                 {"settles_into_following", d.settles},
                 {"impacts_without_solution_of_law", d.degenerate_impacts},
                 {"impacts_gaining_energy", d.energy_gaining_impacts},
                 {"wall_sticks", d.sticks},
                 {"wall_slip_stops", d.slip_stops},
                 {"integrator_steps", d.steps}};
  j["time_share"] = {{"following", d.time_following_s / (d.time_following_s + d.time_free_s)},
                     {"stuck_on_wall", d.time_stuck_s / (d.time_following_s + d.time_free_s)},
                     {"free_flight", d.time_free_s / (d.time_following_s + d.time_free_s)}};
  j["drift"] = {{"max_contact_circle_error_rel", d.max_contact_circle_error},
                {"max_contact_normal_speed_m_s", d.max_contact_normal_speed_m_s},
                {"max_penetration_rel", d.max_penetration}};
  j["energy"] = {{"start_J", d.energy_start_J},
                 {"end_J", d.energy_end_J},
                 {"crank_work_J", d.crank_work_J},
                 {"motor_impulse_work_J", d.motor_impulse_work_J},
                 {"impact_loss_J", d.impact_loss_J},
                 {"friction_loss_J", d.friction_loss_J},
                 {"residual_J", d.energy_residual_J},
                 {"max_residual_J", d.max_energy_residual_J},
                 {"scale_J", d.energy_scale_J},
                 {"residual_rel", std::abs(d.energy_residual_J) / d.energy_scale_J}};
  if (c.model == ClearanceKind::compliant) {
    j["energy"]["contact_damping_loss_J"] = d.impact_loss_J;
    j["energy"]["elastic_energy_end_J"] = d.elastic_energy_end_J;
    if (c.compliant.film.viscosity_Pa_s > 0) j["energy"]["film_loss_J"] = d.film_loss_J;
  }
  return j;
}

/// Linkage contacts: one row per contact of any joint, onset to release.
PendingFile write_linkage_contacts(const std::filesystem::path& path, const Provenance& prov, const LinkageRun& run) {
  auto csv = std::make_unique<CsvWriter>(path, prov.csv_comment_lines(), std::vector<std::string>
                {"joint", "time_s", "approach_speed_m_s", "crank_deg", "impact", "eta_deg", "slip_speed_m_s",
                 "peak_force_N", "max_penetration_mm", "contact_duration_s", "normal_impulse_Ns", "contact_impulse_Ns",
                 "energy_loss_J", "contact_lost", "release_time_s", "release_crank_deg", "release_eta_deg"});
  for (const LinkageContact& r : run.contacts) {
    const double v[] = {r.time_s, r.approach_speed_m_s, units::rad_to_deg(r.crank_angle_rad), r.impact ? 1.0 : 0.0,
                        units::rad_to_deg(r.eta_rad), r.tangential_speed_m_s, r.peak_force_N,
                        units::m_to_mm(r.max_penetration_m), r.duration_s, r.impact_impulse_Ns, r.contact_impulse_Ns,
                        r.energy_loss_J, r.contact_lost ? 1.0 : 0.0, r.release_time_s,
                        units::rad_to_deg(r.release_crank_angle_rad), units::rad_to_deg(r.release_eta_rad)};
    std::vector<std::string> cells{to_string(static_cast<LinkJoint>(r.joint))};
    for (double x : v) cells.push_back(format_double(x));
    csv->text_row(cells);
  }
  return csv;
}

int write_linkage_run(const Scene& scene, const LinkageRun& run, const std::filesystem::path& dir,
                      const Provenance& prov) {
  std::vector<PendingFile> files;
  files.push_back(write_series(dir / "series.csv", prov, run.series));
  files.push_back(write_linkage_contacts(dir / "impacts.csv", prov, run));
  const LinkageDiagnostics& d = run.diagnostics;
  const LinkageSpec& spec = scene.linkage.spec;
  nlohmann::json joints = nlohmann::json::object();
  for (int j : run.clearance_joints) {
    const LinkageJointBooks& b = d.joint[static_cast<std::size_t>(j)];
    nlohmann::json lost = nlohmann::json::array();
    int impacts = 0;
    for (const LinkageContact& c : run.contacts)
      if (c.joint == j && c.contact_lost)
        lost.push_back({{"time_s", c.release_time_s}, {"crank_deg", units::rad_to_deg(c.release_crank_angle_rad)},
                        {"eta_deg", units::rad_to_deg(c.release_eta_rad)}});
    for (const LinkageContact& c : run.contacts) impacts += c.joint == j && c.impact;
    const double span = b.free_time_s + b.contact_time_s;
    joints[to_string(static_cast<LinkJoint>(j))] = {
        {"radial_mm", units::m_to_mm(spec.clearance_m[static_cast<std::size_t>(j)])},
        {"impacts", impacts},
        {"touches_below_settle_speed", b.touches},
        {"contact_losses", b.contact_losses},
        {"free_flight_share", span > 0 ? b.free_time_s / span : 0.0},
        {"contact_share", span > 0 ? b.contact_time_s / span : 0.0},
        {"max_penetration_mm", units::m_to_mm(b.max_penetration_m)},
        {"contact_damping_loss_J", b.contact_loss_J},
        {"friction_loss_J", b.friction_loss_J},
        {"film_loss_J", b.film_loss_J},
        {"contact_lost_at", lost}};
  }
  nlohmann::json summary;
  summary["provenance"] = prov.to_json();
  summary["rig"] = to_json(*scene.rig, report_rig(*scene.rig));
  summary["scene"] = {{"file", scene.source.string()},
                      {"model", "linkage"},
                      {"crank_speed_rpm", units::rad_s_to_rpm(scene.crank_speed_rad_s)},
                      {"crank_motion", scene.linkage.crank_table.string()},
                      {"duration_s", run.duration_s},
                      {"warmup_revolutions", run.warmup_turns},
                      {"output_start_s", run.output_start_s},
                      {"revolutions", scene.revolutions},
                      {"samples_per_revolution", scene.samples_per_revolution}};
  summary["linkage"] = {{"settings",
                         {{"restitution", spec.law.restitution},
                          {"damping", to_string(spec.law.damping)},
                          {"contact_stiffness_N_per_m_n", spec.law.stiffness},
                          {"contact_exponent", spec.law.exponent},
                          {"friction_coefficient", spec.friction.mu},
                          {"tolerance", spec.tolerance},
                          {"settle_speed_mm_s", spec.settle_speed_m_s * 1e3},
                          {"integrator", "cvode-bdf"}}},
                        {"joints", joints},
                        {"energy",
                         {{"start_J", d.energy_start_J},
                          {"end_J", d.energy_end_J},
                          {"crank_work_J", d.crank_work_J},
                          {"dissipated_J", d.dissipated_J},
                          {"modal_damping_J", d.modal_damping_loss_J},
                          {"residual_J", d.energy_residual_J},
                          {"max_residual_J", d.max_energy_residual_J},
                          {"scale_J", d.energy_scale_J},
                          {"residual_rel", std::abs(d.energy_residual_J) / d.energy_scale_J}}},
                        {"integrator_steps", d.steps},
                        {"integrator_counters", run.integrator_counters}};
  summary["series"] = {{"file", "series.csv"}, {"rows", run.series.rows()}, {"columns", column_stats(run.series)}};
  const auto json_path = dir / "summary.json";
  AtomicOutput json(json_path);
  json.stream() << json_text(summary, 2) << "\n";
  for (auto& f : files) f->commit();
  json.commit();
  std::cout << "wrote " << (dir / "series.csv").string() << " (" << run.series.rows() << " rows x "
            << run.series.names.size() << " columns), impacts.csv (" << run.contacts.size() << " contacts) and "
            << json_path.string() << "\n";
  return 0;
}
/// Warm-up turns of the report's matched theory ([theory] warmup_revolutions' default).
constexpr int kReportWarmupTurns = 20;
/// Turns the report's matched theory averages: fewer give a per-turn count
/// that varies from run to run (chaotic impacts).
constexpr int kReportAveragedTurns = 20;

/// What the output turns hold: impacts and impacts per turn after the warm-up.
struct OutputTurns {
  int first = 0, turns = 0;
  std::size_t impacts = 0;
};

OutputTurns output_turns(const ClearanceRun& run, int turns) {
  OutputTurns o{run.first_output_revolution, turns, 0};
  for (const ImpactRecord& r : run.impacts) o.impacts += r.revolution >= o.first && r.revolution < o.first + turns;
  return o;
}

int write_clearance_run(const Scene& scene, const ClearanceRun& run, const std::filesystem::path& dir,
                        const Provenance& prov, int warmup_turns) {
  const auto csv_path = dir / "series.csv";
  std::vector<PendingFile> files;
  files.push_back(write_series(csv_path, prov, run.series));
  std::string extra;
  if (scene.clearance.write_impacts) {
    files.push_back(scene.clearance.model == ClearanceKind::compliant ? write_contacts(dir / "impacts.csv", prov, run)
                                                                       : write_impacts(dir / "impacts.csv", prov, run));
    extra += ", impacts.csv (" + std::to_string(run.impacts.size()) + " impacts)";
  }
  if (scene.clearance.write_revolutions) {
    files.push_back(
        write_revolutions(dir / "revolutions.csv", prov, run, scene.start_angle_rad, scene.crank_speed_rad_s > 0 ? 1 : -1));
    extra += ", revolutions.csv";
  }
  const bool steady = scene.clearance.steady_state;
  const OutputTurns out = output_turns(run, scene.revolutions);
  const double per_turn = static_cast<double>(out.impacts) / scene.revolutions;
  nlohmann::json summary;
  summary["provenance"] = prov.to_json();
  summary["rig"] = to_json(*scene.rig, report_rig(*scene.rig));
  summary["scene"] = {{"file", scene.source.string()},
                      {"model", "clearance"},
                      {"crank_speed_rpm", units::rad_s_to_rpm(scene.crank_speed_rad_s)},
                      {"start_angle_deg", units::rad_to_deg(scene.start_angle_rad)},
                      {"revolutions", scene.revolutions},
                      {"warmup_revolutions", steady ? 0 : warmup_turns},
                      {"samples_per_revolution", scene.samples_per_revolution}};
  summary["clearance"] = clearance_json(scene, run);
  summary["clearance"]["output_turns"] = {{"first_revolution", out.first},
                                          {"revolutions", out.turns},
                                          {"impacts", out.impacts},
                                          {"impacts_per_rev", per_turn}};
  summary["series"] = {{"file", "series.csv"}, {"rows", run.series.rows()}, {"columns", column_stats(run.series)}};
  const auto json_path = dir / "summary.json";
  AtomicOutput json(json_path);
  json.stream() << json_text(summary, 2) << "\n";
  for (auto& f : files) f->commit();
  json.commit();
  std::cout << "wrote " << csv_path.string() << " (" << run.series.rows() << " rows x " << run.series.names.size()
            << " columns)" << extra << " and " << json_path.string() << "\n";
  const std::string turns = std::to_string(scene.revolutions) + (scene.revolutions == 1 ? " turn" : " turns");
  std::cout << out.impacts << " impacts in the " << turns << " output (" << format_number(per_turn, 3) << " per turn)";
  if (steady) std::cout << ", after the steady-state search's " << out.first << " turns\n";
  else if (out.first > 0) std::cout << ", after " << out.first << " warm-up turns (not output)\n";
  else std::cout << ", from the start (no warm-up)\n";
  // Counts from the turns after the start are the start transient: the
  // report's matched theory runs kReportWarmupTurns turns first and averages
  // kReportAveragedTurns.
  if (!steady && out.first < kReportWarmupTurns)
    std::cerr << "fourbar: note: sim: " << out.impacts << " impacts in " << turns
              << (out.first == 0 ? " from the start" : " after " + std::to_string(out.first) + " warm-up turns")
              << ": the transient after the start, not the steady response (the report's model runs "
              << kReportWarmupTurns << " warm-up turns before it counts; --warmup-turns " << kReportWarmupTurns
              << " is the default)\n";
  if (scene.revolutions < kReportAveragedTurns)
    std::cerr << "fourbar: note: sim: " << format_number(per_turn, 3) << " impacts per turn from " << turns
              << " only: the count varies from turn to turn (the report's model averages " << kReportAveragedTurns
              << "); for a mean with its standard error set revolutions = " << kReportAveragedTurns
              << " or more, or use fourbar sweep\n";
  return 0;
}

}  // namespace

int run_sim(const Invocation& inv) {
  std::string scene_file, out_dir;
  bool csv_comments = false;
  long long warmup_turns = kReportWarmupTurns;
  po::options_description opts("options");
  opts.add_options()("scene", po::value(&scene_file)->required(), "scene file (TOML)")(
      "out,o", po::value(&out_dir), "output folder (default: out/<scene name>)")(
      "warmup-turns", po::value(&warmup_turns),
      "turns run first and not output. model = \"clearance\": default 20, the report's model's warm-up "
      "(ignored with steady_state); model = \"linkage\": default 0. 0: the output starts from the start, as "
      "the thesis's first-turn figures and a crank table's own times");
  add_csv_comments_option(opts, csv_comments);
  po::positional_options_description pos;
  pos.add("scene", 1);
  po::variables_map vm;
  if (!parse_arguments("sim", "SCENE.toml [--out DIR] [--warmup-turns N] [--csv-comments]",
                       "Writes DIR/series.csv (crank_deg, then the scene's outputs, one row per\n"
                       "sample, revolutions*samples_per_revolution + 1 rows) and DIR/summary.json\n"
                       "(rig class, scene, min/max/rms of every column, provenance). With\n"
                       "model = \"clearance\" also DIR/impacts.csv and DIR/revolutions.csv when the\n"
                       "scene's [clearance] tables ask for them; summary.json then adds events,\n"
                       "constraint drift, energy balance and steady-state results. The CSV files'\n"
                       "provenance is in summary.json (\"provenance\").\n\n"
                       "A clearance scene without steady_state runs --warmup-turns turns (default 20,\n"
                       "as the report's model) before its output; series.csv starts after them,\n"
                       "impacts.csv and revolutions.csv keep them (column revolution), and\n"
                       "summary.json's clearance.output_turns counts the output turns' impacts.\n"
                       "Notes on stderr say when counts come from the transient after the start\n"
                       "(fewer warm-up turns) or from fewer than 20 turns. A linkage scene runs\n"
                       "--warmup-turns turns (default 0) before series.csv's first row;\n"
                       "impacts.csv and summary.json's joints and energy cover the whole run.\n\n" +
                           sim_outputs_help(),
                       opts, pos, inv, vm))
    return 0;

  if (warmup_turns < 0 || warmup_turns > 100000)
    throw InputError("sim: --warmup-turns " + std::to_string(warmup_turns) + " must be between 0 and 100000");
  const Scene scene = load_scene(scene_file);
  if (out_dir.empty()) out_dir = (std::filesystem::path("out") / scene.source.stem()).string();
  ensure_output_dir(out_dir);

  Provenance prov{inv.command_line, {scene.source, scene.rig->source}, csv_comments};
  if (scene.model == Model::clearance) {
    const int warmup = static_cast<int>(warmup_turns);
    return write_clearance_run(scene, run_clearance(scene, true, warmup), out_dir, prov, warmup);
  }
  if (scene.model == Model::linkage) {
    if (!scene.linkage.crank_table.empty()) prov.inputs.push_back(scene.linkage.crank_table);
    // The linkage model starts its output at the start unless warm-up turns are asked for.
    const int warmup = vm.count("warmup-turns") ? static_cast<int>(warmup_turns) : 0;
    return write_linkage_run(scene, run_linkage(scene, warmup), out_dir, prov);
  }

  const SeriesTable table = run_nominal(scene);

  const std::filesystem::path csv_path = std::filesystem::path(out_dir) / "series.csv";
  PendingFile csv = write_series(csv_path, prov, table);

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
  AtomicOutput json(json_path);
  json.stream() << json_text(summary, 2) << "\n";
  csv->commit();
  json.commit();

  std::cout << "wrote " << csv_path.string() << " (" << table.rows() << " rows x " << table.names.size()
            << " columns) and " << json_path.string() << "\n";
  return 0;
}

}  // namespace fourbar::cli
