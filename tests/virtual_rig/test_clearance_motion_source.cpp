// The clearance model as the virtual rig's motion source.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "common/units.hpp"
#include "sim/drive/crank_motion.hpp"
#include "sim/three_mode/simulator.hpp"
#include "virtual_rig/clearance_motion_source.hpp"

namespace fourbar {
namespace {

TEST(ClearanceMotionSource, AlphaIntegratesToOmegaAcrossImpacts) {
  const auto rig = std::make_shared<const Rig>(thesis_rig());
  const double w = units::rpm_to_rad_s(350), fs = 4000, h = 1 / fs;
  CrankDrive drive;
  drive.mean_speed_rad_s = w;
  ClearanceSettings cs;
  cs.restitution = 0.5;
  cs.tolerance = 1e-9;
  const double xi = 0.254e-3, start = -0.5, end = 0.6;
  (void)fs;
  const ClearanceMotionSource src(rig, drive, cs, xi, start, end, h);

  // Impacts happen in this window (so the jumps matter) ...
  std::size_t inside = 0;
  for (const auto& r : src.impacts()) inside += r.time_s > 0 && r.time_s < 0.5;
  EXPECT_GT(inside, 0u);
  // ... and the box-mean α integrates back to ω exactly across them.
  const double omega = src.at(0.0).omega3_rad_s;
  const LinkState first = src.at(-h / 2);
  double integral = 0;
  for (int i = 0; i < 2000; ++i) integral += src.at(i * h).alpha3_rad_s2 * h;
  const LinkState last = src.at(2000 * h - h / 2);
  EXPECT_NEAR(first.omega3_rad_s + integral, last.omega3_rad_s, 1e-9 * std::abs(omega) + 1e-9);
  // Crank state from the drive; link angles on the contact circle's neighbourhood of the nominal ones.
  const LinkState s = src.at(0.25);
  EXPECT_NEAR(s.crank.angle_rad, w * 0.25, 1e-12);
  const NominalMotion nom = solve_motion(*rig, s.crank);
  EXPECT_NEAR(std::remainder(s.theta3_rad - nom.pose.theta3_rad(), units::kTwoPi), 0.0, 5 * xi / rig->coupler.length_m);
  EXPECT_NEAR(std::remainder(s.theta4_rad - nom.pose.theta4_rad(), units::kTwoPi), 0.0, 5 * xi / rig->rocker.length_m);
}

TEST(ClearanceMotionSource, TinyClearanceMovesLikeTheNominalMechanism) {
  const auto rig = std::make_shared<const Rig>(thesis_rig());
  CrankDrive drive;
  drive.mean_speed_rad_s = units::rpm_to_rad_s(250);
  drive.fluctuation = 0.01, drive.fluctuation_period_s = 2.0;
  ClearanceSettings cs;
  cs.restitution = 0.5;
  const double fs = 2000;
  const ClearanceMotionSource src(rig, drive, cs, 1e-9, -0.05, 0.3, 1 / fs);
  const NominalMotionSource nom(rig, drive);
  for (int i = 0; i < 500; i += 37) {
    const LinkState a = src.at(i / fs), b = nom.at(i / fs);
    EXPECT_NEAR(a.omega3_rad_s, b.omega3_rad_s, 1e-4 * 10);
    EXPECT_NEAR(a.alpha4_rad_s2, b.alpha4_rad_s2, 1e-3 * 300);
  }
}

}  // namespace
}  // namespace fourbar
