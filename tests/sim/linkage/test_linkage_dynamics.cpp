// The linkage model's stages at one instant against closed forms: the
// thesis model's accelerations and motor torque (ClearanceModel, closed form,
// thesis eqs. 4.1-20, 4.2-1, 3.3-1) with clearance at B and a pin force; and
// free fall of coupler and rocker when every joint has clearance and no pin
// touches its bushing; and, with elastic coupler and rocker, the mass matrix
// (assembled over each body's non-zero columns) against the bodies' own
// kinetic energies (sim/flex) and the accelerations against M·z̈ = Q.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mechanism/kinematics.hpp"
#include "sim/three_mode/model.hpp"
#include "sim/flex/elastic_body.hpp"
#include "sim/linkage/linkage_dynamics.hpp"
#include "support/linkage_state.hpp"

namespace fourbar {
namespace {

LinkageSpec spec_with(const std::array<double, 3>& xi) {
  LinkageSpec s;
  s.clearance_m = xi;
  s.law = {1e10, 1.5, DampingLaw::calibrated, 0.5};
  return s;
}

TEST(LinkageDynamics, ClearanceAtBMatchesTheClosedFormModel) {
  const Rig rig = thesis_rig();
  const double xi = 0.254e-3;
  const ClearanceModel cm(rig, xi);
  const LinkageModel lm = build_linkage(rig, spec_with({0, xi, 0}));
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 50; ++k) {
    const CrankState c{3.2 * u(gen), 40 * u(gen), 300 * u(gen)};
    const NominalMotion nm = solve_motion(rig, c);
    LinkageCoordinates q;
    q.crank = c;
    q.u2 = unit(c.angle_rad);
    q.u = {unit(std::atan2(nm.pose.u3.y, nm.pose.u3.x) + 1e-3 * u(gen)),
           unit(std::atan2(nm.pose.u4.y, nm.pose.u4.x) + 1e-3 * u(gen))};
    q.q_offsets = ZVec::Zero(2);
    q.z_rate = ZVec::Zero(3);
    q.z_rate << nm.omega3_rad_s + u(gen), nm.omega4_rad_s + u(gen), c.speed_rad_s;
    LinkageWorkspace w;
    forward_kinematics(lm, q, w);
    const Vec2 P{100 * u(gen), 100 * u(gen)};
    w.pair[1].pin_force_N = P;
    solve_accelerations(lm, q, w);
    const LinkMotion m{q.u[0], q.u[1], q.z_rate(0), q.z_rate(1)};
    double a3 = 0, a4 = 0;
    cm.forced_accelerations(c, q.u2, m, P, a3, a4);
    const double tau = cm.crank_torque_Nm(c, q.u2, m, a3, P);
    EXPECT_NEAR(w.z_accel(0), a3, 1e-11 * (1 + std::abs(a3))) << k;
    EXPECT_NEAR(w.z_accel(1), a4, 1e-11 * (1 + std::abs(a4))) << k;
    EXPECT_NEAR(w.crank_torque_Nm, tau, 1e-11 * (1 + std::abs(tau))) << k;
    // Bearing geometry and relative velocity as the closed-form model's.
    const BearingState b = cm.bearing(c, q.u2, m);
    EXPECT_NEAR(w.pair[1].gap_m, b.gap_m, 1e-15);
    EXPECT_NEAR(w.pair[1].normal_speed_m_s, b.normal_speed_m_s, 1e-12 * (1 + std::abs(b.normal_speed_m_s)));
    EXPECT_NEAR(w.pair[1].tangential_speed_m_s, b.tangential_speed_m_s,
                1e-12 * (1 + std::abs(b.tangential_speed_m_s)));
    // Kinetic and potential energy as the thesis model's.
    EXPECT_NEAR(kinetic_energy_J(w, q), cm.kinetic_energy_J(c, m), 1e-12);
    EXPECT_NEAR(potential_energy_J(lm, w, q), cm.potential_energy_J(c, m), 1e-12);
  }
}

TEST(LinkageDynamics, CouplerAndRockerFallFreelyWithEveryPinInsideItsBushing) {
  const Rig rig = thesis_rig();
  const double xi = 0.254e-3;
  const LinkageModel lm = build_linkage(rig, spec_with({xi, xi, xi}));
  ASSERT_EQ(lm.coordinates(), 6);
  const CrankState c{0.7, 36.6, 5.0};
  const NominalMotion nm = solve_motion(rig, c);
  LinkageCoordinates q;
  q.crank = c;
  q.u2 = unit(c.angle_rad);
  q.u = {nm.pose.u3, nm.pose.u4};
  q.q_offsets = ZVec::Zero(6);
  q.q_offsets(2) = 0.3 * xi;  // the pins off-centre, but inside their bushings
  q.q_offsets(5) = -0.2 * xi;
  q.z_rate = ZVec::Zero(7);
  q.z_rate << 2.0, -3.0, 0.01, -0.02, 0.005, 0.003, c.speed_rad_s;
  LinkageWorkspace w;
  forward_kinematics(lm, q, w);
  std::array<double, kJoints> chi{};
  pair_forces(lm, chi, w);
  for (int j : lm.clearance_joints()) EXPECT_LT(w.pair[static_cast<std::size_t>(j)].penetration_m, 0.0);
  solve_accelerations(lm, q, w);
  for (int b : {1, 2}) {
    const BodyFrame& f = w.body[static_cast<std::size_t>(b)];
    const Vec2 r = lm.body(b).centre_m.x * f.u;
    // Centre acceleration J_c·z̈ + bias = (0, −g); angular acceleration 0.
    ZJac Jc = f.Jp;
    Jc.row(0) += -r.y * f.Jw;
    Jc.row(1) += r.x * f.Jw;
    const Eigen::Vector2d a = Jc * w.z_accel;
    const Vec2 bias = f.a_bias + f.alpha_bias * r.perp() - f.omega * f.omega * r;
    EXPECT_NEAR(a(0) + bias.x, 0.0, 1e-10) << b;
    EXPECT_NEAR(a(1) + bias.y, -rig.gravity_m_s2, 1e-10) << b;
    EXPECT_NEAR(f.Jw.dot(w.z_accel) + f.alpha_bias, 0.0, 1e-10) << b;
  }
  // The motor holds the crank alone: τ = I_O2·α2 + m2·g·S2·cos θ2.
  const double tau = rig.crank.inertia_about_joint() * c.accel_rad_s2 +
                     rig.crank.mass_kg * rig.gravity_m_s2 * rig.crank.mass_centre_m * std::cos(c.angle_rad);
  EXPECT_NEAR(w.crank_torque_Nm, tau, 1e-12 * (1 + std::abs(tau)));
}

TEST(LinkageDynamics, ElasticMassMatrixHoldsTheBodiesKineticEnergiesAndSolvesTheAccelerations) {
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  const double xi = 0.254e-3;
  LinkageSpec spec = spec_with({xi, xi, xi});
  spec.elastic = {false, true, true};
  spec.elastic_modes = 4;
  const LinkageModel lm = build_linkage(rig, spec);
  const int n = lm.coordinates();
  ASSERT_EQ(n, 6 + 8);
  std::mt19937 gen(11);
  for (int k = 0; k < 20; ++k) {
    LinkageCoordinates q;
    random_linkage_state(rig, lm, gen, q);
    const CrankState c = q.crank;
    LinkageWorkspace w;
    forward_kinematics(lm, q, w);
    std::array<double, kJoints> chi{};
    pair_forces(lm, chi, w);
    solve_accelerations(lm, q, w);
    // ½·żᵀ·M·ż against the crank's ½·I_O2·ω2² plus each elastic body's
    // kinetic energy from its frame and modes (sim/flex, no assembly).
    double bodies = 0.5 * rig.crank.inertia_about_joint() * c.speed_rad_s * c.speed_rad_s;
    for (int b : {1, 2}) {
      ElasticBodyData data(*lm.elastic(b));
      bodies += kinetic_energy(*lm.elastic(b), data, frame_state(w, b, false), modal_state(lm, q, w, b, false));
    }
    EXPECT_NEAR(kinetic_energy_J(w, q), bodies, 1e-12 * bodies) << k;
    EXPECT_LT((w.M - w.M.transpose()).cwiseAbs().maxCoeff(), 1e-14 * w.M.cwiseAbs().maxCoeff()) << k;
    // The written-out Cholesky solve against Eigen's LU of the same rows.
    const ZVec rhs = w.Q.head(n) - w.M.block(0, n, n, 1) * c.accel_rad_s2;
    const Eigen::VectorXd lu = Eigen::MatrixXd(w.M.topLeftCorner(n, n)).partialPivLu().solve(Eigen::VectorXd(rhs));
    for (int i = 0; i < n; ++i)
      EXPECT_NEAR(w.z_accel(i), lu(i), 1e-9 * (1 + lu.cwiseAbs().maxCoeff())) << k << " coordinate " << i;
  }
}

/// Calls f(model, state, k) for 20 seeded states in each of four clearance
/// layouts (B; A, B, O4; A; O4 at twice the clearance), elastic coupler and
/// rocker with two modes.
template <class F>
void for_each_layout_state(unsigned seed, F&& f) {
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  const double xi = 0.254e-3;
  for (const std::array<double, 3>& clearances :
       {std::array<double, 3>{0, xi, 0}, std::array<double, 3>{xi, xi, xi}, std::array<double, 3>{xi, 0, 0},
        std::array<double, 3>{0, 0, 2 * xi}}) {
    LinkageSpec spec = spec_with(clearances);
    spec.elastic = {false, true, true};
    spec.elastic_modes = 2;
    const LinkageModel lm = build_linkage(rig, spec);
    std::mt19937 gen(seed);
    for (int k = 0; k < 20; ++k) {
      LinkageCoordinates q;
      random_linkage_state(rig, lm, gen, q);
      f(lm, q, k);
    }
  }
}

// The witnesses' positions-only pass (pair_penetrations, every step) gives
// the bits of the full kinematics' penetration, for a joint placed by its
// offsets (A, O4) and for the loop-closing one (whose pin the random links'
// 1 mrad can push through the wall), and |e| − ξ of the pin's and the
// bushing's world sites.
TEST(LinkageDynamics, PairPenetrationsAreTheKinematicsOwn) {
  for_each_layout_state(29, [](const LinkageModel& lm, const LinkageCoordinates& q, int k) {
    LinkageWorkspace w;
    forward_kinematics(lm, q, w);
    const std::array<double, kJoints> pen = pair_penetrations(lm, q);
    for (int j : lm.clearance_joints()) {
      const PairState& ps = w.pair[static_cast<std::size_t>(j)];
      EXPECT_EQ(pen[static_cast<std::size_t>(j)], ps.penetration_m) << "joint " << j << ", state " << k;
      const JointData& jd = lm.joint(j);
      const Vec2 e = site_position(w, jd.pin) - site_position(w, jd.bushing);
      EXPECT_NEAR(pen[static_cast<std::size_t>(j)], std::sqrt(dot(e, e)) - jd.clearance_m, 1e-15)
          << "joint " << j << ", state " << k;
    }
  });
}

// pair_kinematics (poses and rates, no Jacobians: the contact books' path)
// against forward_kinematics (J_rel·ż), seeded states with random rates.
TEST(LinkageDynamics, PairKinematicsAreTheJacobiansOwnVelocities) {
  for_each_layout_state(31, [](const LinkageModel& lm, const LinkageCoordinates& q, int k) {
    LinkageWorkspace full, light;
    forward_kinematics(lm, q, full);
    pair_kinematics(lm, q, light);
    for (int j : lm.clearance_joints()) {
      const PairState &a = full.pair[static_cast<std::size_t>(j)], &b = light.pair[static_cast<std::size_t>(j)];
      EXPECT_EQ(a.penetration_m, b.penetration_m) << "joint " << j << ", state " << k;
      EXPECT_EQ(a.normal.x, b.normal.x);
      EXPECT_EQ(a.normal.y, b.normal.y);
      const double speed = std::hypot(a.normal_speed_m_s, a.tangential_speed_m_s);
      ASSERT_GT(speed, 0.0);
      EXPECT_NEAR(a.normal_speed_m_s, b.normal_speed_m_s, 1e-13 * speed) << "joint " << j << ", state " << k;
      EXPECT_NEAR(a.tangential_speed_m_s, b.tangential_speed_m_s, 1e-13 * speed) << "joint " << j << ", state " << k;
      EXPECT_EQ(a.omega_pin_rad_s, b.omega_pin_rad_s);
      EXPECT_EQ(a.omega_bushing_rad_s, b.omega_bushing_rad_s);
    }
  });
}

}  // namespace
}  // namespace fourbar
