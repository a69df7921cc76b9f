// The compliant contact's force law and its stiff integrator on a single
// mass m hitting a wall at speed v (penetration δ, m·δ̈ = −F): closed forms
// for a linear spring–dashpot and a Hertz contact, the effective restitution
// of each damping law (tabulated), the friction ramp, the stiffness law.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "sim/contact/contact_force.hpp"
#include "sim/compliant/contact_stiffness.hpp"
#include "sim/integrate/stiff_integrator.hpp"

namespace fourbar {
namespace {

/// One mass on the wall: y = (δ/δ_s, δ̇/v, 0…); the witness is δ. Contact
/// begins at t = 0 with δ = 0, δ̇ = v, and ends at the first root of δ.
struct Collision final : StiffSystem {
  double mass_kg, speed_m_s, length_m, time_s;  // scales: δ_s = length, t_s = length/speed
  std::function<double(double pen, double rate)> force;
  void rhs(double, const StiffState& y, StiffState& dy) override {
    dy = {};
    const double pen = y[0] * length_m, rate = y[1] * speed_m_s;
    dy[0] = y[1] * speed_m_s / length_m * time_s;
    dy[1] = -(pen > 0 ? force(pen, rate) : 0.0) / mass_kg / speed_m_s * time_s;
  }
  double witness(double, const StiffState& y) override { return y[0]; }
};

struct Outcome {
  double duration_s, rebound_m_s;
};

/// Integrates from onset to release; time is scaled by length/speed.
Outcome collide(Collision& c, double tol, StiffMethod method = StiffMethod::bdf) {
  c.time_s = c.length_m / c.speed_m_s;
  StiffIntegrator integ(tol, 2, kStiffSize, method);
  StiffState y{};
  y[1] = 1.0;
  integ.reset(c, 0.0, y);
  for (int i = 0; i < 1'000'000; ++i) {
    const auto s = integ.step(1e3);
    if (s.root < 0) {
      StiffState e;
      integ.interpolate(s.end, e);
      return {s.end * c.time_s, -e[1] * c.speed_m_s};
    }
  }
  ADD_FAILURE() << "no release";
  return {};
}

TEST(ContactForce, AdamsModesMatchTheLinearSpringDashpotToo) {
  // The comparison modes of the same integrator (bench_compliant --integrators):
  // root finding and dense output as with BDF, on a collision that is not stiff.
  const double m = 0.05, k = 2e7, v = 0.02, zeta = 0.3;
  const double wn = std::sqrt(k / m), c = 2 * zeta * std::sqrt(k * m), wd = wn * std::sqrt(1 - zeta * zeta);
  for (StiffMethod method : {StiffMethod::adams_fixed_point, StiffMethod::adams_newton}) {
    Collision col;
    col.mass_kg = m, col.speed_m_s = v, col.length_m = v / wn;
    col.force = [&](double pen, double rate) { return k * pen + c * rate; };
    const Outcome o = collide(col, 1e-12, method);
    EXPECT_NEAR(o.duration_s / (M_PI / wd), 1.0, 1e-8) << static_cast<int>(method);
    EXPECT_NEAR(o.rebound_m_s / (v * std::exp(-zeta * wn * M_PI / wd)), 1.0, 1e-8) << static_cast<int>(method);
  }
}

TEST(ContactForce, LinearSpringDashpotMatchesItsExactSolution) {
  // F = k·δ + c·δ̇ (unclamped): δ = (v/ω_d)·e^(−ζω_n t)·sin(ω_d t), so the
  // contact lasts π/ω_d and the mass leaves at v·e^(−ζω_n·π/ω_d).
  const double m = 0.05, k = 2e7, v = 0.02;
  for (double zeta : {0.0, 0.05, 0.3}) {
    const double wn = std::sqrt(k / m), c = 2 * zeta * std::sqrt(k * m), wd = wn * std::sqrt(1 - zeta * zeta);
    Collision col;
    col.mass_kg = m, col.speed_m_s = v, col.length_m = v / wn;
    col.force = [&](double pen, double rate) { return k * pen + c * rate; };
    const Outcome o = collide(col, 1e-12);
    const double t_exact = M_PI / wd, v_exact = v * std::exp(-zeta * wn * M_PI / wd);
    EXPECT_NEAR(o.duration_s / t_exact, 1.0, 1e-8) << "zeta " << zeta;
    EXPECT_NEAR(o.rebound_m_s / v_exact, 1.0, 1e-8) << "zeta " << zeta;
  }
}

TEST(ContactForce, HertzContactLastsTheHertzDuration) {
  // F = K·δ^1.5: δ_max = (5mv²/(4K))^(2/5), t_c = 2·(δ_max/v)·∫₀¹(1 − x^(5/2))^(−1/2) dx
  // = 2·(δ_max/v)·0.4·B(2/5, 1/2); elastic, so the rebound speed is v.
  const double m = 0.05;
  for (double K : {1e8, 1e10}) {
    for (double v : {0.001, 0.05}) {
      const NormalForceLaw law{K, 1.5, DampingLaw::hunt_crossley, 1.0};
      const double dmax = std::pow(5 * m * v * v / (4 * K), 0.4);
      const double integral = 0.4 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
      Collision col;
      col.mass_kg = m, col.speed_m_s = v, col.length_m = dmax;
      col.force = [&](double pen, double rate) { return normal_force_N(law, pen, rate, 0.0); };
      const Outcome o = collide(col, 1e-12);
      EXPECT_NEAR(o.duration_s / (2 * dmax / v * integral), 1.0, 1e-8) << K << " " << v;
      EXPECT_NEAR(o.rebound_m_s / v, 1.0, 1e-8);
    }
  }
}

double effective_restitution(DampingLaw d, double e) {
  const double m = 0.05, K = 1e10, v = 0.02;
  const NormalForceLaw law{K, 1.5, d, e};
  const double chi = hysteresis_factor(d, e, 1.5) / v;
  Collision col;
  col.mass_kg = m, col.speed_m_s = v, col.length_m = std::pow(5 * m * v * v / (4 * K), 0.4);
  col.force = [&](double pen, double rate) { return normal_force_N(law, pen, rate, chi); };
  return collide(col, 1e-11).rebound_m_s / v;
}

TEST(ContactForce, EffectiveRestitutionOfEachDampingLaw) {
  // The restitution each law really gives (rebound / approach speed, here
  // for m = 0.05 kg, K = 1e10 N/m^1.5, v = 20 mm/s; it depends on c and n
  // only) against the e it was derived from.
  std::printf("    e     calibrated  hunt-crossley  lankarani-nikravesh  flores\n");
  for (int i = 1; i <= 10; ++i) {
    const double e = 0.1 * i;
    const double cal = effective_restitution(DampingLaw::calibrated, e);
    const double hc = effective_restitution(DampingLaw::hunt_crossley, e);
    const double ln = effective_restitution(DampingLaw::lankarani_nikravesh, e);
    const double fl = effective_restitution(DampingLaw::flores, e);
    std::printf("    %.1f   %.4f      %.4f         %.4f               %.4f\n", e, cal, hc, ln, fl);
    // The default law gives the requested e (the issue asks 2 % over [0.3, 1]; it holds to 1e-6 over [0.1, 1]).
    EXPECT_NEAR(cal / e, 1.0, 1e-6) << "calibrated (the default) at e = " << e;
    if (i == 10) {
      EXPECT_NEAR(hc, 1.0, 1e-8);
      EXPECT_NEAR(ln, 1.0, 1e-8);
      EXPECT_NEAR(fl, 1.0, 1e-8);
    }
  }
  // Lankarani–Nikravesh is derived for e near 1 and rebounds far too fast at low e;
  // Flores et al. is within 2 % only from e = 0.7 up (measured 0.976·e there).
  EXPECT_GT(effective_restitution(DampingLaw::lankarani_nikravesh, 0.2), 0.6);
  EXPECT_NEAR(effective_restitution(DampingLaw::flores, 0.9) / 0.9, 1.0, 0.02);
  EXPECT_LT(effective_restitution(DampingLaw::flores, 0.3) / 0.3, 0.9);
}

TEST(ContactForce, NoAdhesionAndFrictionRamp) {
  const NormalForceLaw law{1e9, 1.5, DampingLaw::hunt_crossley, 0.5};
  EXPECT_EQ(normal_force_N(law, 1e-6, -1e3, 100.0), 0.0);  // leaving fast: clamped at zero, never pulls
  EXPECT_EQ(normal_force_N(law, -1e-6, 1.0, 100.0), 0.0);  // a gap
  const FrictionLaw f{0.3, 1e-4, 1e-3};
  EXPECT_EQ(friction_force_N(f, 10.0, 5e-5), 0.0);
  EXPECT_DOUBLE_EQ(friction_force_N(f, 10.0, 2e-3), -3.0);
  EXPECT_DOUBLE_EQ(friction_force_N(f, 10.0, -2e-3), 3.0);
  EXPECT_DOUBLE_EQ(friction_force_N(f, 10.0, 5.5e-4), -1.5);  // halfway up the cubic ramp
  EXPECT_NEAR(friction_ramp(f, 1e-3 - 1e-12), 1.0, 1e-8);    // continuous at v1
}

TEST(ContactStiffness, ConformalCylinderLaw) {
  // Steel on steel, L = 10 mm, ΔR = 0.254 mm: E* = E/(2(1 − ν²)), K = π·E*·L/(2√(2ΔR)).
  const double e_star = composite_modulus_Pa(210e9, 0.3, 210e9, 0.3);
  EXPECT_NEAR(e_star, 210e9 / (2 * 0.91), 1e-3);
  const double K = conformal_cylinder_stiffness(e_star, 0.01, 0.254e-3);
  EXPECT_NEAR(K, M_PI * e_star * 0.01 / (2 * std::sqrt(2 * 0.254e-3)), 1e-6 * K);
  EXPECT_NEAR(K / 8.04e10, 1.0, 0.01);
}

}  // namespace
}  // namespace fourbar
