// The step trace (LinkageSimulator::trace_steps, state_component): every step
// is recorded with the state component whose weighted local-error estimate
// was the largest, and the components are named from the model's layout.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "sim/drive/crank_motion.hpp"
#include "sim/linkage/linkage_simulator.hpp"

namespace fourbar {
namespace {

TEST(LinkageStepTrace, NamesEveryComponentOnceFromTheLayout) {
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  LinkageSpec s;
  s.clearance_m = {0.1e-3, 0.254e-3, 0};  // A and B: one joint is cut, the other has offsets
  s.law = {1e10, 1.5, DampingLaw::calibrated, 0.5};
  s.elastic = {false, true, true};
  s.elastic_modes = 2;
  const LinkageModel model = build_linkage(rig, s);
  const ConstantSpeedCrank crank(0.0, 36.65);
  const LinkageSimulator sim(model, crank);
  const auto n = static_cast<std::size_t>(model.coordinates());
  ASSERT_EQ(n, 2U + 2U + 4U);  // θ3, θ4, one joint's offset, 2 + 2 modes
  std::set<std::string> names;
  for (std::size_t i = 0; i < 2 * n; ++i) names.insert(sim.state_component(i));
  EXPECT_EQ(names.size(), 2 * n);
  for (const char* want : {"theta3", "theta4 rate", "coupler eta1", "coupler eta2 rate", "rocker eta2"})
    EXPECT_EQ(names.count(want), 1U) << want;
  EXPECT_EQ(std::count_if(names.begin(), names.end(), [](const std::string& x) { return x.find(" d_x") != std::string::npos; }), 2);
  EXPECT_EQ(sim.state_component(2 * n), "books");
}

TEST(LinkageStepTrace, AFreelyRingingModeSetsTheSteps) {
  // Crank held, every pin ideal, no gravity, the coupler's one mode started
  // (test_free_vibration.cpp): θ3 and θ4 are prescribed, so the mode is all
  // that moves and it must be what limits the step. (With three modes and
  // the second started, the third, at rest to 1e-6 of it, sets the step: its
  // absolute tolerance, in its own static-deflection unit, is far tighter
  // than the started mode's relative one.)
  Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  rig.gravity_m_s2 = 0;
  LinkageSpec s;
  s.law = {1e10, 1.5, DampingLaw::calibrated, 0.5};
  s.tolerance = 1e-9;
  s.elastic = {false, true, false};
  s.elastic_modes = 1;
  const LinkageModel model = build_linkage(rig, s);
  const ConstantSpeedCrank held(1.0, 0.0);
  LinkageSimulator sim(model, held);
  std::vector<LinkageStepTrace> trace;
  sim.trace_steps(&trace);
  LinkageStart start;
  start.modal_m[0][0] = 1e-5;
  sim.start(0.0, start);
  sim.advance_to(8e-3);  // five periods at 612 Hz
  ASSERT_EQ(trace.size(), sim.diagnostics().steps);
  std::map<std::string, int> by;
  double previous = 0;
  for (const LinkageStepTrace& r : trace) {
    EXPECT_GT(r.end_time_s, previous);
    EXPECT_GT(r.step_s, 0);
    EXPECT_NEAR(r.end_time_s - previous, r.step_s, 1e-12);
    EXPECT_GE(r.order, 1);
    EXPECT_LE(r.order, 5);  // BDF
    previous = r.end_time_s;
    ++by[sim.state_component(r.limiting)];
  }
  const int own = by["coupler eta1"] + by["coupler eta1 rate"];
  EXPECT_GT(own, 0.9 * static_cast<double>(trace.size())) << "steps " << trace.size() << ", own " << own;
  // Stopping the trace stops the records.
  sim.trace_steps(nullptr);
  const std::size_t kept = trace.size();
  sim.advance_to(9e-3);
  EXPECT_EQ(trace.size(), kept);
}

}  // namespace
}  // namespace fourbar
