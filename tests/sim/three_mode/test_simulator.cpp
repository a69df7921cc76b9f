// The three-mode simulator: invariants over many turns (energy balance,
// contact circle, pin inside the bushing), elastic impacts, the two
// integrators, a closed-form bouncing case for event location and the impact
// law, chattering that ends in the following mode, and ξ → 0.

#include <gtest/gtest.h>

#include <random>

#include <boost/math/tools/toms748_solve.hpp>

#include "common/units.hpp"
#include "sim/run/run.hpp"
#include "sim/three_mode/simulator.hpp"
#include "sim/three_mode/run_turns.hpp"
#include "support/thesis_values.hpp"

namespace fourbar {
namespace {

using testing::kXi;

ClearanceSettings settings(double e, IntegratorKind k = IntegratorKind::cvode, double tol = 1e-10) {
  ClearanceSettings s;
  s.restitution = e;
  s.integrator = k;
  s.tolerance = tol;
  return s;
}

using testing::RunResult;
using testing::run_turns;

TEST(ClearanceSimulator, InvariantsOverTenTurns) {
  for (double e : {1.0, 0.5}) {
    for (IntegratorKind k : {IntegratorKind::cvode, IntegratorKind::odeint}) {
      const RunResult r = run_turns(thesis_rig(), kXi, 350, 0, 10, settings(e, k));
      const ClearanceDiagnostics& d = r.d;
      SCOPED_TRACE(std::string("e=") + std::to_string(e) + " " + to_string(k));
      EXPECT_GT(d.impacts, 50u);  // the test means something: many impacts happen
      EXPECT_GT(d.contact_losses, 0u);
      // Energy balance: ΔE = crank work (smooth phases + impulses) − impact losses.
      EXPECT_LT(std::abs(d.energy_residual_J), 1e-8 * d.energy_scale_J);
      EXPECT_LT(d.max_energy_residual_J, 1e-8 * d.energy_scale_J);
      EXPECT_LT(d.max_contact_circle_error, 1e-9);
      EXPECT_LT(d.max_penetration, 1e-9);
      EXPECT_EQ(d.energy_gaining_impacts, 0u);
      if (e == 1.0) {
        EXPECT_NEAR(d.impact_loss_J, 0.0, 1e-12 * d.energy_scale_J);  // elastic smooth impacts lose nothing
        EXPECT_GT(std::abs(d.motor_impulse_work_J), 1e-3);           // yet the motor works at impacts
      } else {
        EXPECT_GT(d.impact_loss_J, 1e-4);
        EXPECT_GT(d.settles, 0u);  // chattering ended in the following mode
      }
    }
  }
}

TEST(ClearanceSimulator, AnyStartAngle) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> angle(-360, 360);
  for (int i = 0; i < 6; ++i) {
    const double a = angle(rng);
    const RunResult r = run_turns(thesis_rig(), kXi, 350, a, 2, settings(0.7, IntegratorKind::cvode, 1e-9));
    EXPECT_LT(std::abs(r.d.energy_residual_J), 1e-7 * r.d.energy_scale_J) << a;
    EXPECT_LT(r.d.max_contact_circle_error, 1e-9) << a;
    EXPECT_LT(r.d.max_penetration, 1e-9) << a;
  }
}

TEST(ClearanceSimulator, TwoIntegratorsAgree) {
  // e = 0.5 over the first two turns (the first impacts come in the second),
  // both at 1e-11: sampled motion and the event sequence agree to far below
  // the clearance-level scale.
  const auto a = run_turns(thesis_rig(), kXi, 350, 0, 2, settings(0.5, IntegratorKind::cvode, 1e-11), 720);
  const auto b = run_turns(thesis_rig(), kXi, 350, 0, 2, settings(0.5, IntegratorKind::odeint, 1e-11), 720);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  ASSERT_GT(a.impacts.size(), 5u);
  const std::size_t n = std::min(a.impacts.size(), b.impacts.size());
  for (std::size_t i = 0; i < std::min<std::size_t>(n, 5); ++i)
    EXPECT_NEAR(a.impacts[i].time_s, b.impacts[i].time_s, 1e-7) << i;
  double w_err = 0, w_max = 0, th_err = 0;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    const auto &x = a.samples[i], &y = b.samples[i];
    w_err = std::max(w_err, std::abs(x.links.omega3_rad_s - y.links.omega3_rad_s));
    w_max = std::max(w_max, std::abs(x.links.omega3_rad_s));
    th_err = std::max(th_err, std::abs(cross(x.links.u3, y.links.u3)));
  }
  EXPECT_LT(th_err, 1e-3 * kXi / thesis_rig().coupler.length_m);  // 0.1 % of the clearance-level angle
  EXPECT_LT(w_err, 1e-4 * w_max);
}

/// Gravity off and the crank at rest: between impacts both links turn at
/// constant rates, so each impact time solves |e(t)| = ξ in closed form.
TEST(ClearanceSimulator, BouncingBetweenWallsClosedForm) {
  Rig rig = thesis_rig();
  rig.gravity_m_s2 = 0;
  const double theta2 = 0.7;
  const ClearanceModel model(rig, kXi);
  const ConstantSpeedCrank crank(theta2, 0.0);
  for (double e : {1.0, 0.8}) {
    ClearanceSettings s = settings(e, IntegratorKind::cvode, 1e-12);
    ClearanceSimulator sim(model, crank, s);
    const Pose p = solve_pose(rig, theta2);
    LinkMotion start{p.u3, p.u4, 0.02, -0.013};  // pin at the bushing centre, moving
    sim.start_free(0.0, start);
    sim.advance_to(2.0);
    const auto& imp = sim.impacts();
    ASSERT_GE(imp.size(), 4u);
    const Vec2 A = rig.crank.length_m * unit(theta2), O4{rig.ground_length_m, 0};
    LinkMotion m = start;
    double t0 = 0, T = model.kinetic_energy_J(crank.at(0), start);
    for (std::size_t k = 0; k < 4; ++k) {
      // Exact gap along the uniform rotation from (t0, m), root by TOMS 748 in long double.
      const long double a3 = std::atan2(m.u3.y, m.u3.x), a4 = std::atan2(m.u4.y, m.u4.x);
      auto pen = [&](long double t) {
        const long double th3 = a3 + m.omega3_rad_s * (t - t0), th4 = a4 + m.omega4_rad_s * (t - t0);
        const long double ex = A.x + rig.coupler.length_m * std::cos(th3) - O4.x - rig.rocker.length_m * std::cos(th4);
        const long double ey = A.y + rig.coupler.length_m * std::sin(th3) - rig.rocker.length_m * std::sin(th4);
        return std::sqrt(ex * ex + ey * ey) - (long double)kXi;
      };
      // Bracket: march until the pin is out.
      long double lo = t0 + 1e-9L, hi = lo;
      while (pen(hi) < 0) hi += 1e-4L;
      if (hi > lo + 1e-4L) lo = hi - 1e-4L;
      std::uintmax_t it = 200;
      const auto root = boost::math::tools::toms748_solve(
          pen, lo, hi, [](long double x, long double y) { return std::abs(y - x) < 1e-16L; }, it);
      const double exact = static_cast<double>(0.5L * (root.first + root.second));
      EXPECT_NEAR(imp[k].time_s, exact, 1e-12) << "impact " << k << " e=" << e;
      // Newton's law and energy across the impact (no motor work with the crank at rest).
      const ImpactResult& r = imp[k].result;
      EXPECT_NEAR(r.normal_speed_after_m_s, -e * r.normal_speed_before_m_s, 1e-12);
      const double T1 = model.kinetic_energy_J(crank.at(imp[k].time_s), r.after);
      EXPECT_NEAR(T1, T - r.energy_loss_J, 1e-14 * T);
      if (e == 1.0) EXPECT_NEAR(T1, T, 1e-14 * T);
      // The next flight starts from the recorded post-impact state.
      const double dt = imp[k].time_s - t0;
      m.u3 = unit(a3 + m.omega3_rad_s * dt);
      m.u4 = unit(a4 + m.omega4_rad_s * dt);
      m.omega3_rad_s = r.after.omega3_rad_s;
      m.omega4_rad_s = r.after.omega4_rad_s;
      t0 = imp[k].time_s;
      T = T1;
    }
  }
}

TEST(ClearanceSimulator, ChatteringEndsInFollowingMode) {
  // Crank at rest with gravity: the pin drops onto the bushing wall and
  // bounces with e = 0.6; rebounds shrink geometrically until the settle rule
  // ends the sequence in the following mode after finitely many impacts.
  const Rig rig = thesis_rig();
  const double theta2 = 1.2;
  const ClearanceModel model(rig, kXi);
  const ConstantSpeedCrank crank(theta2, 0.0);
  ClearanceSettings s = settings(0.6, IntegratorKind::cvode, 1e-11);
  ClearanceSimulator sim(model, crank, s);
  const Pose p = solve_pose(rig, theta2);
  sim.start_free(0.0, LinkMotion{p.u3, p.u4, 0.0, 0.0});
  sim.advance_to(0.5);
  const auto& imp = sim.impacts();
  const ClearanceDiagnostics d = sim.diagnostics();
  ASSERT_GE(imp.size(), 5u);
  EXPECT_LT(imp.size(), 200u);
  EXPECT_EQ(sim.mode(), ContactMode::following);
  EXPECT_GE(d.settles, 1u);
  // Rebound speeds fall by about e per impact; successive flight times shrink too.
  for (std::size_t k = 1; k + 1 < std::min<std::size_t>(imp.size(), 8); ++k) {
    const double ratio = imp[k + 1].result.normal_speed_before_m_s / imp[k].result.normal_speed_before_m_s;
    EXPECT_NEAR(ratio, 0.6, 0.1) << k;
    EXPECT_LT(imp[k + 1].time_s - imp[k].time_s, imp[k].time_s - imp[k - 1].time_s) << k;
  }
  EXPECT_LT(std::abs(d.energy_residual_J), 1e-8 * model.energy_scale_J(0.0));
  EXPECT_LT(d.max_penetration, 1e-9);
}

TEST(ClearanceSimulator, SmallClearanceConvergesToNominal) {
  // At 100 rpm the bearing force stays compressive: pure following mode, and
  // the motion tends to the nominal one as ξ → 0.
  const Rig rig = thesis_rig();
  double previous_theta = 1, previous_omega = 1e9;
  for (double xi : {1e-4, 1e-5, 1e-6}) {
    const RunResult r = run_turns(rig, xi, 100, 0, 1, settings(0.5, IntegratorKind::cvode, 1e-10), 360);
    EXPECT_EQ(r.d.contact_losses, 0u);
    double dth = 0, dw = 0;
    for (const auto& s : r.samples) {
      const NominalMotion nm = solve_motion(rig, s.crank);
      dth = std::max(dth, std::abs(cross(nm.pose.u3, s.links.u3)));
      dw = std::max(dw, std::abs(nm.omega3_rad_s - s.links.omega3_rad_s));
    }
    EXPECT_LT(dth, 3 * xi / rig.coupler.length_m) << xi;  // angle error of order ξ/l
    EXPECT_LT(dth, 0.2 * previous_theta) << xi;
    EXPECT_LT(dw, 0.5 * previous_omega) << xi;
    previous_theta = dth;
    previous_omega = dw;
  }
}

}  // namespace
}  // namespace fourbar

namespace fourbar {
namespace {

Scene clearance_scene(double e, bool steady, int max_revolutions) {
  ClearanceSettings c;
  c.restitution = e;
  c.steady_state = steady;
  c.max_revolutions = max_revolutions;
  c.tolerance = 1e-8;
  return testing::thesis_clearance_scene(c, {"alpha3_rad_s2", "mode"});
}

TEST(ClearanceRun, SteadyStateSearchIsBoundedAndReported) {
  // The model's following mode is undamped, so a strict period-k repeat is
  // not expected here: the search must stop at max_revolutions and say so,
  // and the output turn must be the one after it.
  const ClearanceRun r = run_clearance(clearance_scene(0.5, true, 6));
  EXPECT_FALSE(r.steady_state_reached);
  EXPECT_EQ(r.first_output_revolution, 6);
  EXPECT_EQ(r.revolutions_simulated, 7);
  EXPECT_GT(r.steady_difference, 1e-6);
  ASSERT_EQ(r.series.rows(), 37u);
  EXPECT_NEAR(r.series.columns[0].front(), 6 * 360.0, 1e-9);
  EXPECT_NEAR(r.series.columns[0].back(), 7 * 360.0, 1e-9);
  EXPECT_EQ(r.revolutions.size(), 7u);
  // Per-turn books add up to the run's counts.
  std::size_t n = 0;
  for (const auto& rev : r.revolutions) {
    n += rev.impacts;
    EXPECT_NEAR(rev.following_time_s + rev.free_time_s, rev.end_time_s - rev.start_time_s, 1e-12);
  }
  EXPECT_EQ(n, r.impacts.size());
  EXPECT_EQ(n, r.diagnostics.impacts);
}

}  // namespace
}  // namespace fourbar

namespace fourbar {
namespace {

TEST(ClearanceSimulator, StageFilterFindsTheSameEvents) {
  // Following-mode steps cleared by their Runge–Kutta stage values skip the
  // dense event scan; the integration itself is the same, so the event
  // sequence must be identical to the one with every step scanned.
  for (double e : {1.0, 0.5}) {
    for (double rpm : {350.0, 250.0}) {
      ClearanceSettings fast = settings(e, IntegratorKind::odeint, 1e-8);
      ClearanceSettings full = fast;
      full.full_event_scan = true;
      const RunResult a = run_turns(thesis_rig(), kXi, rpm, 0, 8, fast);
      const RunResult b = run_turns(thesis_rig(), kXi, rpm, 0, 8, full);
      SCOPED_TRACE("e=" + std::to_string(e) + " rpm=" + std::to_string(rpm));
      EXPECT_GT(a.d.filtered_steps, a.d.steps / 3);  // the filter does clear most following steps
      EXPECT_EQ(b.d.filtered_steps, 0u);
      ASSERT_GT(b.impacts.size(), 20u);
      EXPECT_EQ(a.d.contact_losses, b.d.contact_losses);
      EXPECT_EQ(a.d.settles, b.d.settles);
      ASSERT_EQ(a.impacts.size(), b.impacts.size());
      for (std::size_t i = 0; i < a.impacts.size(); ++i) EXPECT_EQ(a.impacts[i].time_s, b.impacts[i].time_s) << i;
    }
  }
}

}  // namespace
}  // namespace fourbar

namespace fourbar {
namespace {

TEST(ClearanceSimulator, ContactLossOnTheGuardDoesNotStall) {
  // The benchmark's CVODE reference (e = 0.5, 1e-13) meets a contact loss
  // where the free flight starts within round-off of the wall and the
  // following mode's N sits at −N_guard: this once restarted the same state
  // at the same time until the event pile-up guard stopped the run.
  const RunResult r = run_turns(thesis_rig(), kXi, 350, 0, 2, settings(0.5, IntegratorKind::cvode, 1e-13));
  EXPECT_GT(r.d.impacts, 50u);
  EXPECT_LT(std::abs(r.d.energy_residual_J), 1e-9 * r.d.energy_scale_J);
  EXPECT_LT(r.d.max_penetration, 1e-9);
}

}  // namespace
}  // namespace fourbar
