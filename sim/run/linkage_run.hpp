#pragma once
// Pipeline stage "linkage run": a scene with model = "linkage" through the
// linkage simulator. The series has the scene's outputs (the clearance
// model's names; the single-bearing columns gap_mm, penetration_mm,
// contact_force_N, eta_deg, bearing_fx_N, bearing_fy_N, mode describe the
// joint that closes the loop — the coupler–rocker joint whenever it has
// clearance — and mode is 1 while any joint is in contact), then per
// clearance joint J: J_gap_mm, J_penetration_mm, J_contact_force_N,
// J_fx_N, J_fy_N. Rows: revolutions·samples_per_revolution + 1, uniform in
// crank angle at constant speed, uniform in time over duration_s with a
// crank table. Warm-up turns run first and are not sampled: the output
// starts when the crank has turned them (impacts.csv and the books keep
// the whole run).

#include <memory>
#include <vector>

#include "sim/drive/crank_motion.hpp"
#include "sim/linkage/linkage_simulator.hpp"
#include "sim/nominal/run.hpp"
#include "sim/scene.hpp"

namespace fourbar {

struct LinkageRun {
  SeriesTable series;
  std::vector<LinkageContact> contacts;
  LinkageDiagnostics diagnostics;
  std::vector<int> clearance_joints;
  double duration_s = 0;      ///< the output's span
  double output_start_s = 0;  ///< the first row's time: the end of the warm-up turns
  int warmup_turns = 0;
  std::string integrator_counters;
};

/// The scene's crank: constant speed, or the [linkage] crank_motion table.
std::unique_ptr<CrankMotion> linkage_crank(const Scene& scene);
/// `warmup_turns` ≥ 0 turns of the crank before the first output row;
/// InputError when a crank table does not turn that often before its end.
LinkageRun run_linkage(const Scene& scene, int warmup_turns = 0);

}  // namespace fourbar
