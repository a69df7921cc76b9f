// One full crank turn of nominal kinematics + kinetostatics at 3600 angles
// (issue target: under 1 ms), and the parts separately. Run:
//   build/bench/bench_nominal --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include "common/units.hpp"
#include "mechanism/kinetostatics.hpp"
#include "sim/nominal/run.hpp"
#include "sim/outputs.hpp"

namespace {

using namespace fourbar;

constexpr int kAngles = 3600;

void BM_KinematicsTurn(benchmark::State& state) {
  const Rig rig = thesis_rig();
  const double w2 = units::rpm_to_rad_s(350);
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < kAngles; ++i) {
      const NominalMotion m = solve_motion(rig, {units::kTwoPi * i / kAngles, w2, 0.0});
      acc += m.alpha3_rad_s2;
    }
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * kAngles);
}
BENCHMARK(BM_KinematicsTurn)->Unit(benchmark::kMicrosecond);

void BM_KinematicsAndLoadsTurn(benchmark::State& state) {
  const Rig rig = thesis_rig();
  const double w2 = units::rpm_to_rad_s(350);
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < kAngles; ++i) {
      const NominalMotion m = solve_motion(rig, {units::kTwoPi * i / kAngles, w2, 0.0});
      const JointLoads l = solve_loads(rig, m);
      acc += l.crank_torque_Nm + l.bearing_N.x;
    }
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * kAngles);
}
BENCHMARK(BM_KinematicsAndLoadsTurn)->Unit(benchmark::kMicrosecond);

// The reference formulation (dense 5×5 Lagrange solve), for the ratio.
void BM_LagrangeReferenceTurn(benchmark::State& state) {
  const Rig rig = thesis_rig();
  const double w2 = units::rpm_to_rad_s(350);
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < kAngles; ++i) {
      const NominalMotion m = solve_motion(rig, {units::kTwoPi * i / kAngles, w2, 0.0});
      acc += solve_loads_lagrange(rig, m).crank_torque_Nm;
    }
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * kAngles);
}
BENCHMARK(BM_LagrangeReferenceTurn)->Unit(benchmark::kMicrosecond);

// The whole `fourbar sim` table for the thesis scene with every output.
void BM_RunNominalAllOutputs(benchmark::State& state) {
  Scene s;
  s.rig = std::make_shared<const Rig>(thesis_rig());
  s.crank_speed_rad_s = units::rpm_to_rad_s(350);
  s.samples_per_revolution = kAngles;
  for (const auto& o : nominal_outputs()) s.outputs.emplace_back(o.name);
  for (auto _ : state) benchmark::DoNotOptimize(run_nominal(s));
}
BENCHMARK(BM_RunNominalAllOutputs)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
