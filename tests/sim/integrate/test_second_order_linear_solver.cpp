// The Schur-complement solver of the linkage integrator's Newton matrices
// (sim/integrate/second_order_linear_solver.hpp) against Eigen's dense LU of
// the same matrix, on the structure it exploits and on a matrix without it
// (the dense fallback); and LinkageIntegrator with each method on a damped
// oscillator in (x, v) with a quadrature of its dissipated power, against
// the closed form.
#include <gtest/gtest.h>

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "sim/integrate/linkage_integrator.hpp"
#include "sim/integrate/second_order_linear_solver.hpp"

namespace fourbar {
namespace {

/// A = I − γJ with J of the linkage's shape: dq/dt = S·q̇, the quadratures
/// read by nobody; `break_structure` puts a non-zero where a zero belongs.
Eigen::MatrixXd newton_matrix(int n, int quads, bool break_structure, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const int size = 2 * n + quads;
  const double gamma = 0.3;
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(size, size);
  for (int i = 0; i < n; ++i) j(i, n + i) = 1 + u(rng);
  for (int i = n; i < size; ++i)
    for (int k = 0; k < 2 * n; ++k) j(i, k) = 3 * u(rng);
  if (break_structure) j(0, 1) = 0.5;
  return Eigen::MatrixXd::Identity(size, size) - gamma * j;
}

Eigen::VectorXd solve_with(SUNLinearSolver ls, SUNContext ctx, const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  const auto size = static_cast<sunindextype>(a.rows());
  SUNMatrix m = SUNDenseMatrix(size, size, ctx);
  Eigen::Map<Eigen::MatrixXd>(SUNDenseMatrix_Data(m), size, size) = a;
  N_Vector x = N_VNew_Serial(size, ctx), bb = N_VNew_Serial(size, ctx);
  Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(bb), size) = b;
  EXPECT_EQ(SUNLinSolSetup(ls, m), 0);
  EXPECT_EQ(SUNLinSolSolve(ls, m, x, bb, 0.0), 0);
  const Eigen::VectorXd out = Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(x), size);
  N_VDestroy(x);
  N_VDestroy(bb);
  SUNMatDestroy(m);
  return out;
}

TEST(SecondOrderLinearSolver, MatchesTheDenseLuWithAndWithoutTheStructure) {
  SUNContext ctx = nullptr;
  ASSERT_EQ(SUNContext_Create(nullptr, &ctx), 0);
  std::mt19937 rng(25);
  const int n = 12, quads = 6;
  SUNLinearSolver ls = second_order_linear_solver(ctx, 2 * n + quads, n);
  for (bool broken : {false, true}) {
    const Eigen::MatrixXd a = newton_matrix(n, quads, broken, rng);
    const Eigen::VectorXd b = Eigen::VectorXd::NullaryExpr(a.rows(), [&] { return std::normal_distribution<>()(rng); });
    const Eigen::VectorXd want = a.partialPivLu().solve(b), got = solve_with(ls, ctx, a, b);
    EXPECT_LT((got - want).norm(), 1e-12 * want.norm()) << (broken ? "dense fallback" : "structured");
  }
  EXPECT_EQ(second_order_solver_counts(ls).structured, 1);
  EXPECT_EQ(second_order_solver_counts(ls).dense, 1);
  SUNLinSolFree(ls);
  SUNContext_Free(&ctx);
}

/// x'' + 2ζω x' + ω² x = 0 scaled as the linkage's state: y = (x, v/ω, loss)
/// with x' = ω·y1, y1' = −ω x − 2ζω y1, loss' = 2ζω·y1² (the damping's power / ω²).
class OscillatorOde : public LinkageOde {
 public:
  static constexpr double w = 2000.0, zeta = 0.02;
  void rhs(double, const double* y, double* dy) override {
    dy[0] = w * y[1];
    dy[1] = -w * y[0] - 2 * zeta * w * y[1];
    dy[2] = 2 * zeta * w * y[1] * y[1];
  }
  void witnesses(double, const double*, double*) override {}
};

TEST(LinkageIntegrator, EveryMethodFollowsADampedOscillatorAndItsLosses) {
  const double t_end = 0.01, wd = OscillatorOde::w * std::sqrt(1 - OscillatorOde::zeta * OscillatorOde::zeta);
  const double decay = std::exp(-OscillatorOde::zeta * OscillatorOde::w * t_end);
  const double x = decay * (std::cos(wd * t_end) + OscillatorOde::zeta * OscillatorOde::w / wd * std::sin(wd * t_end));
  for (LinkageMethod m : {LinkageMethod::bdf, LinkageMethod::esdirk4, LinkageMethod::esdirk5, LinkageMethod::erk,
                          LinkageMethod::adams}) {
    OscillatorOde ode;
    LinkageIntegrator integ(1e-11, 3, 2, 0, m);
    integ.reset(ode, 0.0, {1.0, 0.0, 0.0});
    double t = 0;
    for (int i = 0; i < 200000 && t < t_end; ++i) t = integ.step(t_end).end;
    std::vector<double> y;
    integ.interpolate(t_end, y);
    const double energy = 0.5 * (y[0] * y[0] + y[1] * y[1]);
    EXPECT_NEAR(y[0], x, 1e-7) << static_cast<int>(m);
    EXPECT_NEAR(energy + y[2], 0.5, 1e-8) << static_cast<int>(m);  // energy + losses = the start's
  }
}

}  // namespace
}  // namespace fourbar
