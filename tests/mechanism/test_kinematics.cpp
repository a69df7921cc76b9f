// Nominal kinematics: closed forms checked against finite differences of the
// positions, loop closure, the thesis eq. 2.1-1a roots and both branches.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/units.hpp"
#include "mechanism/kinematics.hpp"

namespace fourbar {
namespace {

double wrap_pi(double a) { return std::remainder(a, units::kTwoPi); }

Vec2 joint_from_crank(const Rig& rig, const Pose& p) { return rig.crank.length_m * p.u2 + rig.coupler.length_m * p.u3; }
Vec2 joint_from_rocker(const Rig& rig, const Pose& p) {
  return Vec2{rig.ground_length_m, 0.0} + rig.rocker.length_m * p.u4;
}

TEST(NominalKinematics, LoopClosesAt3600AnglesOnBothBranches) {
  const Rig rig = thesis_rig();
  for (double branch : {1.0, -1.0}) {
    double worst = 0;
    for (int i = 0; i < 3600; ++i) {
      const Pose p = solve_pose(rig, units::deg_to_rad(0.1 * i), branch);
      worst = std::max(worst, (joint_from_crank(rig, p) - joint_from_rocker(rig, p)).norm());
      EXPECT_NEAR(std::hypot(p.u3.x, p.u3.y), 1.0, 1e-15);
      EXPECT_NEAR(std::hypot(p.u4.x, p.u4.y), 1.0, 1e-15);
    }
    EXPECT_LT(worst, 1e-12) << "branch " << branch;
  }
}

TEST(NominalKinematics, OpenBranchIsConvexAboveGroundForThesisRig) {
  const Rig rig = thesis_rig();
  const Pose p = solve_pose(rig, units::deg_to_rad(90.0));
  const Vec2 b = joint_from_crank(rig, p);
  EXPECT_GT(b.y, 0.0);
  // Open and crossed assemblies are mirror images about the line A–O4.
  const Pose q = solve_pose(rig, units::deg_to_rad(90.0), -1.0);
  EXPECT_GT(std::abs(wrap_pi(p.theta3_rad() - q.theta3_rad())), 0.1);
}

TEST(NominalKinematics, CosTheta3IsARootOfThesisEquation) {
  const Rig rig = thesis_rig();
  for (int i = 0; i < 360; ++i) {
    const double t2 = units::deg_to_rad(i + 0.5);
    const auto roots = thesis_cos_theta3_roots(rig, t2);
    for (double branch : {1.0, -1.0}) {
      const double c3 = solve_pose(rig, t2, branch).u3.x;
      const double d = std::min(std::abs(c3 - roots[0]), std::abs(c3 - roots[1]));
      EXPECT_LT(d, 1e-9) << "crank " << i + 0.5 << " deg";
    }
  }
}

// Velocities and accelerations against central differences of positions,
// with a varying crank speed (α2 ≠ 0), along a crank trajectory
// θ2(t) = θ0 + ω0·t + ½·α2·t².
TEST(NominalKinematics, RatesMatchFiniteDifferencesOfPositions) {
  const Rig rig = thesis_rig();
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> angle(0, units::kTwoPi), speed(5.0, 60.0), accel(-200.0, 200.0);
  const double h = 2e-4;  // s
  for (int trial = 0; trial < 200; ++trial) {
    const double t0 = angle(rng), w0 = speed(rng), a2 = accel(rng);
    auto crank_at = [&](double t) { return CrankState{t0 + w0 * t + 0.5 * a2 * t * t, w0 + a2 * t, a2}; };
    auto th = [&](double t) {
      const Pose p = solve_pose(rig, crank_at(t).angle_rad);
      return std::pair{p.theta3_rad(), p.theta4_rad()};
    };
    const NominalMotion m = solve_motion(rig, crank_at(0));
    // Fourth-order central differences (error O(h^4)).
    const auto [p2a, p2b] = th(-2 * h);
    const auto [p1a, p1b] = th(-h);
    const auto [q1a, q1b] = th(h);
    const auto [q2a, q2b] = th(2 * h);
    const auto [c0a, c0b] = th(0);
    auto d1 = [&](double m2, double m1, double p1, double p2) {
      return (wrap_pi(m2 - p2) + 8 * wrap_pi(p1 - m1)) / (12 * h);
    };
    auto d2 = [&](double m2, double m1, double c, double p1, double p2) {
      return (-wrap_pi(p2 - c) - wrap_pi(m2 - c) + 16 * (wrap_pi(p1 - c) + wrap_pi(m1 - c))) / (12 * h * h);
    };
    const double w3 = d1(p2a, p1a, q1a, q2a), w4 = d1(p2b, p1b, q1b, q2b);
    const double a3 = d2(p2a, p1a, c0a, q1a, q2a), a4 = d2(p2b, p1b, c0b, q1b, q2b);
    const double w_scale = std::abs(w0) * 0.5, a_scale = w0 * w0 * 0.5 + std::abs(a2);
    EXPECT_LT(std::abs(m.omega3_rad_s - w3) / w_scale, 1e-7) << "trial " << trial;
    EXPECT_LT(std::abs(m.omega4_rad_s - w4) / w_scale, 1e-7) << "trial " << trial;
    EXPECT_LT(std::abs(m.alpha3_rad_s2 - a3) / a_scale, 1e-7) << "trial " << trial;
    EXPECT_LT(std::abs(m.alpha4_rad_s2 - a4) / a_scale, 1e-7) << "trial " << trial;
  }
}

// Accelerations against central differences of the closed-form velocities:
// a first difference of an analytic function, so it reaches 1e-7 relative.
TEST(NominalKinematics, AccelerationsMatchDifferencesOfVelocities) {
  const Rig rig = thesis_rig();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0, units::kTwoPi), speed(5.0, 60.0), accel(-200.0, 200.0);
  const double h = 1e-4;
  double worst = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const double t0 = angle(rng), w0 = speed(rng), a2 = accel(rng);
    auto motion = [&](double t) { return solve_motion(rig, {t0 + w0 * t + 0.5 * a2 * t * t, w0 + a2 * t, a2}); };
    const NominalMotion m = motion(0), mm2 = motion(-2 * h), mm1 = motion(-h), mp1 = motion(h), mp2 = motion(2 * h);
    auto d1 = [&](double f_m2, double f_m1, double f_p1, double f_p2) {
      return (f_m2 - f_p2 + 8 * (f_p1 - f_m1)) / (12 * h);
    };
    const double a3 = d1(mm2.omega3_rad_s, mm1.omega3_rad_s, mp1.omega3_rad_s, mp2.omega3_rad_s);
    const double a4 = d1(mm2.omega4_rad_s, mm1.omega4_rad_s, mp1.omega4_rad_s, mp2.omega4_rad_s);
    const double scale = w0 * w0 + std::abs(a2);
    worst = std::max({worst, std::abs(m.alpha3_rad_s2 - a3) / scale, std::abs(m.alpha4_rad_s2 - a4) / scale});
  }
  EXPECT_LT(worst, 1e-7);
}

// The velocities are the thesis closed forms (eq. 2.1-2, errata signs).
TEST(NominalKinematics, VelocitiesEqualThesisClosedForms) {
  const Rig rig = thesis_rig();
  const double l2 = rig.crank.length_m, l3 = rig.coupler.length_m, l4 = rig.rocker.length_m;
  for (int i = 0; i < 360; i += 7) {
    const double w2 = 36.6519;
    const NominalMotion m = solve_motion(rig, {units::deg_to_rad(i), w2, 0.0});
    const double t2 = m.crank.angle_rad, t3 = m.pose.theta3_rad(), t4 = m.pose.theta4_rad();
    EXPECT_NEAR(m.omega3_rad_s, -w2 * l2 * std::sin(t2 - t4) / (l3 * std::sin(t3 - t4)), 1e-12);
    EXPECT_NEAR(m.omega4_rad_s, -w2 * l2 * std::sin(t2 - t3) / (l4 * std::sin(t3 - t4)), 1e-12);
    const double w3 = m.omega3_rad_s, w4 = m.omega4_rad_s;
    const double a3 = -(l2 * w2 * w2 * std::cos(t2 - t4) + l3 * w3 * w3 * std::cos(t3 - t4) - l4 * w4 * w4) /
                      (l3 * std::sin(t3 - t4));
    const double a4 = -(l2 * w2 * w2 * std::cos(t2 - t3) + l3 * w3 * w3 - l4 * w4 * w4 * std::cos(t3 - t4)) /
                      (l4 * std::sin(t3 - t4));
    EXPECT_NEAR(m.alpha3_rad_s2, a3, 1e-9 * std::abs(a3) + 1e-9);
    EXPECT_NEAR(m.alpha4_rad_s2, a4, 1e-9 * std::abs(a4) + 1e-9);
  }
}

}  // namespace
}  // namespace fourbar
