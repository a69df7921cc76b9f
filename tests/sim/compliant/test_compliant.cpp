// The compliant contact model on the thesis rig: energy balance with contact
// damping and wall friction, bounded penetration, its records, and the scene
// keys (rig bearing, stiffness law, rejected values).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/error.hpp"
#include "common/units.hpp"
#include "sim/compliant/compliant_simulator.hpp"
#include "sim/compliant/contact_stiffness.hpp"
#include "sim/three_mode/simulator.hpp"
#include "sim/scene.hpp"
#include "support/temp_dir.hpp"
#include "scene_error.hpp"

namespace fourbar {
namespace {

ClearanceSettings compliant(double e, double K, double mu, double tol) {
  ClearanceSettings s;
  s.model = ClearanceKind::compliant;
  s.restitution = e;
  s.friction_coefficient = mu;
  s.tolerance = tol;
  s.compliant.stiffness_N_per_m_n = K;
  return s;
}

TEST(Compliant, EnergyBalanceOverTenTurnsAndBoundedPenetration) {
  // ΔE (mechanical + elastic) = crank work − damping loss − friction loss.
  const ClearanceModel model(thesis_rig(), 0.254e-3);
  const double w = units::rpm_to_rad_s(350), T = units::kTwoPi / w;
  const ConstantSpeedCrank crank(0.0, w);
  for (const auto& [K, mu] : {std::pair{1e9, 0.0}, std::pair{1e10, 0.2}}) {
    CompliantSimulator sim(model, crank, compliant(0.5, K, mu, 1e-11));
    sim.set_revolution_origin(0.0);
    sim.start_nominal(0.0);
    sim.advance_to(10 * T);
    const ClearanceDiagnostics d = sim.diagnostics();
    SCOPED_TRACE("K = " + std::to_string(K) + ", mu = " + std::to_string(mu));
    EXPECT_LT(std::abs(d.energy_residual_J) / d.energy_scale_J, 1e-8);
    EXPECT_LT(d.max_energy_residual_J / d.energy_scale_J, 1e-8);
    EXPECT_GT(d.impact_loss_J, 0.0);
    if (mu > 0) EXPECT_GT(d.friction_loss_J, 0.0);
    else EXPECT_EQ(d.friction_loss_J, 0.0);
    if (mu == 0) EXPECT_GT(d.impacts, 0u);  // with mu = 0.2 the pin stays on the wall (docs/clearance-model.md)
    // Penetration: a few micrometres, far below ξ, with no growth over the run.
    EXPECT_GT(d.max_penetration, 0.0);
    EXPECT_LT(d.max_penetration, 0.1);
    for (const ImpactRecord& r : sim.impacts()) {
      EXPECT_GT(r.peak_force_N, 0.0);
      EXPECT_GE(r.contact_duration_s, 0.0);
      EXPECT_GE(r.contact_impulse_Ns, r.result.normal_impulse_Ns * (1 - 1e-12));
      EXPECT_LE(r.max_penetration_m, d.max_penetration * 0.254e-3 * (1 + 1e-12));
    }
  }
}

TEST(Compliant, FirstImpactTendsToTheThreeModeOneAsTheStiffnessGrows) {
  // Thesis rig, 350 rpm, e = 0.5: the pin leaves the wall near 373° and hits
  // it again; the first impact's time, approach speed and impulse (first
  // compression–restitution cycle) against the three-mode model's with the
  // same e, for K = 1e10, 1e11, 1e12 N/m^1.5. (Statistics over many turns do
  // not converge over this range: docs/clearance-model.md "Compliant contact".)
  const ClearanceModel model(thesis_rig(), 0.254e-3);
  const double w = units::rpm_to_rad_s(350), T = units::kTwoPi / w;
  const ConstantSpeedCrank crank(0.0, w);
  ClearanceSettings s3;
  s3.restitution = 0.5;
  ClearanceSimulator three(model, crank, s3);
  three.start_nominal(0.0);
  three.advance_to(1.2 * T);
  ASSERT_FALSE(three.impacts().empty());
  const ImpactRecord& ref = three.impacts().front();
  double last_dt = 1e300, last_dv = 1e300, last_dj = 1e300;
  std::printf("    K          dt_s       dv_rel     dJ_rel   (three-mode: t = %.7f s, v = %.4e m/s, J = %.4e N s)\n",
              ref.time_s, ref.result.normal_speed_before_m_s, ref.result.normal_impulse_Ns);
  for (double K : {1e10, 1e11, 1e12}) {
    CompliantSimulator sim(model, crank, compliant(0.5, K, 0.0, 1e-10));
    sim.start_nominal(0.0);
    sim.advance_to(1.2 * T);
    const ImpactRecord* first = nullptr;
    for (const ImpactRecord& r : sim.impacts())
      if (r.time_s > 0 && r.result.normal_speed_before_m_s > 1e-3) {
        first = &r;
        break;
      }
    ASSERT_NE(first, nullptr) << K;
    const double dt = std::abs(first->time_s - ref.time_s);
    const double dv = std::abs(first->result.normal_speed_before_m_s / ref.result.normal_speed_before_m_s - 1);
    const double dj = std::abs(first->result.normal_impulse_Ns / ref.result.normal_impulse_Ns - 1);
    std::printf("    %.0e   %.2e   %.2e   %.2e\n", K, dt, dv, dj);
    EXPECT_LT(dt, last_dt) << K;
    EXPECT_LT(dv, last_dv) << K;
    EXPECT_LT(dj, last_dj) << K;
    last_dt = dt, last_dv = dv, last_dj = dj;
  }
  EXPECT_LT(last_dt, 3e-5);
  EXPECT_LT(last_dv, 0.1);
  EXPECT_LT(last_dj, 0.1);
}

TEST(Compliant, StiffnessFromTheRigBearingAndBadInput) {
  testing::TempDir dir;
  std::string rig = testing::thesis_rig_toml();
  const std::string bearing = "pin_radius_mm = 10\nbushing_radius_mm = 10.254\nbearing_length_mm = 10\n"
                              "pin_youngs_modulus_GPa = 210\npin_poisson_ratio = 0.3\n"
                              "bushing_youngs_modulus_GPa = 210\nbushing_poisson_ratio = 0.3\n";
  auto with = [&](const std::string& extra) {
    std::string r = rig;
    const auto i = r.find("radial_mm");
    EXPECT_NE(i, std::string::npos);
    const auto eol = r.find('\n', i);
    return r.insert(eol + 1, extra);
  };
  const std::string scene = "rig = \"r.toml\"\nmodel = \"clearance\"\ncrank_speed_rpm = 350\noutputs = "
                            "[\"contact_force_N\", \"penetration_mm\"]\n[clearance]\nmodel = \"compliant\"\n"
                            "restitution = 0.5\n";
  dir.write("r.toml", with(bearing));
  const Scene s = load_scene(dir.write("s.toml", scene));
  EXPECT_EQ(s.clearance.model, ClearanceKind::compliant);
  EXPECT_EQ(s.clearance.compliant.damping, DampingLaw::calibrated);
  const double e_star = composite_modulus_Pa(210e9, 0.3, 210e9, 0.3);
  EXPECT_DOUBLE_EQ(s.clearance.compliant.stiffness_N_per_m_n, conformal_cylinder_stiffness(e_star, 0.01, 0.254e-3));

  auto error_of = [&](const std::string& rig_text, const std::string& scene_text) {
    return testing::scene_error(dir, rig_text, scene_text);
  };
  const auto has = testing::expect_names;
  auto swap = [](std::string t, const std::string& a, const std::string& b) { return t.replace(t.find(a), a.size(), b); };
  has(error_of(with(swap(bearing, "pin_poisson_ratio = 0.3", "pin_poisson_ratio = 0.5")), scene), "pin_poisson_ratio");
  has(error_of(with(swap(bearing, "bushing_youngs_modulus_GPa = 210", "bushing_youngs_modulus_GPa = 0")), scene),
      "bushing_youngs_modulus_GPa");
  // Finite in GPa, infinite in Pa: refused, not an infinite stiffness.
  has(error_of(with(swap(bearing, "pin_youngs_modulus_GPa = 210", "pin_youngs_modulus_GPa = 1e300")), scene),
      "pin_youngs_modulus_GPa");
  has(error_of(with(swap(bearing, "pin_radius_mm = 10", "pin_radius_mm = 10.1")), scene), "does not fit the bushing");
  has(error_of(with(bearing), scene + "radial_mm = 0.1\n"), "does not fit");
  has(error_of(rig, scene), "contact_stiffness_N_per_m_n");  // nothing to compute K from
  has(error_of(rig, scene + "contact_stiffness_N_per_m_n = -1e9\n"), "contact_stiffness_N_per_m_n");
  has(error_of(rig, scene + "contact_stiffness_N_per_m_n = 0\n"), "must be a positive number");
  has(error_of(with(bearing), scene + "contact_exponent = 1.0\n"), "contact_exponent");
  has(error_of(rig, scene + "contact_stiffness_N_per_m_n = 1e9\ncontact = \"rough\"\n"), "three-mode");
  has(error_of(rig, scene + "contact_stiffness_N_per_m_n = 1e9\nintegrator = \"odeint\"\n"), "integrator");
  has(error_of(rig, swap(scene, "restitution = 0.5", "restitution = 0") + "contact_stiffness_N_per_m_n = 1e9\n"),
      "restitution");
  has(error_of(rig, swap(scene, "model = \"compliant\"\n", "") + "damping = \"flores\"\n"), "only used with model");
}

}  // namespace
}  // namespace fourbar
