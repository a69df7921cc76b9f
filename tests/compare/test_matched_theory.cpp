#include <gtest/gtest.h>

#include <cmath>

#include "common/units.hpp"
#include "compare/matched_theory.hpp"
#include "compare/metrics.hpp"
#include "compare/recording_comparison.hpp"
#include "mechanism/kinematics.hpp"

namespace fourbar {
namespace {

Rig thesis() { return thesis_rig(); }  // Table 6.1/7.1, clearance 0.254 mm

TEST(MatchedTheory, NominalSeriesOnTheGridAreTheClosedForm) {
  const Rig rig = thesis();
  const double w = units::rpm_to_rad_s(350);
  TheorySettings s;
  s.warmup_revolutions = 1, s.averaged_revolutions = 1;
  const CrankGrid grid{720, 0.0, 1.0};
  const MatchedTheory t = simulate_matched_theory(rig, 0.254e-3, w, grid, s);
  double a3_rms = rms(t.series[index_of(LinkQuantity::alpha3)].nominal);
  for (std::size_t k = 0; k < 720; k += 7) {
    const NominalMotion m = solve_motion(rig, CrankState{grid.angle_rad(static_cast<double>(k)), w, 0.0});
    EXPECT_NEAR(t.series[index_of(LinkQuantity::omega3)].nominal[k], m.omega3_rad_s, 1e-12);
    EXPECT_NEAR(t.series[index_of(LinkQuantity::omega4)].nominal[k], m.omega4_rad_s, 1e-12);
    // Cell mean vs point value: second order in the half-degree cell.
    EXPECT_NEAR(t.series[index_of(LinkQuantity::alpha3)].nominal[k], m.alpha3_rad_s2, 1e-4 * a3_rms);
  }
}

TEST(MatchedTheory, TinyClearanceTendsToTheNominalMechanism) {
  const Rig rig = thesis();
  TheorySettings s;
  s.warmup_revolutions = 1, s.averaged_revolutions = 2;
  const CrankGrid grid{360, 0.0, 1.0};
  const MatchedTheory t = simulate_matched_theory(rig, 1e-9, units::rpm_to_rad_s(250), grid, s);
  for (LinkQuantity q : kLinkQuantities) {
    const TheorySeries& ts = t.series[index_of(q)];
    EXPECT_LT(rms_difference(ts.clearance.mean, ts.nominal), 1e-4 * rms(ts.nominal)) << column_name(q);
  }
}

TEST(MatchedTheory, ClearanceRunCountsImpactsLocatesThemAndBalancesEnergy) {
  const Rig rig = thesis();
  TheorySettings s;
  s.warmup_revolutions = 3, s.averaged_revolutions = 4;
  const CrankGrid grid{360, 0.0, 1.0};
  const MatchedTheory t = simulate_matched_theory(rig, 0.254e-3, units::rpm_to_rad_s(350), grid, s);
  ASSERT_EQ(t.severity.impacts_by_rev.size(), 4u);
  int n = 0;
  for (int k : t.severity.impacts_by_rev) n += k;
  EXPECT_EQ(static_cast<std::size_t>(n), t.impacts.size());
  EXPECT_GT(n, 0);
  double sum = 0;
  for (const BearingImpact& b : t.impacts) {
    sum += b.normal_impulse_Ns;
    EXPECT_GE(b.pin_deg, 0.0);
    EXPECT_LT(b.pin_deg, 360.0);
    EXPECT_GE(b.revolution, 0);
    EXPECT_LT(b.revolution, 4);
    // The two local directions differ by θ4 − θ3, the angle between the links (transmission angle, 180° ± it).
    const double diff = std::fmod(b.pin_deg - b.bushing_deg + 720.0, 360.0);
    EXPECT_GT(std::min(diff, 360.0 - diff), 10.0);
  }
  EXPECT_NEAR(t.severity.sum_normal_impulse_per_rev_Ns * 4, sum, 1e-12 * std::max(1.0, sum));
  ASSERT_TRUE(t.severity.impact_index_Ns);
  EXPECT_NEAR(*t.severity.impact_index_Ns, sum / n, 1e-15);
  EXPECT_LT(t.energy_residual_rel, 1e-6);
  EXPECT_EQ(t.series[0].clearance.revolutions, 4u);
}

TEST(MatchedTheory, PassBandRemovesHighOrdersAndKeepsLowOnes) {
  const Rig rig = thesis();
  TheorySettings s;
  s.warmup_revolutions = 2, s.averaged_revolutions = 4;
  const double w = units::rpm_to_rad_s(350), f_crank = w / units::kTwoPi;
  const CrankGrid grid{360, 0.0, 1.0};
  MatchedTheory t = simulate_matched_theory(rig, 0.254e-3, w, grid, s);
  const MatchedTheory raw = t;
  FilterSpec low;
  low.band = BandType::lowpass;
  low.high_hz = 20.5 * f_crank;  // orders 0 … 20 pass
  apply_pass_band(t, low);
  for (LinkQuantity q : {LinkQuantity::alpha3, LinkQuantity::omega4}) {
    const auto& before = raw.series[index_of(q)];
    const auto& after = t.series[index_of(q)];
    // The nominal turn is exactly periodic: orders ≤ 20 unchanged, the rest gone.
    const auto a0 = order_amplitudes(before.nominal, 360, 40), a1 = order_amplitudes(after.nominal, 360, 40);
    for (int k = 0; k <= 40; ++k) {
      if (k <= 20) EXPECT_NEAR(a1[k], a0[k], 1e-9 * a0[1]) << k;
      else EXPECT_LT(a1[k], 1e-9 * a0[1]) << k;
    }
    // The clearance turns (not periodic, reflected ends): high orders strongly reduced.
    const auto c0 = order_amplitudes(before.clearance_revolutions, 360, 60);
    const auto c1 = order_amplitudes(after.clearance_revolutions, 360, 60);
    double hi0 = 0, hi1 = 0;
    for (int k = 30; k <= 60; ++k) hi0 += c0[k] * c0[k], hi1 += c1[k] * c1[k];
    EXPECT_LT(hi1, 1e-4 * hi0) << column_name(q);
  }
}

}  // namespace
}  // namespace fourbar
