// An accelerometer on the linkage model's coupler and rocker: on rigid links
// the closed form analyze/conversion.hpp inverts (m_t = a_J·n + r·α − h·ω² +
// g·cos θ); on an elastic coupler with one mode, at mid-span (slope 0, Φy = 1)
// the same plus the modal part η̈ − ω²·η.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mechanism/kinematics.hpp"
#include "sim/linkage/linkage_sensor.hpp"
#include "support/linkage_state.hpp"

namespace fourbar {
namespace {

LinkageSpec spec_at_b(bool elastic) {
  LinkageSpec s;
  s.clearance_m = {0, 0.254e-3, 0};
  s.law = {1e10, 1.5, DampingLaw::calibrated, 0.5};
  s.elastic = {false, elastic, false};
  s.elastic_modes = 1;
  return s;
}

/// m_t of analyze/conversion.hpp (sign +1) for a link of direction u, speed ω, acceleration α.
double closed_form(Vec2 aJ, Vec2 u, double om, double al, double r, double h, double g) {
  return dot(aJ, u.perp()) + r * al - h * om * om + g * u.x;
}

TEST(LinkageSensor, RigidLinksReadTheClosedForm) {
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  const LinkageModel lm = build_linkage(rig, spec_at_b(false));
  std::mt19937 gen(11);
  for (int k = 0; k < 20; ++k) {
    LinkageCoordinates q;
    random_linkage_state(rig, lm, gen, q);
    LinkageWorkspace w;
    forward_kinematics(lm, q, w);
    solve_accelerations(lm, q, w);
    const double l2 = rig.crank.length_m, a2 = q.crank.accel_rad_s2, w2 = q.crank.speed_rad_s;
    const Vec2 aA = l2 * (a2 * q.u2.perp() - w2 * w2 * q.u2);
    for (auto [r, h] : {std::pair{0.309, 0.0}, std::pair{0.15, 0.01}}) {
      const SensorReading s = sensor_reading(lm, q, w, {1, r, h});
      const double ref = closed_form(aA, q.u[0], q.z_rate(0), w.z_accel(0), r, h, rig.gravity_m_s2);
      EXPECT_NEAR(s.tangential_m_s2, ref, 1e-10 * (1 + std::abs(ref))) << k;
    }
    // Rocker: its first joint O4 is fixed.
    const SensorReading s4 = sensor_reading(lm, q, w, {2, 0.2, 0.0});
    const double ref4 = closed_form({0, 0}, q.u[1], q.z_rate(1), w.z_accel(1), 0.2, 0.0, rig.gravity_m_s2);
    EXPECT_NEAR(s4.tangential_m_s2, ref4, 1e-10 * (1 + std::abs(ref4))) << k;
    EXPECT_EQ(midspan_deflection_m(lm, q, w, 1), 0.0);
  }
}

TEST(LinkageSensor, ElasticCouplerAddsTheModalPart) {
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  const LinkageModel lm = build_linkage(rig, spec_at_b(true));
  const int i = lm.modal_index(1);
  std::mt19937 gen(13);
  double largest = 0;
  for (int k = 0; k < 20; ++k) {
    LinkageCoordinates q;
    random_linkage_state(rig, lm, gen, q);
    LinkageWorkspace w;
    forward_kinematics(lm, q, w);
    solve_accelerations(lm, q, w);
    const double l2 = rig.crank.length_m, a2 = q.crank.accel_rad_s2, w2 = q.crank.speed_rad_s;
    const Vec2 aA = l2 * (a2 * q.u2.perp() - w2 * w2 * q.u2);
    const double L = rig.coupler.length_m, om = q.z_rate(0);
    const double rigid = closed_form(aA, q.u[0], om, w.z_accel(0), L / 2, 0.0, rig.gravity_m_s2);
    const double modal = w.z_accel(i) - om * om * q.q_offsets(i);
    const SensorReading s = sensor_reading(lm, q, w, {1, L / 2, 0.0});
    EXPECT_NEAR(s.tangential_m_s2, rigid + modal, 1e-9 * (1 + std::abs(rigid) + std::abs(modal))) << k;
    EXPECT_DOUBLE_EQ(midspan_deflection_m(lm, q, w, 1), q.q_offsets(i));
    largest = std::max(largest, std::abs(modal) / (1 + std::abs(rigid)));
  }
  EXPECT_GT(largest, 1e-3);  // the modal part is not negligible at these states
}

}  // namespace
}  // namespace fourbar
