// Newton shooting for periodic orbits (sim/studies/periodic_orbit.hpp): the
// generic iteration on maps with closed-form periodic points, and the
// three-mode model's turn map on the period-2 motion of the e = 0.8 session's
// 250 rpm recording (docs/fit.md "A periodic recording").

#include "sim/studies/periodic_orbit.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "common/units.hpp"
#include "mechanism/rig.hpp"

namespace fourbar {
namespace {

// The logistic map x ↦ r·x·(1 − x) at r = 3.2 has the period-2 points
// x± = (r + 1 ± √((r + 1)(r − 3))) / (2r); its fixed point 1 − 1/r is not one.
TEST(ShootFixedPoint, LogisticMapPeriodTwoPoints) {
  const double r = 3.2;
  const StateMap twice = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
    const double a = r * x(0) * (1 - x(0));
    y = Eigen::VectorXd::Constant(1, r * a * (1 - a));
    return true;
  };
  const double root = std::sqrt((r + 1) * (r - 3));
  const double plus = (r + 1 + root) / (2 * r), minus = (r + 1 - root) / (2 * r);
  for (double x0 : {0.45, 0.55, 0.85}) {
    const auto x = shoot_fixed_point(twice, Eigen::VectorXd::Constant(1, x0));
    ASSERT_TRUE(x) << x0;
    const double want = x0 < 0.6 ? minus : plus;
    EXPECT_NEAR((*x)(0), want, 1e-8) << x0;
  }
}

// An affine map x ↦ −A·x + c squared: the fixed point of its square is
// (I − A²)⁻¹·(c − A·c); Newton on an affine map converges in one step.
TEST(ShootFixedPoint, AffineMapInFourDimensions) {
  Eigen::Matrix4d a;
  a << 0.5, 0.1, 0, 0, -0.2, 0.3, 0.1, 0, 0, 0, 0.4, 0.2, 0.1, 0, 0, -0.6;
  const Eigen::Vector4d c(1, -2, 0.5, 3);
  const StateMap twice = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
    y = -a * (-a * x + c) + c;
    return true;
  };
  const Eigen::Vector4d want = (Eigen::Matrix4d::Identity() - a * a).inverse() * (c - a * c);
  const auto x = shoot_fixed_point(twice, Eigen::VectorXd::Zero(4));
  ASSERT_TRUE(x);
  EXPECT_LT((*x - want).norm(), 1e-8);
}

TEST(ShootFixedPoint, NoFixedPointOrNoMapGivesNone) {
  const StateMap shift = [](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
    y = x.array() + 1.0;  // G ≡ 1: no root, singular Jacobian
    return true;
  };
  EXPECT_FALSE(shoot_fixed_point(shift, Eigen::VectorXd::Zero(2)));
  const StateMap outside = [](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
    y = 0.5 * x;
    return x.norm() < 1;  // the map exists only inside the unit ball
  };
  EXPECT_FALSE(shoot_fixed_point(outside, Eigen::VectorXd::Constant(2, 3.0)));
  const auto inside = shoot_fixed_point(outside, Eigen::VectorXd::Constant(2, 0.3));
  ASSERT_TRUE(inside);
  EXPECT_LT(inside->norm(), 1e-8);
}

// The e = 0.8 smooth session's 250 rpm, 0.254 mm recording
// (bench/make_fit_session.sh DIR 0.8 smooth 0 25 30 170) took a period-2
// motion; its turn starts at crank 0, from a run of the model on the
// recording's truth (bench/periodic_orbit_probe REC.truth.csv 250 0.254 0.8
// 40 0 1), in the scaled units (δ3, δ4 over ξ/l3, rates over ω2·ξ/l3):
const Eigen::Vector4d kRecordedA(0.1532583515, -0.9032230443, 9.225793396, 1.444956482);
const Eigen::Vector4d kRecordedB(-1.024680071, -0.8754458641, -5.050921309, 7.494912744);

TEST(TurnMap, NewtonFindsTheRecordedPeriodTwoMotionAndItIsStable) {
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml");
  ClearanceSettings s;
  s.radial_clearance_m = 0.254e-3;
  s.restitution = 0.8;
  s.tolerance = 1e-8;  // the virtual rig scene's
  const TurnMap map(rig, 0.254e-3, units::rpm_to_rad_s(250), s);
  std::vector<Eigen::Vector4d> turns;
  const StateMap twice = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {
    if (!map.run(Eigen::Vector4d(x), 2, turns)) return false;
    y = turns.back();
    return true;
  };
  // From 1e-4 off the recorded state (itself, 40 turns from the truth's,
  // within ~1e-4 of the orbit), Newton lands on the orbit. The map is not
  // smooth: 1e-3 off, a different impact sequence gives |P²(x) − x| = 6.2.
  const auto root = shoot_fixed_point(twice, Eigen::VectorXd(kRecordedA + Eigen::Vector4d(1e-4, -1e-4, 1e-4, 1e-4)));
  ASSERT_TRUE(root);
  const Eigen::Vector4d x(*root);
  EXPECT_LT((x - kRecordedA).norm(), 1e-3);
  ASSERT_TRUE(map.run(x, 2, turns));
  EXPECT_LT((turns[0] - kRecordedB).norm(), 1e-3) << "one turn on: the orbit's other turn start";
  EXPECT_LT((turns[1] - x).norm(), 1e-8) << "two turns on: back";
  ASSERT_TRUE(map.run(x, 40, turns));
  EXPECT_LT(repeat_distance(turns, 2), 1e-6) << "stable: a run on it keeps repeating";
  EXPECT_GT(repeat_distance(turns, 1), 1.0) << "period 2, not 1";
  // The model's own run (nominal start at crank 0, as the fit's) does not take it.
  EXPECT_GT(repeat_distance(map.own_turns(20, 30), 2), 0.1);
}

}  // namespace
}  // namespace fourbar
