// A sweep point runs its base scene's model: on the compliant scene the
// point's statistics are those of the compliant simulator itself (before,
// every sweep ran the three-mode model whatever the scene said); and a
// compliant scene whose stiffness comes from the rig's bearing gets the
// stiffness of each point's clearance, K = π·E*·L / (2·√(2·ξ)).

#include <gtest/gtest.h>

#include <memory>

#include "common/units.hpp"
#include "sim/compliant/compliant_simulator.hpp"
#include "sim/compliant/contact_stiffness.hpp"
#include "sim/studies/sweep.hpp"

namespace fourbar {
namespace {

constexpr int kSweepSkip = 1, kSweepCounted = 2;

/// The point's statistics from the compliant simulator run directly.
struct DirectCounts {
  double impacts_per_rev = 0, sum_normal_impulse_per_rev_Ns = 0, max_penetration_rel = 0;
};

DirectCounts compliant_directly(const Scene& base, const SweepPoint& p, const ClearanceSettings& s) {
  const ClearanceModel model(*base.rig, p.radial_clearance_m);
  const ConstantSpeedCrank crank(base.start_angle_rad, p.crank_speed_rad_s);
  CompliantSimulator sim(model, crank, s);
  sim.set_revolution_origin(base.start_angle_rad);
  sim.start_nominal(0.0);
  sim.advance_to(crank.time_at_angle(base.start_angle_rad + units::kTwoPi * (kSweepSkip + kSweepCounted)));
  DirectCounts d;
  for (int k = kSweepSkip; k < kSweepSkip + kSweepCounted; ++k) {
    d.impacts_per_rev += sim.revolutions()[static_cast<std::size_t>(k)].impacts / double(kSweepCounted);
    d.sum_normal_impulse_per_rev_Ns +=
        sim.revolutions()[static_cast<std::size_t>(k)].sum_normal_impulse_Ns / double(kSweepCounted);
  }
  d.max_penetration_rel = sim.diagnostics().max_penetration;
  return d;
}

SweepPoint one_point(const Scene& base, double clearance_m) {
  SweepGrid g;
  g.radial_clearance_m = {clearance_m};
  g.crank_speed_rad_s = {base.crank_speed_rad_s};
  g.restitution = {base.clearance.restitution};
  g.friction_coefficient = {base.clearance.friction_coefficient};
  g.skip_revolutions = kSweepSkip;
  g.revolutions = kSweepCounted;
  SweepPoint p = sweep_points(g).front();
  compute_sweep_point(base, g, p);
  return p;
}

TEST(SweepModel, CompliantSceneIsSweptWithTheCompliantModel) {
  const Scene base = load_scene(FOURBAR_SOURCE_DIR "/data/scenes/thesis_compliant_350rpm_e05.toml");
  ASSERT_EQ(base.clearance.model, ClearanceKind::compliant);
  const SweepPoint p = one_point(base, base.clearance_m());
  ASSERT_FALSE(p.failed()) << p.error;
  const DirectCounts d = compliant_directly(base, p, base.clearance);
  EXPECT_GT(d.impacts_per_rev, 0.0);
  EXPECT_EQ(p.impacts_per_rev, d.impacts_per_rev);
  EXPECT_EQ(p.sum_normal_impulse_per_rev_Ns, d.sum_normal_impulse_per_rev_Ns);
  EXPECT_EQ(p.max_penetration_rel, d.max_penetration_rel);
  // A compliant contact penetrates: µm against the three-mode model's round-off.
  EXPECT_GT(p.max_penetration_rel, 1e-4);
}

TEST(SweepModel, BearingStiffnessFollowsEachPointsClearance) {
  Scene base = load_scene(FOURBAR_SOURCE_DIR "/data/scenes/thesis_compliant_350rpm_e05.toml");
  Rig rig = *base.rig;  // steel pin and bushing, 10 mm long, no radii: the clearance is free
  rig.bearing.length_m = 10e-3;
  rig.bearing.pin_youngs_modulus_Pa = rig.bearing.bushing_youngs_modulus_Pa = 210e9;
  rig.bearing.pin_poisson_ratio = rig.bearing.bushing_poisson_ratio = 0.3;
  base.rig = std::make_shared<const Rig>(rig);
  base.clearance.compliant.stiffness_given = false;
  base.clearance.compliant.stiffness_N_per_m_n = 1e10;  // the scene's, for its own clearance: not the point's
  const double e_star = composite_modulus_Pa(210e9, 0.3, 210e9, 0.3);
  for (double clearance_m : {0.1e-3, 0.4e-3}) {
    const SweepPoint p = one_point(base, clearance_m);
    ASSERT_FALSE(p.failed()) << p.error;
    ClearanceSettings s = base.clearance;
    s.compliant.stiffness_N_per_m_n = conformal_cylinder_stiffness(e_star, 10e-3, clearance_m);
    const DirectCounts d = compliant_directly(base, p, s);
    EXPECT_EQ(p.sum_normal_impulse_per_rev_Ns, d.sum_normal_impulse_per_rev_Ns) << clearance_m;
    EXPECT_EQ(p.max_penetration_rel, d.max_penetration_rel) << clearance_m;
  }
}

}  // namespace
}  // namespace fourbar
