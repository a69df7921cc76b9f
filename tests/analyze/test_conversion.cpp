// Accelerometer → link angular acceleration (thesis §7.2, derived in full):
// the forward sensor model against finite differences of the sensor's
// position, the inverse against the nominal mechanism, the thesis formula as
// a special case, the gravity term at standstill, and bad mounts.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "analyze/ac_coupling.hpp"
#include "analyze/conversion.hpp"
#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {
namespace {

// A crank trajectory with varying speed: θ2(t) = θ0 + w·t + b·sin(c·t).
struct Trajectory {
  double theta0, w, b, c;
  CrankState at(double t) const {
    return {theta0 + w * t + b * std::sin(c * t), w + b * c * std::cos(c * t), -b * c * c * std::sin(c * t)};
  }
};

// Sensor position from positions only: P = J + r·u + h·n.
Vec2 sensor_position(const Rig& rig, const ResolvedMount& m, double theta2) {
  const Pose p = solve_pose(rig, theta2);
  const Vec2 joint = m.link == SensedLink::coupler ? rig.crank.length_m * p.u2 : Vec2{rig.ground_length_m, 0.0};
  const Vec2 u = m.link == SensedLink::coupler ? p.u3 : p.u4;
  return joint + m.r_m * u + m.h_m * u.perp();
}

std::vector<AccelerometerMount> sample_mounts() {
  std::vector<AccelerometerMount> out;
  for (SensedLink link : {SensedLink::coupler, SensedLink::rocker})
    for (SensorAxis axis : {SensorAxis::tangential, SensorAxis::normal})
      for (int sign : {1, -1}) {
        AccelerometerMount m;
        m.channel = "test";
        m.link = link;
        m.axis = axis;
        m.axis_sign = sign;
        m.distance_m = sign > 0 ? 0.2 : 0.03;  // the second measured from the far joint
        m.from = sign > 0 ? MeasuredFrom::first_joint : MeasuredFrom::far_joint;
        m.offset_m = sign > 0 ? 0.0 : 0.015;
        out.push_back(m);
      }
  return out;
}

TEST(Conversion, ForwardModelMatchesFiniteDifferencesOfSensorPosition) {
  const Rig rig = thesis_rig();
  const Trajectory traj{0.3, units::rpm_to_rad_s(350), 0.2, 9.0};
  const double h = 1e-4;
  for (const AccelerometerMount& mount : sample_mounts()) {
    const ResolvedMount m = resolve_mount(rig, mount);
    double worst = 0, scale = 0;
    for (int i = 0; i < 200; ++i) {
      const double t = 0.0013 * i;
      // 4th-order central second difference of P(t).
      auto P = [&](double dt) { return sensor_position(rig, m, traj.at(t + dt).angle_rad); };
      const Vec2 a = (-1.0 / 12) * P(-2 * h) + (4.0 / 3) * P(-h) + (-5.0 / 2) * P(0) + (4.0 / 3) * P(h) +
                     (-1.0 / 12) * P(2 * h);
      const Vec2 f = (1.0 / (h * h)) * a + Vec2{0.0, rig.gravity_m_s2};
      const CrankState c = traj.at(t);
      const Pose pose = solve_pose(rig, c.angle_rad);
      const Vec2 u = m.link == SensedLink::coupler ? pose.u3 : pose.u4;
      const double expected = m.sign * dot(f, m.axis == SensorAxis::tangential ? u.perp() : u);
      const double got = sensor_reading(rig, m, nominal_link_motion(rig, m.link, c));
      worst = std::max(worst, std::abs(got - expected));
      scale = std::max(scale, std::abs(expected));
    }
    EXPECT_LT(worst, 1e-6 * scale) << to_string(m.link) << ' ' << to_string(m.axis) << " sign " << m.sign;
  }
}

TEST(Conversion, InverseRecoversNominalAlphaAndOmegaSquared) {
  const Rig rig = thesis_rig();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0, units::kTwoPi), speed(-60, 60), accel(-300, 300);
  for (const AccelerometerMount& mount : sample_mounts()) {
    const ResolvedMount m = resolve_mount(rig, mount);
    for (int i = 0; i < 500; ++i) {
      const CrankState c{angle(rng), speed(rng), accel(rng)};
      const SensedLinkMotion k = nominal_link_motion(rig, m.link, c);
      const double reading = sensor_reading(rig, m, k);
      if (m.axis == SensorAxis::tangential) {
        const double a = angular_acceleration_from_tangential(rig, m, k, reading);
        EXPECT_NEAR(a, k.alpha_rad_s2, 1e-10 * (1 + std::abs(k.alpha_rad_s2)));
      } else {
        const double w2 = angular_speed_squared_from_normal(rig, m, k, reading, k.alpha_rad_s2);
        EXPECT_NEAR(w2, k.omega_rad_s * k.omega_rad_s, 1e-10 * (1 + w2));
      }
    }
  }
}

TEST(Conversion, ReducesToThesisFormulaForItsAssumptions) {
  // Thesis eq. 7.2.1-6 / 7.2.2-1: sensor at the far joint, α2 = 0, no gravity.
  Rig rig = thesis_rig();
  rig.gravity_m_s2 = 0;
  const double w2 = units::rpm_to_rad_s(350);
  std::vector<double> angle(360), reading(360), ours(360), thesis(360), speed(360, w2), accel(360, 0.0);
  for (SensedLink link : {SensedLink::coupler, SensedLink::rocker})
    for (int sign : {1, -1}) {
      AccelerometerMount mount;
      mount.channel = "t";
      mount.link = link;
      mount.axis_sign = sign;
      mount.distance_m = link_length_m(rig, link);
      const ResolvedMount m = resolve_mount(rig, mount);
      for (int i = 0; i < 360; ++i) {
        angle[i] = units::deg_to_rad(i);
        reading[i] = sensor_reading(rig, m, nominal_link_motion(rig, link, {angle[i], w2, 0.0}));
      }
      angular_acceleration_from_tangential(rig, mount, nominal_link_track(rig, link, {angle, speed, accel}), reading,
                                           ours);
      thesis_angular_acceleration(rig, link, sign, w2, angle, reading, thesis);
      for (int i = 0; i < 360; ++i) EXPECT_NEAR(ours[i], thesis[i], 1e-10 * (1 + std::abs(ours[i])));
    }
}

TEST(Conversion, StandingStillTheSensorReadsOnlyGravityAndAlphaIsZero) {
  const Rig rig = thesis_rig();
  for (const AccelerometerMount& mount : sample_mounts()) {
    const ResolvedMount m = resolve_mount(rig, mount);
    if (m.axis != SensorAxis::tangential) continue;
    for (int i = 0; i < 360; ++i) {
      const CrankState c{units::deg_to_rad(i), 0.0, 0.0};
      const Pose p = solve_pose(rig, c.angle_rad);
      const Vec2 u = m.link == SensedLink::coupler ? p.u3 : p.u4;
      const double gravity_projection = m.sign * rig.gravity_m_s2 * u.perp().y;  // s·g·cos θ
      const SensedLinkMotion k = nominal_link_motion(rig, m.link, c);
      EXPECT_NEAR(sensor_reading(rig, m, k), gravity_projection, 1e-12);
      EXPECT_NEAR(angular_acceleration_from_tangential(rig, m, k, gravity_projection), 0.0, 1e-12);
    }
  }
}

// A link swinging slowly (crank at 0.5 rpm): the reading is almost only the
// gravity projection. The full conversion gives the tiny true α; dropping the
// gravity term (the thesis) errs by up to g/r. With an AC-coupled sensor
// (corner 0.5 Hz ≫ the motion) the sensor output is almost nothing, and the
// restored channel still gives the true α.
TEST(Conversion, SlowlySwingingLinkGravityTermAcAndDcCoupled) {
  const Rig rig = thesis_rig();
  const double w2 = units::rpm_to_rad_s(0.5), fs = 200.0;
  const std::size_t n = static_cast<std::size_t>(fs * units::kTwoPi / w2);  // one turn
  std::vector<double> angle(n), speed(n, w2), accel(n, 0.0), truth(n), dc(n), ac(n), restored(n), alpha(n);
  for (std::size_t i = 0; i < n; ++i) angle[i] = 0.1 + w2 * i / fs;
  AccelerometerMount mount;
  mount.channel = "coupler_t";
  mount.distance_m = 0.29;
  mount.axis_sign = -1;
  const ResolvedMount m = resolve_mount(rig, mount);
  double max_alpha = 0, max_thesis_err = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const SensedLinkMotion k = nominal_link_motion(rig, m.link, {angle[i], w2, 0.0});
    truth[i] = k.alpha_rad_s2;
    dc[i] = sensor_reading(rig, m, k);
    max_alpha = std::max(max_alpha, std::abs(truth[i]));
  }
  EXPECT_LT(max_alpha, 1e-4 * rig.gravity_m_s2 / m.r_m);  // the link barely accelerates
  const std::vector<SensedLinkMotion> track = nominal_link_track(rig, SensedLink::coupler, {angle, speed, accel});
  angular_acceleration_from_tangential(rig, mount, track, dc, alpha);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(alpha[i], truth[i], 1e-11);
  thesis_angular_acceleration(rig, SensedLink::coupler, -1, w2, angle, dc, alpha);
  for (std::size_t i = 0; i < n; ++i) max_thesis_err = std::max(max_thesis_err, std::abs(alpha[i] - truth[i]));
  EXPECT_GT(max_thesis_err, 0.5 * rig.gravity_m_s2 / m.r_m);

  // AC-coupled: the sensor sees the gravity projection high-passed at 0.5 Hz.
  mount.high_pass_corner_hz = 0.5;
  apply_sensor_high_pass(dc, fs, mount.high_pass_corner_hz, 0.0, ac);
  double max_ac = 0;
  for (std::size_t i = n / 10; i < n; ++i) max_ac = std::max(max_ac, std::abs(ac[i]));
  EXPECT_LT(max_ac, 0.02 * rig.gravity_m_s2);  // the piezo output is nearly flat
  restore_dc_coupled_reading(rig, mount, track, fs, ac, restored);
  // The sensor started at rest (output 0 at sample 0), so the restored channel
  // matches the DC reading up to a constant; the model mean fixes it.
  angular_acceleration_from_tangential(rig, mount, track, restored, alpha);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(alpha[i], truth[i], 1e-9);
}

TEST(Conversion, BadMountsAreInputErrorsNamingTheChannel) {
  const Rig rig = thesis_rig();
  auto expect_error = [&](AccelerometerMount m, const char* needle) {
    m.channel = "coupler_tan";
    try {
      resolve_mount(rig, m);
      ADD_FAILURE() << "no error for " << needle;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("coupler_tan"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  AccelerometerMount m;
  m.distance_m = 0.35;
  expect_error(m, "outside the link");
  m.distance_m = -0.01;
  expect_error(m, "outside the link");
  m.distance_m = 0.0;
  expect_error(m, "r = 0");
  m.distance_m = rig.coupler.length_m;
  m.from = MeasuredFrom::far_joint;
  expect_error(m, "r = 0");
  m.from = MeasuredFrom::first_joint;
  m.axis_sign = 0;
  expect_error(m, "must be +1 or -1");
  m.axis_sign = 1;
  m.high_pass_corner_hz = -1;
  expect_error(m, "high-pass corner");
  m.high_pass_corner_hz = 0;
  m.distance_m = std::nan("");
  expect_error(m, "finite");

  // A normal channel given to the tangential conversion, and short crank tracks.
  m.distance_m = 0.3;
  m.axis = SensorAxis::normal;
  std::vector<double> x(10, 0.0), y(10), shorter(9, 0.0);
  const std::vector<SensedLinkMotion> track = nominal_link_track(rig, SensedLink::coupler, {x, x, x});
  EXPECT_THROW(angular_acceleration_from_tangential(rig, m, track, x, y), InputError);
  m.axis = SensorAxis::tangential;
  EXPECT_THROW(nominal_link_track(rig, SensedLink::coupler, {x, shorter, x}), InputError);
  EXPECT_THROW(angular_acceleration_from_tangential(rig, m, track, shorter, y), InputError);
}

}  // namespace
}  // namespace fourbar

namespace fourbar {
namespace {

// The tabulated nominal motion against the exact one at random crank states
// (any speed and acceleration, negative and large angles too).
TEST(LinkTable, MatchesTheExactNominalMotion) {
  const Rig rig = thesis_rig();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(-50.0, 2000.0), speed(-60.0, 60.0), accel(-300.0, 300.0);
  for (SensedLink link : {SensedLink::coupler, SensedLink::rocker}) {
    const LinkTable table(rig, link);
    EXPECT_GE(table.points(), 4096u);
    EXPECT_LE(table.max_error(), LinkTable::kTolerance);
    for (int i = 0; i < 2000; ++i) {
      const CrankState c{angle(rng), speed(rng), accel(rng)};
      const SensedLinkMotion e = nominal_link_motion(rig, link, c), t = table.motion(c);
      const double w2 = c.speed_rad_s * c.speed_rad_s;
      EXPECT_NEAR(t.u.x, e.u.x, 1e-10);
      EXPECT_NEAR(t.u.y, e.u.y, 1e-10);
      EXPECT_NEAR(t.omega_rad_s, e.omega_rad_s, 1e-10 * std::abs(c.speed_rad_s) * 3);
      EXPECT_NEAR(t.alpha_rad_s2, e.alpha_rad_s2, 1e-10 * (w2 * 20 + std::abs(c.accel_rad_s2) * 3));
      EXPECT_NEAR(t.joint_accel_m_s2.x, e.joint_accel_m_s2.x, 1e-10 * (w2 + std::abs(c.accel_rad_s2)));
      EXPECT_NEAR(t.joint_accel_m_s2.y, e.joint_accel_m_s2.y, 1e-10 * (w2 + std::abs(c.accel_rad_s2)));
    }
  }
}

// convert_reading (one pass, table) equals restore_dc_coupled_reading followed
// by the per-sample conversion with the exact track, for tangential and
// normal mounts, DC- and AC-coupled, with offsets.
TEST(LinkTable, OnePassConversionEqualsTheTwoStepExactOne) {
  const Rig rig = thesis_rig();
  const double fs = 5000, w0 = units::rpm_to_rad_s(350);
  const std::size_t n = 20000;
  std::vector<double> angle(n), speed(n), accel(n), reading(n), link_alpha(n);
  std::mt19937 rng(9);
  std::normal_distribution<double> noise(0, 1);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = i / fs;
    angle[i] = 0.4 + w0 * t + 0.3 * std::sin(2.0 * t), speed[i] = w0 + 0.6 * std::cos(2.0 * t);
    accel[i] = -1.2 * std::sin(2.0 * t);
    reading[i] = 40 * std::sin(3 * angle[i]) + noise(rng);
    link_alpha[i] = 200 * std::cos(angle[i]);
  }
  const CrankTrack crank{angle, speed, accel};
  for (SensorAxis axis : {SensorAxis::tangential, SensorAxis::normal})
    for (double corner : {0.0, 0.5}) {
      AccelerometerMount m;
      m.channel = "x";
      m.link = SensedLink::coupler;
      m.axis = axis;
      m.distance_m = 0.25;
      m.offset_m = 0.012;
      m.axis_sign = -1;
      m.high_pass_corner_hz = corner;
      const LinkTable table(rig, m.link);
      const std::vector<SensedLinkMotion> track = nominal_link_track(rig, m.link, crank);
      std::vector<double> two_step(n), one_pass(n);
      restore_dc_coupled_reading(rig, m, track, fs, reading, two_step);
      if (axis == SensorAxis::tangential) angular_acceleration_from_tangential(rig, m, track, two_step, two_step);
      else angular_speed_squared_from_normal(rig, m, track, two_step, link_alpha, two_step);
      convert_reading(rig, m, table, crank, fs, reading, link_alpha, one_pass);
      double peak = 0, diff = 0;
      for (std::size_t i = 0; i < n; ++i)
        peak = std::max(peak, std::abs(two_step[i])), diff = std::max(diff, std::abs(one_pass[i] - two_step[i]));
      EXPECT_LT(diff, 1e-9 * peak) << to_string(axis) << " corner " << corner;
    }
}

}  // namespace
}  // namespace fourbar
