// The links' ringing (virtual_rig/link_ringing.hpp) against the closed-form
// impulse response of a damped oscillator, independent of the step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/units.hpp"
#include "virtual_rig/link_ringing.hpp"

namespace fourbar {
namespace {

using units::kPi;

LinkMode coupler_mode() {
  LinkMode m;
  m.link = RingingLink::coupler;
  m.frequency_hz = 600;
  m.damping_ratio = 0.03;
  m.modal_mass_kg = 0.2;
  m.shape_at_bearing = 0.8;
  m.shape_at_sensor = 0.5;
  return m;
}

/// Transverse acceleration at the sensor τ after an impulse P⊥ (closed form):
/// q = A e^{−στ} sin(ω_d τ), A = φ_b P⊥ / (m ω_d);  a = φ_s q̈.
double closed_form(const LinkMode& m, double p_across, double tau) {
  const double w = 2 * kPi * m.frequency_hz, sigma = m.damping_ratio * w, wd = w * std::sqrt(1 - m.damping_ratio * m.damping_ratio);
  const double amp = m.shape_at_bearing * p_across / (m.modal_mass_kg * wd);
  return m.shape_at_sensor * amp * std::exp(-sigma * tau) * ((sigma * sigma - wd * wd) * std::sin(wd * tau) - 2 * sigma * wd * std::cos(wd * tau));
}

TEST(LinkRinging, OneImpulseRingsAsTheClosedForm) {
  const LinkMode m = coupler_mode();
  LinkRinging r({m}, {{0.01, 0.3, -0.2}});
  for (int i = 0; i < 400; ++i) {
    const double t = 0.01 + i * 1.0 / 12800;
    r.advance_to(t);
    EXPECT_NEAR(r.sensor_acceleration(ChannelRole::coupler_tangential), closed_form(m, 0.3, t - 0.01),
                1e-9 * std::abs(closed_form(m, 0.3, 0)) + 1e-9)
        << "t " << t;
  }
}

TEST(LinkRinging, ResultDoesNotDependOnTheStep) {
  const std::vector<BearingImpulse> impulses{{0.001, 0.5, 0.1}, {0.0043, -0.2, 0.4}, {0.0071, 0.1, -0.3}};
  LinkMode rocker = coupler_mode();
  rocker.link = RingingLink::rocker, rocker.frequency_hz = 720;
  LinkRinging coarse({coupler_mode(), rocker}, impulses), fine({coupler_mode(), rocker}, impulses);
  for (int i = 1; i <= 100; ++i) {
    const double t = i * 1e-4;
    for (int k = 1; k <= 7; ++k) fine.advance_to(t - 1e-4 + k * 1e-4 / 7);
    coarse.advance_to(t);
    for (ChannelRole role : {ChannelRole::coupler_tangential, ChannelRole::rocker_tangential})
      EXPECT_NEAR(coarse.sensor_acceleration(role), fine.sensor_acceleration(role), 1e-9) << "t " << t;
  }
  // Each link rings with its own modes only; a normal-axis sensor sees none.
  EXPECT_NE(coarse.sensor_acceleration(ChannelRole::coupler_tangential), coarse.sensor_acceleration(ChannelRole::rocker_tangential));
  EXPECT_EQ(coarse.sensor_acceleration(ChannelRole::coupler_normal), 0.0);
}

TEST(LinkRinging, QueriesInAnyOrderMatchTheSequentialAdvance) {
  // A multiplexed channel and an analog filter's sub-steps ask for times out
  // of order: the stateless query must give what advancing in order gives.
  const std::vector<BearingImpulse> impulses{{0.001, 0.5, 0.1}, {0.0043, -0.2, 0.4}, {0.0071, 0.1, -0.3}};
  LinkMode rocker = coupler_mode();
  rocker.link = RingingLink::rocker, rocker.frequency_hz = 720;
  LinkRinging seq({coupler_mode(), rocker}, impulses);
  const LinkRinging any({coupler_mode(), rocker}, impulses);
  EXPECT_EQ(any.sensor_acceleration_at(0.0005, ChannelRole::coupler_tangential), 0.0);  // before the first impulse
  std::vector<double> times, expected;
  for (int i = 1; i <= 120; ++i) {
    const double t = 0.0009 + i * 0.77e-4;
    seq.advance_to(t);
    times.push_back(t);
    expected.push_back(seq.sensor_acceleration(ChannelRole::rocker_tangential));
  }
  double largest = 0;
  for (std::size_t k = times.size(); k-- > 0;) {  // backwards
    EXPECT_NEAR(any.sensor_acceleration_at(times[k], ChannelRole::rocker_tangential), expected[k], 1e-9) << "t " << times[k];
    largest = std::max(largest, std::abs(expected[k]));
  }
  EXPECT_GT(largest, 1.0);  // the check compares a real ringing, not zeros
}

TEST(LinkRinging, ImpulsesTakeTheirPartAcrossEachLink) {
  ImpactRecord along_coupler, across_coupler;
  along_coupler.time_s = 0.2, along_coupler.eta_rad = 0.3, along_coupler.theta3_rad = 0.3, along_coupler.theta4_rad = 0.3 - kPi / 2;
  along_coupler.result.normal_impulse_Ns = 1.0;
  across_coupler = along_coupler;
  across_coupler.time_s = 0.1, across_coupler.theta3_rad = 0.3 - kPi / 2, across_coupler.settle_normal_impulse_Ns = 0.5;
  const auto p = bearing_impulses({along_coupler, across_coupler});
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[0].time_s, 0.1);  // sorted by time
  EXPECT_NEAR(p[0].across_coupler_Ns, 1.5, 1e-12);  // impact plus settle impulse
  EXPECT_NEAR(p[1].across_coupler_Ns, 0.0, 1e-12);
  EXPECT_NEAR(p[1].across_rocker_Ns, 1.0, 1e-12);
}

}  // namespace
}  // namespace fourbar
