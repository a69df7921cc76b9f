// The impact law against the thesis's explicit forms (eq. 5.4-2, 5.4-3,
// corrected), Newton's restitution, the friction cases, and the energy
// identity ΔT = ω2·τ̂ − loss with the motor impulse that holds ω2.

#include <gtest/gtest.h>

#include <random>

#include "sim/three_mode/impact.hpp"
#include "sim/three_mode/thesis_reference.hpp"

namespace fourbar {
namespace {

struct ContactCase {
  CrankState crank;
  LinkMotion links;
  double eta;
};

/// A random configuration on the contact circle with random rates, pin approaching the wall.
ContactCase random_contact(std::mt19937& rng, const ClearanceModel& model) {
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), speed(-40, 40), rate(-5, 5);
  for (;;) {
    ContactCase c;
    c.crank = {angle(rng), speed(rng), 0.0};
    c.eta = angle(rng);
    c.links = model.following_links(c.crank, c.eta, 0.0);
    c.links.omega3_rad_s += rate(rng);
    c.links.omega4_rad_s += rate(rng);
    if (model.bearing(c.crank, c.links).normal_speed_m_s > 1e-3) return c;
  }
}

double theta(Vec2 u) { return std::atan2(u.y, u.x); }

TEST(Impact, AgreesWithThesisExplicitForms) {
  const Rig rig = thesis_rig();
  const double xi = 0.254e-3;
  const ClearanceModel model(rig, xi);
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit01(0, 1);
  int n_slip = 0, n_stick = 0;
  for (int i = 0; i < 3000; ++i) {
    const ContactCase c = random_contact(rng, model);
    const double e = unit01(rng);
    const ContactLaw law = i % 3 == 0 ? ContactLaw::smooth : i % 3 == 1 ? ContactLaw::rough : ContactLaw::stick_slip;
    const double mu = law == ContactLaw::stick_slip ? 0.5 * unit01(rng) : 0.0;
    const ImpactResult r = resolve_impact(model, c.crank, c.links, {e, law, mu});
    if (r.degenerate) continue;
    const BearingState b = model.bearing(c.crank, c.links);
    const double sigma = b.tangential_speed_m_s > 0 ? 1.0 : -1.0;
    const ThesisContactCase tc = law == ContactLaw::smooth ? ThesisContactCase::smooth
                                 : r.stuck                 ? ThesisContactCase::stick
                                                           : ThesisContactCase::slip;
    n_slip += tc == ThesisContactCase::slip;
    n_stick += tc == ThesisContactCase::stick;
    const ThesisImpactSolution t = thesis_impact(rig, xi, tc, e, mu, sigma, c.crank.angle_rad, theta(c.links.u3),
                                                 theta(c.links.u4), c.eta, c.crank.speed_rad_s,
                                                 c.links.omega3_rad_s, c.links.omega4_rad_s);
    const double ws = 1 + std::abs(c.links.omega3_rad_s) + std::abs(c.links.omega4_rad_s);
    EXPECT_NEAR(t.omega3_rad_s, r.after.omega3_rad_s, 1e-9 * ws) << i;
    EXPECT_NEAR(t.omega4_rad_s, r.after.omega4_rad_s, 1e-9 * ws) << i;
    const double fs = 1e-9 * (std::abs(r.normal_impulse_Ns) + std::abs(r.tangential_impulse_Ns) + 1e-6);
    EXPECT_NEAR(t.normal_impulse_Ns, r.normal_impulse_Ns, fs) << i;
    EXPECT_NEAR(t.tangential_impulse_Ns, -r.tangential_impulse_Ns, fs) << i;  // thesis f is on the bushing
  }
  EXPECT_GT(n_slip, 100);
  EXPECT_GT(n_stick, 100);
}

TEST(Impact, NewtonRestitutionAndTangentialLaws) {
  const Rig rig = thesis_rig();
  const ClearanceModel model(rig, 0.254e-3);
  std::mt19937 rng(22);
  std::uniform_real_distribution<double> unit01(0, 1);
  for (int i = 0; i < 1000; ++i) {
    const ContactCase c = random_contact(rng, model);
    const double e = unit01(rng), mu = unit01(rng);
    const ImpactResult s = resolve_impact(model, c.crank, c.links, {e, ContactLaw::smooth, 0});
    const double vn = s.normal_speed_before_m_s, vt = s.tangential_speed_before_m_s;
    EXPECT_NEAR(s.normal_speed_after_m_s, -e * vn, 1e-12);
    EXPECT_EQ(s.tangential_impulse_Ns, 0.0);
    EXPECT_GT(s.normal_impulse_Ns, 0.0);
    const ImpactResult r = resolve_impact(model, c.crank, c.links, {e, ContactLaw::rough, 0});
    if (!r.degenerate) {
      EXPECT_NEAR(r.normal_speed_after_m_s, -e * vn, 1e-12);
      EXPECT_NEAR(r.tangential_speed_after_m_s, 0.0, 1e-12);
    }
    const ImpactResult k = resolve_impact(model, c.crank, c.links, {e, ContactLaw::stick_slip, mu});
    if (k.degenerate) continue;
    EXPECT_NEAR(k.normal_speed_after_m_s, -e * vn, 1e-12);
    EXPECT_LE(std::abs(k.tangential_impulse_Ns), mu * k.normal_impulse_Ns * (1 + 1e-12));
    if (k.stuck) {
      EXPECT_NEAR(k.tangential_speed_after_m_s, 0.0, 1e-12);
    } else {  // sliding against the initial slip with the full Coulomb impulse
      EXPECT_NEAR(k.tangential_impulse_Ns, -(vt > 0 ? 1 : -1) * mu * k.normal_impulse_Ns, 1e-15);
    }
  }
}

TEST(Impact, EnergyIdentityWithMotorImpulse) {
  // ΔT = ω2·τ̂ − loss exactly; for e = 1 smooth the loss is zero although ΔT ≠ 0.
  const Rig rig = thesis_rig();
  const ClearanceModel model(rig, 0.254e-3);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> unit01(0, 1);
  double max_dT = 0;
  for (int i = 0; i < 1000; ++i) {
    const ContactCase c = random_contact(rng, model);
    const double e = i % 2 ? 1.0 : unit01(rng);
    const ContactLaw law = i % 4 < 2 ? ContactLaw::smooth : i % 4 == 2 ? ContactLaw::rough : ContactLaw::stick_slip;
    const ImpactResult r = resolve_impact(model, c.crank, c.links, {e, law, 0.3});
    const double T0 = model.kinetic_energy_J(c.crank, c.links), T1 = model.kinetic_energy_J(c.crank, r.after);
    const double work = c.crank.speed_rad_s * r.motor_impulse_Nms;
    EXPECT_NEAR(T1 - T0, work - r.energy_loss_J, 1e-12 * (1 + T0)) << i;
    // Independent form of the normal loss: ½·F·(1 − e)·v_n for the smooth law.
    if (law == ContactLaw::smooth) {
      EXPECT_NEAR(r.energy_loss_J, 0.5 * r.normal_impulse_Ns * (1 - e) * r.normal_speed_before_m_s, 1e-15);
      if (e == 1.0) EXPECT_NEAR(r.energy_loss_J, 0.0, 1e-15);
      max_dT = std::max(max_dT, std::abs(T1 - T0));
    }
    if (law == ContactLaw::rough && !r.degenerate) EXPECT_GE(r.energy_loss_J, -1e-15);
  }
  EXPECT_GT(max_dT, 1e-4);  // the kinetic energy itself does change (motor work)
}

}  // namespace
}  // namespace fourbar
