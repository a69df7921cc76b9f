// The matched theory with the compliant contact model (model = "compliant"):
// the same runs as the compliant simulator driven directly, the stiffness from
// the rig's bearing by the conformal-cylinder closed form, and a missing
// bearing named as bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/error.hpp"
#include "common/units.hpp"
#include "compare/matched_theory.hpp"
#include "sim/compliant/compliant_simulator.hpp"
#include "sim/drive/crank_motion.hpp"

namespace fourbar {
namespace {

constexpr double kXi = 0.254e-3;

TheorySettings compliant_theory(double stiffness) {
  TheorySettings s;
  s.model = ClearanceKind::compliant;
  s.restitution = 0.5;
  s.tolerance = 1e-8;
  s.warmup_revolutions = 1, s.averaged_revolutions = 2;
  s.compliant.stiffness_N_per_m_n = stiffness;
  s.compliant.stiffness_given = stiffness > 0;
  s.source = "session.toml [theory]";
  return s;
}

TEST(MatchedTheoryCompliant, IsTheCompliantSimulatorOnTheGrid) {
  const Rig rig = thesis_rig();
  const double w = units::rpm_to_rad_s(350);
  const CrankGrid grid{180, 0.0, 1.0};
  const TheorySettings s = compliant_theory(1e9);
  const MatchedTheory t = simulate_matched_theory(rig, kXi, w, grid, s);

  // The same run, driven directly: ω3 in the middle of every cell of the averaged turns.
  ClearanceSettings cs;
  cs.model = ClearanceKind::compliant;
  cs.restitution = 0.5;
  cs.tolerance = 1e-8;
  cs.compliant.stiffness_N_per_m_n = 1e9;
  cs.compliant.stiffness_given = true;
  const ClearanceModel model(rig, kXi);
  const ConstantSpeedCrank crank(0.0, w);
  CompliantSimulator sim(model, crank, cs);
  sim.set_revolution_origin(0.0);
  sim.start_nominal(0.0);
  const std::size_t n = 180;
  std::vector<double> times;
  for (std::size_t j = 0; j <= 2 * n * 2; ++j)
    times.push_back(crank.time_at_angle(units::kTwoPi * (1.0 + (static_cast<double>(j) - 1.0) / (2.0 * n))));
  sim.set_sample_times(times);
  sim.advance_to(crank.time_at_angle(units::kTwoPi * 3.0));
  const auto& omega3 = t.series[index_of(LinkQuantity::omega3)].clearance_revolutions;
  ASSERT_EQ(omega3.size(), 2 * n);
  ASSERT_EQ(sim.samples().size(), times.size());
  for (std::size_t i = 0; i < 2 * n; ++i)
    EXPECT_EQ(omega3[i], sim.samples()[2 * i + 1].links.omega3_rad_s) << i;

  // A compliant run: the pin goes into the wall (the three-mode model's penetration is round-off).
  EXPECT_GT(t.max_penetration_rel, 1e-3);
  EXPECT_LT(t.max_penetration_rel, 0.2);
  EXPECT_LT(t.energy_residual_rel, 1e-6);
  EXPECT_EQ(t.settings.model, ClearanceKind::compliant);
  TheorySettings three_mode = s;
  three_mode.model = ClearanceKind::three_mode;
  EXPECT_LT(simulate_matched_theory(rig, kXi, w, grid, three_mode).max_penetration_rel, 1e-6);
  for (const BearingImpact& b : t.impacts) {
    EXPECT_GE(b.pin_deg, 0.0);
    EXPECT_LT(b.pin_deg, 360.0);
    EXPECT_GT(b.normal_impulse_Ns, 0.0);
  }
}

TEST(MatchedTheoryCompliant, StiffnessFromTheRigBearingOrNamedWhenMissing) {
  Rig rig = thesis_rig();
  const double w = units::rpm_to_rad_s(350);
  const CrankGrid grid{90, 0.0, 1.0};
  TheorySettings s = compliant_theory(0.0);
  s.warmup_revolutions = 0, s.averaged_revolutions = 1;
  s.tolerance = 1e-6;
  try {
    simulate_matched_theory(rig, kXi, w, grid, s);
    ADD_FAILURE() << "no bearing to compute the stiffness from was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("contact_stiffness_N_per_m_n"), std::string::npos) << what;
    EXPECT_NE(what.find("session.toml [theory]"), std::string::npos) << what;
    EXPECT_NE(what.find("bearing_length_mm"), std::string::npos) << what;
  }
  // Steel on bronze, L = 12 mm: K = π·E*·L / (2·√(2ξ)), 1/E* = Σ (1 − ν²)/E.
  rig.bearing.length_m = 0.012;
  rig.bearing.pin_youngs_modulus_Pa = 210e9, rig.bearing.pin_poisson_ratio = 0.3;
  rig.bearing.bushing_youngs_modulus_Pa = 110e9, rig.bearing.bushing_poisson_ratio = 0.34;
  const double e_star = 1.0 / ((1 - 0.3 * 0.3) / 210e9 + (1 - 0.34 * 0.34) / 110e9);
  const double k = 3.141592653589793 * e_star * 0.012 / (2 * std::sqrt(2 * kXi));
  const MatchedTheory t = simulate_matched_theory(rig, kXi, w, grid, s);
  EXPECT_NEAR(t.settings.compliant.stiffness_N_per_m_n, k, 1e-12 * k);
  EXPECT_GT(t.max_penetration_rel, 0.0);
}

TEST(MatchedTheoryCompliant, LubricatedRigNeedsTheCompliantTheoryAndItsBearing) {
  Rig rig = thesis_rig();
  rig.bearing.lubricant_viscosity_Pa_s = 0.05;
  const double w = units::rpm_to_rad_s(350);
  const CrankGrid grid{90, 0.0, 1.0};
  TheorySettings three;
  three.restitution = 0.5, three.warmup_revolutions = 0, three.averaged_revolutions = 1;
  auto error_of = [&](const TheorySettings& s) {
    try {
      simulate_matched_theory(rig, kXi, w, grid, s);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    ADD_FAILURE() << "accepted";
    return std::string();
  };
  const std::string a = error_of(three);
  EXPECT_NE(a.find("no lubricant film"), std::string::npos) << a;
  TheorySettings s = compliant_theory(1e9);
  s.warmup_revolutions = 0, s.averaged_revolutions = 1;
  const std::string b = error_of(s);  // no bearing length for the film
  EXPECT_NE(b.find("lubricant_viscosity_Pa_s"), std::string::npos) << b;
  EXPECT_NE(b.find("bearing_length_mm"), std::string::npos) << b;
  rig.bearing.length_m = 0.01, rig.bearing.pin_radius_m = 0.01;
  const MatchedTheory t = simulate_matched_theory(rig, kXi, w, grid, s);
  EXPECT_EQ(t.settings.compliant.film.viscosity_Pa_s, 0.05);
  EXPECT_EQ(t.settings.compliant.film.length_m, 0.01);
}

}  // namespace
}  // namespace fourbar
