// The sensor model against an independent formulation: the second time
// derivative (finite differences) of the mounting point's position.

#include <gtest/gtest.h>

#include <cmath>

#include "common/units.hpp"
#include "virtual_rig/sensor_signal.hpp"
#include "mechanism/vec2.hpp"

namespace fourbar {
namespace {

/// Position of a point fixed on the coupler or rocker at time t.
Vec2 point(const Rig& rig, const MotionSource& m, double t, bool coupler, double s, double d) {
  const LinkState st = m.at(t);
  if (coupler) {
    const Vec2 a = rig.crank.length_m * unit(st.crank.angle_rad), u = unit(st.theta3_rad);
    return a + s * u + d * u.perp();
  }
  const Vec2 u = unit(st.theta4_rad);
  return Vec2{rig.ground_length_m, 0} + s * u + d * u.perp();
}

TEST(SensorSignal, SpecificForceIsTheSecondDerivativeMinusGravity) {
  const auto rig = std::make_shared<const Rig>(thesis_rig());
  const double w0 = units::rpm_to_rad_s(350);
  const NominalMotionSource motion(rig, CrankDrive{0.3, w0, 0.05, 0.5});  // α2 ≠ 0
  const double h = 2e-5;
  for (const ChannelRole role : {ChannelRole::coupler_tangential, ChannelRole::coupler_normal,
                                 ChannelRole::rocker_tangential, ChannelRole::rocker_normal}) {
    for (double s : {0.0, 0.1, rig->coupler.length_m}) {
      for (double d : {0.0, -0.02}) {
        for (double t = 0.013; t < 0.2; t += 0.021) {
          const bool coupler = is_on_coupler(role);
          // 4th-order central difference of the position.
          auto p = [&](double dt) { return point(*rig, motion, t + dt, coupler, s, d); };
          const Vec2 acc = (-1.0 / 12) * p(-2 * h) + (4.0 / 3) * p(-h) + (-5.0 / 2) * p(0) + (4.0 / 3) * p(h) +
                           (-1.0 / 12) * p(2 * h);
          const Vec2 a = acc * (1.0 / (h * h));
          const LinkState st = motion.at(t);
          const Vec2 u = unit(coupler ? st.theta3_rad : st.theta4_rad);
          const Vec2 f = a + Vec2{0, rig->gravity_m_s2};
          const double want = is_tangential(role) ? dot(f, u.perp()) : dot(f, u);
          EXPECT_NEAR(specific_force(*rig, st, role, s, d), want, 1e-4 * (1 + std::abs(want)))
              << to_string(role) << " s=" << s << " d=" << d << " t=" << t;
        }
      }
    }
  }
}

// Thesis eq. 7.2.2-1: a sensor at the rocker's end reads l4·α4 tangentially
// (plus the gravity projection g·cos θ4, which the thesis leaves out).
TEST(SensorSignal, RockerTangentialIsL4Alpha4PlusGravity) {
  const auto rig = std::make_shared<const Rig>(thesis_rig());
  const NominalMotionSource motion(rig, CrankDrive{0, units::rpm_to_rad_s(350), 0, 1});
  for (double t = 0; t < 0.17; t += 0.01) {
    const LinkState st = motion.at(t);
    EXPECT_NEAR(specific_force(*rig, st, ChannelRole::rocker_tangential, rig->rocker.length_m, 0),
                rig->rocker.length_m * st.alpha4_rad_s2 + rig->gravity_m_s2 * std::cos(st.theta4_rad), 1e-9);
    EXPECT_NEAR(specific_force(*rig, st, ChannelRole::rocker_normal, rig->rocker.length_m, 0),
                -rig->rocker.length_m * st.omega4_rad_s * st.omega4_rad_s + rig->gravity_m_s2 * std::sin(st.theta4_rad),
                1e-9);
  }
}

TEST(CrankDrive, FluctuationAndInverse) {
  const CrankDrive d{0.5, -20.0, 0.02, 2.0};
  for (double t : {0.0, 0.3, 1.7}) {
    const double h = 1e-5;
    EXPECT_NEAR((d.at(t + h).angle_rad - d.at(t - h).angle_rad) / (2 * h), d.at(t).speed_rad_s, 1e-6);
    EXPECT_NEAR((d.at(t + h).speed_rad_s - d.at(t - h).speed_rad_s) / (2 * h), d.at(t).accel_rad_s2, 1e-5);
    EXPECT_NEAR(d.time_at_turned(d.at(t).angle_rad - 0.5), t, 1e-12);
  }
  EXPECT_NEAR(d.at(0.5).speed_rad_s, -20.0 * (1 + 0.02 * std::sin(M_PI / 2)), 1e-12);
}

}  // namespace
}  // namespace fourbar
