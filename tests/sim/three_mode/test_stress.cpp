// Stress subset of the clearance simulator (issue 7) for CI: the extremes of
// the parameter space (clearance 1 µm and 1 mm, e = 0 and 1, rough and
// stick-slip μ = 1, 10 and 3000 rpm, rigs near a toggle, start angles round
// the turn), each checked by stress::run_case (no NaN, no failure or hang,
// drift and energy within the bounds of issue 3). The full sweep is
// bench/stress_clearance. Also: the output sampling does not change the
// motion, and the transmission-angle limits of the near-toggle rigs.

#include <gtest/gtest.h>

#include "sim/run/run.hpp"
#include "sim/three_mode/stress_case.hpp"

namespace fourbar {
namespace {

using stress::Case;

Case base(const std::string& name = "thesis", const Rig& rig = thesis_rig()) {
  Case c;
  c.rig_name = name;
  c.rig = rig;
  c.turns = 2;
  return c;
}

void expect_passes(const Case& c) {
  const stress::Result r = stress::run_case(c);
  EXPECT_TRUE(r.ok) << c.label() << ": " << r.failure;
  EXPECT_LT(r.energy_residual, stress::kEnergyBound) << c.label();
  EXPECT_LT(r.drift, stress::kDriftBound) << c.label();
}

TEST(ClearanceStress, NearToggleRigsReachTheirTransmissionLimits) {
  const RigReport lo = report_rig(stress::near_toggle_rig(5));
  const RigReport hi = report_rig(stress::near_toggle_rig(175));
  EXPECT_NEAR(lo.transmission_min_deg, 5.0, 0.05);
  EXPECT_NEAR(hi.transmission_max_deg, 175.0, 0.05);
  EXPECT_EQ(lo.grashof, GrashofClass::crank_rocker);
  EXPECT_EQ(hi.grashof, GrashofClass::crank_rocker);
}

TEST(ClearanceStress, StartAnglesRoundTheTurn) {
  for (double deg : {0.0, 95.0, 185.0, 275.0}) {
    Case c = base();
    c.start_deg = deg;
    expect_passes(c);
  }
}

TEST(ClearanceStress, ClearanceExtremes) {
  Case tiny = base();
  tiny.clearance_m = 1e-6;
  tiny.restitution = 0;
  tiny.rpm = 3000;
  expect_passes(tiny);
  Case large = base();
  large.clearance_m = 1e-3;
  large.restitution = 1;
  large.rpm = 1000;
  expect_passes(large);
}

TEST(ClearanceStress, TinyClearanceAtSpeedStaysInsideTheBushing) {
  // Regression (issue 7): impacts located to a fixed 1e-13 s let the pin
  // reach 7.7e-9·ξ past the wall at ξ = 1 µm, 3000 rpm, e = 1 (approach
  // speed × 1e-13 s); now located to a few ulps of t.
  Case c = base();
  c.clearance_m = 1e-6;
  c.restitution = 1;
  c.rpm = 3000;
  c.turns = 3;
  const stress::Result r = stress::run_case(c);
  EXPECT_TRUE(r.ok) << r.failure;
  EXPECT_GT(r.impacts, 1000u);
  EXPECT_LT(r.drift, stress::kDriftBound);
}

TEST(ClearanceStress, ImpactLawExtremes) {
  Case rough = base();
  rough.clearance_m = 1e-3;
  rough.contact = ContactLaw::rough;
  expect_passes(rough);
  Case sticky = base();
  sticky.contact = ContactLaw::stick_slip;
  sticky.friction = 1;
  sticky.restitution = 0.75;
  sticky.rpm = 1000;
  expect_passes(sticky);
  Case frictionless = base();
  frictionless.contact = ContactLaw::stick_slip;
  frictionless.friction = 0;
  frictionless.restitution = 0;
  expect_passes(frictionless);
}

TEST(ClearanceStress, SlowCrank) {
  Case c = base();
  c.clearance_m = 1e-3;
  c.restitution = 1;
  c.rpm = 10;
  c.turns = 1;
  expect_passes(c);
}

TEST(ClearanceStress, NearToggle) {
  Case lo = base("toggle-0", stress::near_toggle_rig(5));
  lo.start_deg = 200;
  expect_passes(lo);
  Case hi = base("toggle-180", stress::near_toggle_rig(175));
  hi.rpm = 1000;
  hi.clearance_m = 0.1e-3;
  expect_passes(hi);
}

TEST(ClearanceStress, NearToggleEnergyResidualIsIntegrationError) {
  // Near a toggle the default tolerance 1e-10 does not hold the energy
  // balance to 1e-8 at every start angle (bench/stress_clearance: 1.4e-8 …
  // 1.1e-7 on the toggle rigs). It is integration error, not a modelling
  // fault: the residual falls with the tolerance, and at 1e-12 every
  // invariant holds.
  Case loose = base("toggle-0", stress::near_toggle_rig(5));
  Case tight = loose;
  tight.tolerance = 1e-12;
  const stress::Result a = stress::run_case(loose), b = stress::run_case(tight);
  EXPECT_GT(a.impacts, 10u);
  EXPECT_TRUE(b.ok) << b.failure;
  EXPECT_LT(b.energy_residual, 0.1 * a.energy_residual);
}

Scene sampled_scene(int samples_per_revolution) {
  Scene s;
  s.rig = std::make_shared<const Rig>(thesis_rig());
  s.model = Model::clearance;
  s.crank_speed_rad_s = units::rpm_to_rad_s(350);
  s.revolutions = 3;
  s.samples_per_revolution = samples_per_revolution;
  s.outputs = {"time_s", "theta3_rad", "omega3_rad_s", "alpha3_rad_s2", "alpha4_rad_s2", "bearing_fx_N", "mode",
               "gap_mm"};
  s.clearance.restitution = 0.5;
  return s;
}

TEST(ClearanceStress, OutputSamplingDoesNotChangeTheMotion) {
  // The samples are read off the integrator's dense output; the steps and
  // events must not depend on how many are asked for.
  const ClearanceRun coarse = run_clearance(sampled_scene(36));
  const ClearanceRun fine = run_clearance(sampled_scene(3600));
  ASSERT_EQ(coarse.series.rows(), 3u * 36 + 1);
  ASSERT_EQ(fine.series.rows(), 3u * 3600 + 1);
  ASSERT_GT(coarse.impacts.size(), 10u);
  ASSERT_EQ(coarse.impacts.size(), fine.impacts.size());
  for (std::size_t i = 0; i < coarse.impacts.size(); ++i) {
    EXPECT_EQ(coarse.impacts[i].time_s, fine.impacts[i].time_s) << i;
    EXPECT_EQ(coarse.impacts[i].result.normal_impulse_Ns, fine.impacts[i].result.normal_impulse_Ns) << i;
  }
  for (std::size_t row = 0; row < coarse.series.rows(); ++row)
    for (std::size_t col = 0; col < coarse.series.names.size(); ++col)
      EXPECT_EQ(coarse.series.columns[col][row], fine.series.columns[col][row * 100])
          << coarse.series.names[col] << " row " << row;
  EXPECT_EQ(coarse.diagnostics.energy_residual_J, fine.diagnostics.energy_residual_J);
}

}  // namespace
}  // namespace fourbar
