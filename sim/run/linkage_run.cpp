#include "sim/run/linkage_run.hpp"

#include <cmath>
#include <string>

#include "common/error.hpp"
#include "common/number_text.hpp"
#include "common/units.hpp"
#include "sim/run/run.hpp"
#include "sim/drive/tabulated_crank.hpp"
#include "sim/outputs.hpp"

namespace fourbar {

std::unique_ptr<CrankMotion> linkage_crank(const Scene& scene) {
  if (!scene.linkage.crank_table.empty()) return TabulatedCrank::from_csv(scene.linkage.crank_table);
  return std::make_unique<ConstantSpeedCrank>(scene.start_angle_rad, scene.crank_speed_rad_s);
}

namespace {

/// When the output starts (the crank has turned `warmup_turns` times from its
/// start, in the direction it turns: a table's, from its start to its end, so
/// that a recording that starts at rest counts too) and how long it spans.
void set_output_window(const Scene& scene, const CrankMotion& crank, int warmup_turns, LinkageRun& out) {
  const auto* table = dynamic_cast<const TabulatedCrank*>(&crank);
  const double end = table ? scene.linkage.duration_s.value_or(table->end_time_s()) : 0.0;
  if (warmup_turns > 0) {
    const CrankState c0 = crank.at(0.0);
    const double turned = table ? crank.at(end).angle_rad - c0.angle_rad : c0.speed_rad_s;
    const double dir = turned < 0 ? -1.0 : 1.0;
    const double angle = c0.angle_rad + dir * units::kTwoPi * warmup_turns;
    try {
      out.output_start_s = crank.time_at_angle(angle);
    } catch (const RunError&) {
      out.output_start_s = end;  // never reached
    }
    if (table && !(out.output_start_s < end))
      throw InputError("sim: --warmup-turns " + std::to_string(warmup_turns) + ": the crank table " +
                       scene.linkage.crank_table.string() + " does not turn " + std::to_string(warmup_turns) +
                       " times before its end at " + format_double(end) +
                       " s; give fewer warm-up turns (0 starts the output at the table's start)");
  }
  out.duration_s =
      table ? end - out.output_start_s : scene.revolutions * (units::kTwoPi / std::abs(scene.crank_speed_rad_s));
}

const char* const kLinkNames[] = {"coupler", "rocker"};

/// The series' columns: crank_deg, the scene's outputs, the per-joint
/// columns, the sensors, each elastic link's modes and mid-span deflection.
std::vector<std::string> series_names(const Scene& scene, const LinkageModel& model) {
  std::vector<std::string> names{"crank_deg"};
  names.insert(names.end(), scene.outputs.begin(), scene.outputs.end());
  const char* per_joint[] = {"gap_mm", "penetration_mm", "contact_force_N", "fx_N", "fy_N"};
  for (int j : model.clearance_joints())
    for (const char* p : per_joint) names.push_back(std::string(to_string(static_cast<LinkJoint>(j))) + "_" + p);
  for (const LinkSensor& x : scene.linkage.sensors)
    names.push_back(std::string(kLinkNames[x.body - 1]) + "_acc_" + format_double(x.distance_m * 1e3) + "mm_" +
                    format_double(x.offset_m * 1e3) + "mm_m_s2");
  for (int b = 1; b < kBodies; ++b)
    if (const ElasticLink* link = model.elastic(b)) {
      for (int k = 0; k < link->modes(); ++k)
        names.push_back(std::string(kLinkNames[b - 1]) + "_eta" + std::to_string(k + 1) + "_um");
      names.push_back(std::string(kLinkNames[b - 1]) + "_midspan_deflection_um");
    }
  return names;
}

/// The samples as the series' `rows` rows (series_names' order); the angles
/// made continuous from row to row.
void fill_series(const Scene& scene, const LinkageModel& model, const std::vector<LinkageSample>& samples,
                 std::size_t rows, SeriesTable& series) {
  std::vector<const ClearanceOutputSpec*> specs;
  for (const std::string& name : scene.outputs) specs.push_back(find_clearance_output(name));
  series.columns.assign(series.names.size(), std::vector<double>(rows));
  const auto main = static_cast<std::size_t>(model.cut_joint());
  double th2 = 0, th3 = 0, th4 = 0, eta = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const LinkageSample& s = samples[i];
    auto continuous = [&](double& acc, double a) { acc = i == 0 ? a : acc + std::remainder(a - acc, units::kTwoPi); };
    continuous(th2, s.crank.angle_rad);
    continuous(th3, s.theta3_rad);
    continuous(th4, s.theta4_rad);
    continuous(eta, s.joint[main].eta_rad);
    ClearanceSample c;
    c.time_s = s.time_s;
    c.crank = s.crank;
    c.crank.angle_rad = th2;
    c.mode = s.in_contact ? ContactMode::following : ContactMode::free_flight;
    c.links = {unit(s.theta3_rad), unit(s.theta4_rad), s.omega3_rad_s, s.omega4_rad_s};
    c.alpha3_rad_s2 = s.alpha3_rad_s2;
    c.alpha4_rad_s2 = s.alpha4_rad_s2;
    c.crank_torque_Nm = s.crank_torque_Nm;
    c.kinetic_energy_J = s.kinetic_energy_J;
    c.potential_energy_J = s.potential_energy_J;
    c.bearing_force_N = s.joint[main].pin_force_N;
    c.normal_force_N = s.joint[main].normal_force_N;
    c.gap_m = s.joint[main].gap_m;
    c.penetration_m = s.joint[main].penetration_m;
    std::size_t col = 0;
    series.columns[col++][i] = units::rad_to_deg(th2);
    for (const ClearanceOutputSpec* spec : specs) series.columns[col++][i] = clearance_column_value(*spec, c, th3, th4, eta);
    for (int j : model.clearance_joints()) {
      const JointSample& js = s.joint[static_cast<std::size_t>(j)];
      for (double v : {units::m_to_mm(js.gap_m), units::m_to_mm(js.penetration_m), js.normal_force_N, js.pin_force_N.x,
                       js.pin_force_N.y})
        series.columns[col++][i] = v;
    }
    for (double v : s.sensor_m_s2) series.columns[col++][i] = v;
    for (int b = 1; b < kBodies; ++b)
      if (const ElasticLink* link = model.elastic(b)) {
        const auto bu = static_cast<std::size_t>(b - 1);
        for (int k = 0; k < link->modes(); ++k) series.columns[col++][i] = s.modal_m[bu][static_cast<std::size_t>(k)] * 1e6;
        series.columns[col++][i] = s.midspan_deflection_m[bu] * 1e6;
      }
  }
}

}  // namespace

LinkageRun run_linkage(const Scene& scene, int warmup_turns) {
  const LinkageModel model = build_linkage(*scene.rig, scene.linkage.spec);
  if (model.all_ideal())
    throw InputError(
        "[linkage]: no joint has a clearance; give one of crank_coupler_radial_mm, coupler_rocker_radial_mm, "
        "rocker_ground_radial_mm > 0 (or use model = \"nominal\" for the ideal linkage)");
  if (warmup_turns < 0) throw InputError("linkage run: warm-up turns " + std::to_string(warmup_turns) + " must be >= 0");
  const std::unique_ptr<CrankMotion> crank = linkage_crank(scene);
  LinkageRun out;
  out.warmup_turns = warmup_turns;
  set_output_window(scene, *crank, warmup_turns, out);
  const auto rows = static_cast<std::size_t>(scene.revolutions) * static_cast<std::size_t>(scene.samples_per_revolution);
  std::vector<double> times(rows + 1);
  for (std::size_t i = 0; i <= rows; ++i)
    times[i] = out.output_start_s + out.duration_s * static_cast<double>(i) / static_cast<double>(rows);
  LinkageSimulator sim(model, *crank);
  sim.set_sample_times(times);
  sim.set_sensors(scene.linkage.sensors);
  sim.start_centred(0.0);
  sim.advance_to(times.back());
  out.contacts = sim.contacts();
  out.diagnostics = sim.diagnostics();
  out.clearance_joints = model.clearance_joints();
  out.integrator_counters = sim.integrator_counters();
  out.series.names = series_names(scene, model);
  fill_series(scene, model, sim.samples(), times.size(), out.series);
  return out;
}

}  // namespace fourbar
