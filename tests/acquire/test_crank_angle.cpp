// The crank motion fitted through the pulse times: exact for constant speed,
// C² across pulses, and close to a slowly fluctuating true motion.

#include <gtest/gtest.h>

#include <cmath>

#include "acquire/crank_angle.hpp"
#include "common/units.hpp"
#include "virtual_rig/motion_source.hpp"

namespace fourbar {
namespace {

std::vector<double> pulse_times(const CrankDrive& d, int n) {
  std::vector<double> t;
  for (int k = 0; k < n; ++k) t.push_back(d.time_at_turned(units::kTwoPi * k));
  return t;
}

TEST(CrankAngle, ConstantSpeedIsExact) {
  CrankDrive d{0, 30, 0, 1};
  for (int n : {2, 3, 4, 8}) {
    CrankAngleModel m(pulse_times(d, n));
    for (std::size_t k = 0; k < m.revolutions(); ++k) {
      const RevolutionCurve r = m.revolution(k);
      for (double tau : {0.0, 0.1, 0.5, 0.93}) {
        const CrankPoint p = r.at(r.t0 + tau * r.h);
        EXPECT_NEAR(p.phase_rad, 30 * p.time_s, 1e-9) << n;
        EXPECT_NEAR(p.speed_rad_s, 30, 1e-9);
        EXPECT_NEAR(p.accel_rad_s2, 0, 1e-6);
      }
    }
  }
}

TEST(CrankAngle, SmoothAcrossPulsesAndBothWaysRound) {
  CrankDrive d{0, 36.65, 0.02, 2.0};
  CrankAngleModel m(pulse_times(d, 30));
  for (std::size_t k = 1; k < m.revolutions(); ++k) {
    const RevolutionCurve a = m.revolution(k - 1), b = m.revolution(k);
    const CrankPoint end = a.at(a.t0 + a.h), start = b.at(b.t0);
    EXPECT_NEAR(end.phase_rad, start.phase_rad, 1e-9);
    EXPECT_NEAR(end.speed_rad_s, start.speed_rad_s, 1e-9);
    EXPECT_NEAR(end.accel_rad_s2, start.accel_rad_s2, 1e-6);
    for (double u : {0.0, 0.25, 0.6, 0.99}) {
      const CrankPoint g = b.at_fraction(u);
      const CrankPoint back = b.at(g.time_s);
      EXPECT_NEAR(back.phase_rad, g.phase_rad, 2e-6) << k << " " << u;
      EXPECT_NEAR(back.speed_rad_s, g.speed_rad_s, 1e-4 * g.speed_rad_s);
    }
  }
}

// ±2 % sinusoidal speed fluctuation over twelve revolutions (a motor
// controller's hunting): the fitted angle follows it to < 0.01° RMS, while
// constant speed between pulses would be off by about a degree.
TEST(CrankAngle, FollowsASlowSpeedFluctuation) {
  const double w0 = units::rpm_to_rad_s(350);
  CrankDrive d{0, w0, 0.02, 12 * units::kTwoPi / w0};
  const auto t = pulse_times(d, 60);
  CrankAngleModel m(t);
  double sq = 0, sq_linear = 0, sq_speed = 0;
  int n = 0;
  for (std::size_t k = 0; k < m.revolutions(); ++k) {
    const RevolutionCurve r = m.revolution(k);
    for (int i = 0; i < 200; ++i) {
      const double time = r.t0 + r.h * i / 200.0;
      const CrankState truth = d.at(time);
      const double e = m.revolution(k).at(time).phase_rad - truth.angle_rad;
      const double linear = units::kTwoPi * (k + (time - t[k]) / (t[k + 1] - t[k])) - truth.angle_rad;
      sq += e * e, sq_linear += linear * linear;
      const double ew = r.at(time).speed_rad_s / truth.speed_rad_s - 1;
      sq_speed += ew * ew;
      ++n;
    }
  }
  const double rms_deg = units::rad_to_deg(std::sqrt(sq / n));
  EXPECT_LT(rms_deg, 0.01);
  EXPECT_GT(units::rad_to_deg(std::sqrt(sq_linear / n)), 10 * rms_deg);
  EXPECT_LT(std::sqrt(sq_speed / n), 1e-3);  // speed to 0.1 %
}

// Both ends of a segment: no worse than a few times the interior (Boost
// 1.74's own right-end slope estimate made the last turns drift by degrees).
TEST(CrankAngle, SegmentEndsAreAsGoodAsTheMiddle) {
  const double w0 = units::rpm_to_rad_s(350);
  CrankDrive d{0, w0, 0.02, 10 * units::kTwoPi / w0};
  for (int n : {5, 12, 30}) {
    CrankAngleModel m(pulse_times(d, n));
    std::vector<double> worst;
    for (std::size_t k = 0; k < m.revolutions(); ++k) {
      const RevolutionCurve r = m.revolution(k);
      double w = 0;
      for (int i = 0; i < 100; ++i) {
        const double time = r.t0 + r.h * i / 100.0;
        w = std::max(w, std::abs(std::remainder(r.at(time).phase_rad - d.at(time).angle_rad, units::kTwoPi)));
      }
      worst.push_back(units::rad_to_deg(w));
    }
    EXPECT_LT(worst.front(), 0.05) << n;
    EXPECT_LT(worst.back(), 0.05) << n;
  }
}

}  // namespace
}  // namespace fourbar
