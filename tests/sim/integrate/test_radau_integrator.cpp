// The Radau IIA backend of StiffIntegrator (StiffMethod::radau5) on closed
// forms: a very stiff linear problem, a stiff damped oscillator (complex
// eigenvalues), order 5 on a smooth problem, the witness's zero located at a
// known root, and a quadrature integrated beside the coupled state.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sim/integrate/radau_integrator.hpp"
#include "sim/integrate/stiff_integrator.hpp"

namespace fourbar {
namespace {

/// y' = λ(y − cos t) − sin t: y = cos t + (y0 − 1)e^{λt}. Quadrature q' = y: q = sin t + (y0 − 1)(e^{λt} − 1)/λ.
struct StiffCosine : StiffSystem {
  double lambda = -1e7;
  void rhs(double t, const StiffState& y, StiffState& dy) override {
    dy = {};
    dy[0] = lambda * (y[0] - std::cos(t)) - std::sin(t);
    dy[1] = y[0];
  }
  double witness(double t, const StiffState&) override { return t - 1e9; }  // never
};

/// x'' + 2ζω x' + ω² x = 0, ζ = 0.01, ω = 1e4 (eigenvalues −100 ± 1e4 i).
struct Oscillator : StiffSystem {
  double omega = 1e4, zeta = 0.01;
  bool roots = true;
  void rhs(double, const StiffState& y, StiffState& dy) override {
    dy = {};
    dy[0] = y[1];
    dy[1] = -2 * zeta * omega * y[1] - omega * omega * y[0];
  }
  double witness(double, const StiffState& y) override { return roots ? y[0] : 1.0; }  // zero crossings
  double exact(double t) const {  // x(0) = 1, x'(0) = 0
    const double wd = omega * std::sqrt(1 - zeta * zeta);
    return std::exp(-zeta * omega * t) * (std::cos(wd * t) + zeta * omega / wd * std::sin(wd * t));
  }
};

/// A smooth nonlinear problem: y' = −y² on y(0) = 1, y = 1/(1 + t).
struct Logistic : StiffSystem {
  void rhs(double, const StiffState& y, StiffState& dy) override {
    dy = {};
    dy[0] = -y[0] * y[0];
  }
  double witness(double, const StiffState& y) override { return y[0] - 0.25; }  // y = 1/4 at t = 3
};

TEST(RadauIntegrator, VeryStiffLinearProblemAndItsQuadrature) {
  StiffCosine sys;
  StiffIntegrator integ(1e-10, 1, 2, StiffMethod::radau5);
  StiffState y{};
  y[0] = 2.0;  // a transient e^{−1e7 t} on top of cos t
  integ.reset(sys, 0.0, y);
  double t = 0;
  double worst = 0, worst_q = 0;
  while (t < 2.0) {
    const StiffIntegrator::Step s = integ.step(2.0);
    ASSERT_EQ(s.root, 0);
    t = s.end;
    integ.interpolate(t, y);
    const double ex = std::cos(t) + std::exp(sys.lambda * t);
    const double q = std::sin(t) + (std::exp(sys.lambda * t) - 1) / sys.lambda;
    worst = std::max(worst, std::abs(y[0] - ex));
    worst_q = std::max(worst_q, std::abs(y[1] - q));
  }
  EXPECT_EQ(t, 2.0);
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(worst_q, 1e-8);
  // L-stable and one-step: not thousands of steps for a transient of 1e-7 s and two seconds of cos t.
  EXPECT_LT(integ.steps(), 300u);
}

TEST(RadauIntegrator, StiffDampedOscillatorThroughItsDenseOutput) {
  Oscillator sys;
  StiffIntegrator integ(1e-11, 2, 2, StiffMethod::radau5);
  StiffState y{};
  y[0] = 1.0;
  integ.reset(sys, 0.0, y);
  double worst = 0;
  int roots = 0;
  double t = 0;
  const double t_end = 0.01;  // ≈ 16 periods
  while (t < t_end) {
    const StiffIntegrator::Step s = integ.step(t_end);
    for (int k = 0; k <= 4; ++k) {  // inside the step, by the collocation polynomial
      const double tk = s.start + (s.end - s.start) * k / 4.0;
      integ.interpolate(tk, y);
      worst = std::max(worst, std::abs(y[0] - sys.exact(tk)));
    }
    if (s.root != 0) {
      ++roots;
      integ.interpolate(s.end, y);
      integ.reset(sys, s.end, y);
    }
    t = s.end;
  }
  EXPECT_LT(worst, 1e-7);
  // x = 0 twice a period: wd·t = k·π − atan(ωd/(ζω)) → 2 per period over 0.01 s.
  const double wd = sys.omega * std::sqrt(1 - sys.zeta * sys.zeta);
  const double phase = std::atan2(wd, sys.zeta * sys.omega);  // first zero at (π/2 + …)/wd
  int expected = 0;
  for (int k = 0; k < 100; ++k)
    if ((k * M_PI + phase) / wd < t_end) ++expected;
  EXPECT_EQ(roots, expected);
}

TEST(RadauIntegrator, WitnessZeroIsLocatedAtTheKnownRoot) {
  Logistic sys;
  StiffIntegrator integ(1e-12, 1, 1, StiffMethod::radau5);
  StiffState y{};
  y[0] = 1.0;
  integ.reset(sys, 0.0, y);
  StiffIntegrator::Step s;
  for (int i = 0; i < 10000 && s.root == 0; ++i) s = integ.step(10.0);
  ASSERT_EQ(s.root, -1);
  EXPECT_NEAR(s.end, 3.0, 1e-7);
  integ.interpolate(s.end, y);
  EXPECT_LE(y[0] - 0.25, 0.0);  // the end where the sign has changed, as CVODE
  EXPECT_NEAR(y[0], 0.25, 1e-9);
  // And on from there without a reset: to t = 10, y = 1/11.
  while (s.end < 10.0) s = integ.step(10.0);
  integ.interpolate(10.0, y);
  EXPECT_NEAR(y[0], 1.0 / 11.0, 1e-8);
}

/// x'' = −x, x(0) = 1: x(2π) = 1. Fixed steps h = 2π/n (set as the first
/// step, then every step capped by t_stop on the grid; the tolerance so
/// loose that the controller would take larger ones). The problem is linear:
/// the simplified Newton iteration converges to rounding, so the error is
/// the method's.
double fixed_step_error(int n) {
  Oscillator sys;
  sys.omega = 1;
  sys.zeta = 0;
  sys.roots = false;
  RadauIntegrator integ(1e-2, 2, 2);
  StiffState y{};
  y[0] = 1.0;
  integ.reset(sys, 0.0, y);
  const double h = 2 * M_PI / n;
  integ.set_step(h);
  for (int i = 1; i <= n; ++i) {
    const StiffIntegrator::Step s = integ.step(i * h);
    EXPECT_NEAR(s.end - s.start, h, 1e-12);  // one step per grid interval
  }
  integ.interpolate(2 * M_PI, y);
  return std::hypot(y[0] - 1.0, y[1]);
}

TEST(RadauIntegrator, OrderFiveOnASmoothProblem) {
  std::vector<double> err;
  for (int n : {8, 16, 32, 64}) err.push_back(fixed_step_error(n));
  for (std::size_t i = 1; i < err.size(); ++i) {
    const double order = std::log2(err[i - 1] / err[i]);
    EXPECT_GT(order, 4.7) << "n = " << (8 << i);
    EXPECT_LT(order, 5.3);
  }
  EXPECT_GT(err.back(), 1e-12);  // still above rounding: the ratios measure the method
}

}  // namespace
}  // namespace fourbar
