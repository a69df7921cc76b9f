// α → ω: the thesis trapezoid, the periodic crank-angle-domain integration
// (exact on band-limited signals, constant from the topology), no drift over
// 10 000 noisy revolutions where the plain trapezoid drifts.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "analyze/integration.hpp"
#include "common/units.hpp"
#include "mechanism/kinematics.hpp"

namespace fourbar {
namespace {

using units::kTwoPi;

// A test motion on the angle grid: ω(θ) = c + Σ a_m·cos(mθ + φ_m), crank
// speed ω2(θ) = w0(1 + e·sin θ); α = ω2·dω/dθ.
struct Motion {
  double c = 0.7, w0 = 36.6, e = 0.1;
  double omega(double th) const { return c + 3 * std::cos(th + 0.2) - 1.5 * std::sin(2 * th) + 0.4 * std::cos(9 * th + 1); }
  double domega(double th) const { return -3 * std::sin(th + 0.2) - 3 * std::cos(2 * th) - 3.6 * std::sin(9 * th + 1); }
  double speed(double th) const { return w0 * (1 + e * std::sin(th)); }
};

TEST(Integration, TrapezoidIsExactOnLinesAndSecondOrderOnSinusoids) {
  std::vector<double> y(101), out(101);
  for (int i = 0; i <= 100; ++i) y[i] = 2.0 + 3.0 * i * 0.01;
  cumulative_trapezoid(y, 0.01, 5.0, out);
  for (int i = 0; i <= 100; ++i) EXPECT_NEAR(out[i], 5.0 + 2.0 * i * 0.01 + 1.5 * (i * 0.01) * (i * 0.01), 1e-13);
  // ∫cos(ωt) = sin(ωt)/ω: error falls 4× per halving of the step.
  double prev_err = 0;
  for (int n : {100, 200, 400}) {
    const double h = 1.0 / n, w = 7.0;
    std::vector<double> c(n + 1), s(n + 1);
    for (int i = 0; i <= n; ++i) c[i] = std::cos(w * i * h);
    cumulative_trapezoid(c, h, 0.0, s);
    double err = 0;
    for (int i = 0; i <= n; ++i) err = std::max(err, std::abs(s[i] - std::sin(w * i * h) / w));
    if (prev_err > 0) EXPECT_NEAR(prev_err / err, 4.0, 0.05);
    prev_err = err;
  }
}

TEST(Integration, SpectralIsExactOnBandLimitedRevolutions) {
  const Motion m;
  for (std::size_t n : {64u, 360u, 1001u}) {
    PeriodicIntegrator integ(n);
    std::vector<double> alpha(n), speed(n), omega(n), truth(n);
    double turns = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double th = 0.4 + kTwoPi * k / n;
      speed[k] = m.speed(th);
      alpha[k] = speed[k] * m.domega(th);
      truth[k] = m.omega(th);
      turns += truth[k] / speed[k] / n;  // what the constraint must reproduce
    }
    integ.integrate(PeriodicMethod::spectral, alpha, speed, turns, omega);
    for (std::size_t k = 0; k < n; ++k) EXPECT_NEAR(omega[k], truth[k], 1e-12 * 5) << "N " << n << " k " << k;
  }
}

// A crank speeding up through the revolution: the link's ω gains a net
// change over the turn, ω = P(θ) + s·θ. Keeping the slope reproduces it
// exactly; strict periodicity leaves the sawtooth s·(θ − π).
TEST(Integration, KeepingTheSlopeFollowsASpeedChangeWithinTheTurn) {
  const Motion m;
  const double slope = 0.05;  // rad/s per radian of crank angle
  for (std::size_t n : {64u, 720u}) {
    PeriodicIntegrator integ(n);
    std::vector<double> alpha(n), speed(n), omega(n), periodic(n), truth(n);
    double turns = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double th = kTwoPi * k / n;
      speed[k] = m.speed(th);
      truth[k] = m.omega(th) + slope * th;
      alpha[k] = speed[k] * (m.domega(th) + slope);
      turns += truth[k] / speed[k] / n;
    }
    integ.integrate(PeriodicMethod::spectral, alpha, speed, turns, omega, true);
    integ.integrate(PeriodicMethod::spectral, alpha, speed, turns, periodic, false);
    double err = 0, err_periodic = 0;
    for (std::size_t k = 0; k < n; ++k) {
      err = std::max(err, std::abs(omega[k] - truth[k]));
      err_periodic = std::max(err_periodic, std::abs(periodic[k] - truth[k]));
    }
    EXPECT_LT(err, 1e-11) << n;
    EXPECT_GT(err_periodic, 0.8 * slope * units::kPi) << n;  // the sawtooth's half height
  }
}

TEST(Integration, ClosedTrapezoidIsSecondOrder) {
  const Motion m;
  double prev = 0;
  for (std::size_t n : {180u, 360u, 720u}) {
    PeriodicIntegrator integ(n);
    std::vector<double> alpha(n), speed(n), omega(n);
    double turns = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double th = kTwoPi * k / n;
      speed[k] = m.speed(th);
      alpha[k] = speed[k] * m.domega(th);
      turns += m.omega(th) / speed[k] / n;
    }
    integ.integrate(PeriodicMethod::closed_trapezoid, alpha, speed, turns, omega);
    double err = 0;
    for (std::size_t k = 0; k < n; ++k) err = std::max(err, std::abs(omega[k] - m.omega(kTwoPi * k / n)));
    // The trapezoid's gain on harmonic m is x·cot x, x = m·h/2 (h = 2π/N),
    // so its error on ω = Σ a_m·cos(mθ + φ) is at most Σ a_m·|1 − x·cot x|
    // (the varying crank speed adds harmonics; allow 50 %).
    double bound = 0;
    for (auto [mh, a] : {std::pair{1.0, 3.0}, {2.0, 1.5}, {9.0, 0.4}}) {
      const double x = mh * kTwoPi / n / 2;
      bound += a * std::abs(1 - x / std::tan(x));
    }
    EXPECT_LT(err, 1.5 * bound) << n;
    if (prev > 0) EXPECT_NEAR(prev / err, 4.0, 0.2) << n;
    prev = err;
  }
}

TEST(Integration, NominalMechanismTurnsAndVelocity) {
  const Rig rig = thesis_rig();
  EXPECT_EQ(link_turns_per_crank_turn(rig, SensedLink::coupler), 0);
  EXPECT_EQ(link_turns_per_crank_turn(rig, SensedLink::rocker), 0);
  // A drag link (ground shortest): rocker and coupler turn with the crank.
  Rig drag = thesis_rig();
  drag.ground_length_m = 0.05;
  drag.crank.length_m = 0.10;
  drag.coupler.length_m = 0.12;
  drag.rocker.length_m = 0.11;
  drag.crank.mass_centre_m = drag.coupler.mass_centre_m = drag.rocker.mass_centre_m = 0.04;
  validate_rig(drag);
  EXPECT_EQ(link_turns_per_crank_turn(drag, SensedLink::rocker), 1);
  EXPECT_EQ(link_turns_per_crank_turn(drag, SensedLink::coupler), 1);
  // The nominal α3, α4 integrate back to ω3, ω4 for both rigs, crank at
  // 350 rpm: the spectral method to the resolution of the 720-point grid.
  for (const Rig* r : std::initializer_list<const Rig*>{&rig, &drag}) {
    const std::size_t n = 720;
    PeriodicIntegrator integ(n);
    for (SensedLink link : {SensedLink::coupler, SensedLink::rocker}) {
      std::vector<double> alpha(n), speed(n, units::rpm_to_rad_s(350)), omega(n), truth(n);
      for (std::size_t k = 0; k < n; ++k) {
        const NominalMotion nm = solve_motion(*r, {kTwoPi * k / n, speed[k], 0.0});
        alpha[k] = link == SensedLink::coupler ? nm.alpha3_rad_s2 : nm.alpha4_rad_s2;
        truth[k] = link == SensedLink::coupler ? nm.omega3_rad_s : nm.omega4_rad_s;
      }
      integ.integrate(PeriodicMethod::spectral, alpha, speed, link_turns_per_crank_turn(*r, link), omega);
      for (std::size_t k = 0; k < n; ++k) EXPECT_NEAR(omega[k], truth[k], 1e-9 * speed[0]);
    }
  }
}

// 10 000 revolutions of α with 3 % white noise and a small constant offset
// (as a sensor or gravity error would leave): the periodic integration has
// the same error in the last 100 revolutions as in the first 100; the plain
// trapezoid drifts.
TEST(Integration, NoDriftOver10000Revolutions) {
  const Motion m;
  const std::size_t n = 360, revs = 10000;
  std::mt19937 rng(42);
  std::normal_distribution<double> noise(0, 1);
  PeriodicIntegrator integ(n);
  std::vector<double> base_alpha(n), speed(n), truth(n), alpha(n), omega(n);
  double turns = 0, rms = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double th = kTwoPi * k / n;
    speed[k] = m.speed(th);
    base_alpha[k] = speed[k] * m.domega(th);
    truth[k] = m.omega(th);
    turns += truth[k] / speed[k] / n;
    rms += base_alpha[k] * base_alpha[k] / n;
  }
  const double sigma = 0.03 * std::sqrt(rms), offset = 0.002 * std::sqrt(rms);
  double err_first = 0, err_last = 0, trap_first = 0, trap_last = 0;
  double trap = truth[0], prev_g = 0;
  for (std::size_t r = 0; r < revs; ++r) {
    for (std::size_t k = 0; k < n; ++k) alpha[k] = base_alpha[k] + offset + sigma * noise(rng);
    integ.integrate(PeriodicMethod::spectral, alpha, speed, turns, omega);
    double e = 0, et = 0;
    for (std::size_t k = 0; k < n; ++k) {
      // Thesis: trapezoid in the angle domain, carried through the record.
      const double g = alpha[k] / speed[k];
      if (r + k > 0) trap += 0.5 * (kTwoPi / n) * (prev_g + g);
      prev_g = g;
      e += (omega[k] - truth[k]) * (omega[k] - truth[k]);
      et += (trap - truth[k]) * (trap - truth[k]);
    }
    if (r < 100) err_first += e, trap_first += et;
    if (r >= revs - 100) err_last += e, trap_last += et;
  }
  const double norm = std::sqrt(100.0 * n);
  err_first = std::sqrt(err_first) / norm, err_last = std::sqrt(err_last) / norm;
  trap_first = std::sqrt(trap_first) / norm, trap_last = std::sqrt(trap_last) / norm;
  // Noise floor of the spectral integration: white noise of variance σ_g²
  // in g = α/ω2 gives ω variance 2σ_g²/N·Σ1/m² ≈ σ_g²·π²/(3N).
  double mean_inv_speed_sq = 0;
  for (double w : speed) mean_inv_speed_sq += 1.0 / (w * w) / n;
  const double floor = sigma * std::sqrt(mean_inv_speed_sq * units::kPi * units::kPi / (3.0 * n));
  RecordProperty("periodic_rms_error_first_100", std::to_string(err_first));
  RecordProperty("periodic_rms_error_last_100", std::to_string(err_last));
  RecordProperty("trapezoid_rms_error_last_100", std::to_string(trap_last));
  EXPECT_LT(err_first, 1.1 * floor);
  EXPECT_GT(err_first, 0.9 * floor);
  EXPECT_LT(err_last, 1.2 * err_first);
  EXPECT_GT(trap_last, 20 * trap_first);  // the thesis method drifts
}

TEST(Integration, NormalChannelAnchorRecoversTheConstant) {
  std::vector<double> wt(100), wsq(100);
  const double c = -2.5;
  for (int i = 0; i < 100; ++i) {
    wt[i] = 1.3 + std::sin(kTwoPi * i / 100);  // integrated, with an arbitrary constant
    const double w = std::sin(kTwoPi * i / 100) + c;
    wsq[i] = w * w;
  }
  const double off = omega_offset_from_normal(wt, wsq, -1.0);
  for (int i = 0; i < 100; ++i) EXPECT_NEAR(wt[i] + off, std::sin(kTwoPi * i / 100) + c, 1e-12);
}

}  // namespace
}  // namespace fourbar
