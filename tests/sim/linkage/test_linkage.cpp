// The planar linkage model against today's compliant model (rigid links, one
// clearance at the coupler–rocker joint: the same ODE in other coordinates),
// and its energy books with clearance in any joint.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "common/error.hpp"
#include "common/units.hpp"
#include "mechanism/kinematics.hpp"
#include "sim/compliant/compliant_simulator.hpp"
#include "sim/drive/measured_crank.hpp"
#include "sim/linkage/linkage_simulator.hpp"
#include "support/thesis_values.hpp"

namespace fourbar {
namespace {

using testing::kXi;

LinkageSpec spec_b(double e, double K, double mu, double tol) {
  LinkageSpec s;
  s.clearance_m = {0, kXi, 0};
  s.law = {K, 1.5, DampingLaw::calibrated, e};
  s.friction = {mu, 1e-4, 1e-3};  // CompliantSettings' defaults
  s.tolerance = tol;
  return s;
}

ClearanceSettings compliant(double e, double K, double mu, double tol) {
  ClearanceSettings s;
  s.model = ClearanceKind::compliant;
  s.restitution = e;
  s.friction_coefficient = mu;
  s.tolerance = tol;
  s.compliant.stiffness_N_per_m_n = K;
  return s;
}

using testing::relative_rms;

TEST(Linkage, RigidLinksWithClearanceAtBAgreeWithTheCompliantModel) {
  // Thesis rig, 350 rpm, e = 0.5, K = 1e10 N/m^1.5, μ = 0 and 0.2; both start
  // from the nominal links (pin centred, moving with the bushing) at t = 0;
  // α3 sampled at 720 crank angles over one turn.
  const Rig rig = thesis_rig();
  const double w = units::rpm_to_rad_s(350), T = units::kTwoPi / w;
  const ConstantSpeedCrank crank(0.0, w);
  const ClearanceModel cm(rig, kXi);
  std::vector<double> times;
  for (int i = 0; i <= 720; ++i) times.push_back(T * i / 720.0);
  for (double mu : {0.0, 0.2}) {
    const CompliantSettings defaults;
    EXPECT_EQ(defaults.friction_stick_speed_m_s, 1e-4);
    EXPECT_EQ(defaults.friction_slip_speed_m_s, 1e-3);
    CompliantSimulator ref(cm, crank, compliant(0.5, 1e10, mu, 1e-12));
    const NominalMotion nm = solve_motion(rig, crank.at(0.0));
    ref.set_sample_times(times);
    ref.start_free(0.0, LinkMotion{nm.pose.u3, nm.pose.u4, nm.omega3_rad_s, nm.omega4_rad_s});
    ref.advance_to(T);
    const LinkageModel lm = build_linkage(rig, spec_b(0.5, 1e10, mu, 1e-12));
    EXPECT_EQ(lm.coordinates(), 2);
    LinkageSimulator sim(lm, crank);
    sim.set_sample_times(times);
    sim.start_centred(0.0);
    sim.advance_to(T);
    ASSERT_EQ(ref.samples().size(), times.size());
    ASSERT_EQ(sim.samples().size(), times.size());
    std::vector<double> a, b, ta, tb, ka, kb;
    for (std::size_t i = 0; i < times.size(); ++i) {
      a.push_back(sim.samples()[i].alpha3_rad_s2);
      b.push_back(ref.samples()[i].alpha3_rad_s2);
      ta.push_back(sim.samples()[i].crank_torque_Nm);
      tb.push_back(ref.samples()[i].crank_torque_Nm);
      ka.push_back(sim.samples()[i].kinetic_energy_J + sim.samples()[i].potential_energy_J);
      kb.push_back(ref.samples()[i].kinetic_energy_J + ref.samples()[i].potential_energy_J);
    }
    const double err = relative_rms(a, b);
    std::printf("    mu = %.1f: relative RMS over one turn: alpha3 %.3e, crank torque %.3e, energy %.3e (%zu contacts vs %zu)\n",
                mu, err, relative_rms(ta, tb), relative_rms(ka, kb), sim.contacts().size(), ref.impacts().size());
    EXPECT_LE(err, 1e-8);
    EXPECT_LE(relative_rms(ta, tb), 1e-8);
    EXPECT_LE(relative_rms(ka, kb), 1e-10);
    EXPECT_EQ(sim.contacts().size(), ref.impacts().size());
    EXPECT_GT(ref.impacts().size(), 0u);
    for (std::size_t i = 0; i < std::min(sim.contacts().size(), ref.impacts().size()); ++i)
      EXPECT_NEAR(sim.contacts()[i].time_s, ref.impacts()[i].time_s, 1e-9);
  }
}

TEST(Linkage, AgreesWithTheCompliantModelUnderAMeasuredCrankMotion) {
  // The same comparison with the crank speed varying from turn to turn
  // (MeasuredSpeedCrank, α2 ≠ 0), μ = 0.1, over the second turn.
  const Rig rig = thesis_rig();
  const double w = units::rpm_to_rad_s(350), T = units::kTwoPi / w;
  const MeasuredSpeedCrank crank = MeasuredSpeedCrank::from_revolution_speeds(0.0, {0.97 * w, 1.04 * w, 0.99 * w});
  std::vector<double> times;
  for (int i = 0; i <= 720; ++i) times.push_back(T + T * i / 720.0);
  const ClearanceModel cm(rig, kXi);
  CompliantSimulator ref(cm, crank, compliant(0.5, 1e10, 0.1, 1e-12));
  const NominalMotion nm = solve_motion(rig, crank.at(0.0));
  ref.set_sample_times(times);
  ref.start_free(0.0, LinkMotion{nm.pose.u3, nm.pose.u4, nm.omega3_rad_s, nm.omega4_rad_s});
  ref.advance_to(2 * T);
  const LinkageModel lm = build_linkage(rig, spec_b(0.5, 1e10, 0.1, 1e-12));
  LinkageSimulator sim(lm, crank);
  sim.set_sample_times(times);
  sim.start_centred(0.0);
  sim.advance_to(2 * T);
  ASSERT_EQ(sim.samples().size(), times.size());
  ASSERT_EQ(ref.samples().size(), times.size());
  std::vector<double> a, b;
  for (std::size_t i = 0; i < times.size(); ++i) {
    a.push_back(sim.samples()[i].alpha3_rad_s2);
    b.push_back(ref.samples()[i].alpha3_rad_s2);
  }
  const double err = relative_rms(a, b);
  std::printf("    measured crank: relative RMS of alpha3 over the second turn %.3e\n", err);
  EXPECT_LE(err, 1e-8);
}

TEST(Linkage, EnergyBalanceWithClearanceInAnyJoint) {
  // Motor work = contact damping + friction dissipation + Δ(kinetic + potential
  // + contact elastic energy), per configuration of clearances, over 3 turns
  // (10 with clearance in all three joints) of the thesis rig at 350 rpm
  // (e = 0.5, K = 1e10, μ = 0.1), from centred pins.
  const Rig rig = thesis_rig();
  const double w = units::rpm_to_rad_s(350), T = units::kTwoPi / w;
  const ConstantSpeedCrank crank(0.0, w);
  const std::array<std::array<double, 3>, 4> cases{{{kXi, 0, 0}, {0, 0, kXi}, {kXi, kXi, kXi}, {0.1e-3, kXi, 0.05e-3}}};
  for (const auto& xi : cases) {
    LinkageSpec s = spec_b(0.5, 1e10, 0.1, 1e-11);
    s.clearance_m = xi;
    const LinkageModel lm = build_linkage(rig, s);
    LinkageSimulator sim(lm, crank);
    sim.start_centred(0.0);
    const double turns = xi[0] > 0 && xi[1] > 0 && xi[2] > 0 && xi[0] == xi[2] ? 10 : 3;
    sim.advance_to(turns * T);
    const LinkageDiagnostics d = sim.diagnostics();
    SCOPED_TRACE("clearances " + std::to_string(xi[0]) + ", " + std::to_string(xi[1]) + ", " + std::to_string(xi[2]));
    std::printf("    xi = (%.3g, %.3g, %.3g) mm, %g turns: work %.6e J, dissipated %.6e J, residual %.2e of E, counters %s\n",
                xi[0] * 1e3, xi[1] * 1e3, xi[2] * 1e3, turns, d.crank_work_J, d.dissipated_J,
                d.energy_residual_J / d.energy_scale_J, sim.integrator_counters().c_str());
    EXPECT_LT(std::abs(d.energy_residual_J) / d.energy_scale_J, 1e-8);
    EXPECT_LT(d.max_energy_residual_J / d.energy_scale_J, 1e-8);
    double sum = 0;
    for (int j = 0; j < kJoints; ++j) {
      const LinkageJointBooks& b = d.joint[static_cast<std::size_t>(j)];
      sum += b.contact_loss_J + b.friction_loss_J + b.film_loss_J;
      if (xi[static_cast<std::size_t>(j)] == 0) {
        EXPECT_EQ(b.contact_time_s + b.free_time_s, 0.0);
        continue;
      }
      EXPECT_GT(b.contact_loss_J, 0.0) << to_string(static_cast<LinkJoint>(j));
      EXPECT_GE(b.friction_loss_J, 0.0);
      EXPECT_NEAR(b.contact_time_s + b.free_time_s, turns * T, 1e-9);
      EXPECT_GT(b.max_penetration_m, 0.0);
      EXPECT_LT(b.max_penetration_m, 0.2 * xi[static_cast<std::size_t>(j)]);
    }
    EXPECT_NEAR(sum, d.dissipated_J, 1e-12 * d.energy_scale_J);
    int seen[kJoints] = {0, 0, 0};
    for (const LinkageContact& c : sim.contacts()) {
      ++seen[c.joint];
      EXPECT_GT(xi[static_cast<std::size_t>(c.joint)], 0.0);
      EXPECT_GE(c.release_time_s, c.time_s);
      EXPECT_GE(c.contact_impulse_Ns, c.impact_impulse_Ns * (1 - 1e-9));
    }
    for (int j = 0; j < kJoints; ++j)
      if (xi[static_cast<std::size_t>(j)] > 0) EXPECT_GT(seen[j], 0) << to_string(static_cast<LinkJoint>(j));
  }
}

TEST(Linkage, RejectsALinkageWithoutClearance) {
  LinkageSpec s = spec_b(0.5, 1e10, 0.0, 1e-10);
  s.clearance_m = {0, 0, 0};
  EXPECT_THROW(build_linkage(thesis_rig(), s), InputError);
  s.clearance_m = {-1e-4, kXi, 0};
  EXPECT_THROW(build_linkage(thesis_rig(), s), InputError);
  s.clearance_m = {0, kXi, 0};
  s.law.stiffness = 0;
  EXPECT_THROW(build_linkage(thesis_rig(), s), InputError);
}

}  // namespace
}  // namespace fourbar
