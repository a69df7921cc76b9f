#pragma once
// The 3-stage Radau IIA method (order 5, L-stable; Hairer & Wanner, Solving
// Ordinary Differential Equations II, sec. IV.8, their code RADAU5): a
// one-step stiff integrator for the compliant contact model, the second
// backend of StiffIntegrator (StiffMethod::radau5).
//
// - Simplified Newton iteration on the stage increments, transformed by the
//   eigenvectors of the Radau matrix into one real and one complex linear
//   system (fac1·I − J and (α + iβ)·I − J, LU by Eigen).
// - The Jacobian is a difference quotient over the first `coupled`
//   components; the rest are quadratures whose columns are zero, so each
//   linear system is block triangular: an LU of the coupled block only, the
//   quadrature rows by substitution (exact, not an approximation).
// - The embedded error estimate filtered by (fac1·I − J)⁻¹ (with the
//   second filter at the first step and after a rejection), the
//   Gustafsson predictive step-size controller, the Jacobian and LU kept
//   while the Newton contraction is small and the step size unchanged.
// - Dense output by the collocation polynomial; the witness's zero located
//   on it (Illinois), the step ending there, as CVODE's root finding does:
//   the returned time is the bracket's end where the sign has changed.
// - Tolerances as RADAU5 transforms them: rtol' = 0.1·tol^(2/3) (so that
//   the global error follows `tol` roughly as for a multistep code).

#include <array>
#include <complex>
#include <cstddef>

#include <Eigen/Dense>

#include "sim/integrate/stiff_integrator.hpp"

namespace fourbar {

class RadauIntegrator {
 public:
  RadauIntegrator(double tolerance, std::size_t coupled, std::size_t size);

  /// (Re)starts at (t0, y0): the Jacobian is recomputed; the step size of
  /// the last accepted step is kept as the first guess (a one-step method
  /// needs no start-up).
  void reset(StiffSystem& system, double t0, const StiffState& y0);
  /// One step, never past `t_stop`; ends early at a root of the witness.
  StiffIntegrator::Step step(double t_stop);
  /// The collocation polynomial of the last step, on [its start, its end].
  void interpolate(double t, StiffState& y) const;

  /// The size of the next step to try (the controller's guess otherwise).
  void set_step(double h) { h_ = h; }

  std::size_t steps() const { return steps_; }
  StiffIntegrator::Counters counters() const { return counters_; }

 private:
  using Real = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kStiffSize, kStiffSize>;
  using Cplx = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic, 0, kStiffSize, kStiffSize>;
  using RealVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kStiffSize, 1>;
  using CplxVec = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, 1, 0, kStiffSize, 1>;

  void jacobian();
  void decompose();
  void solve_real(StiffState& r) const;
  void solve_complex(StiffState& re, StiffState& im) const;
  double norm(const StiffState& v) const;
  double error_estimate(const StiffState& z1, const StiffState& z2, const StiffState& z3);
  bool newton(double t, StiffState& z1, StiffState& z2, StiffState& z3, int& iterations);
  void starting_values(StiffState& z1, StiffState& z2, StiffState& z3) const;
  void set_scale();
  double locate_root(double g_lo, double g_hi);
  double witness_at(double t);
  void initial_step();

  double rtol_, atol_, fnewt_;
  std::size_t coupled_, size_;
  StiffSystem* system_ = nullptr;

  double t_ = 0, h_ = 0;             ///< the current time and the next step size
  StiffState y_{}, f0_{}, scal_{};   ///< the state at t_, f(t_, y_), the error weights
  double g_ = 0;                      ///< the witness at t_
  bool first_ = true, reject_ = false, need_jacobian_ = true, need_lu_ = true;
  bool jac_fresh_ = false;            ///< the Jacobian was computed for the step being tried
  double h_lu_ = 0;                   ///< the step size of the LU factors
  double theta_ = 0, faccon_ = 1;     ///< Newton contraction and its bound
  double h_acc_ = 0, err_acc_ = 0;    ///< the last accepted step's size and error (Gustafsson)
  int accepted_since_reset_ = 0;

  // J over the coupled columns: rows 0..size−1 (the quadrature rows below the coupled block).
  Real jac_;
  Eigen::PartialPivLU<Real> lu_real_;
  Eigen::PartialPivLU<Cplx> lu_cplx_;
  double fac1_ = 0;
  std::complex<double> fac2_;

  // Dense output: y(x) = c0 + s(c1 + (s − c2 + 1)(c2' + (s − c1 + 1) c3)), s = (x − x_end)/h_dense.
  StiffState cont_[4]{};
  double x_end_ = 0, h_dense_ = 0, x_start_ = 0;
  bool stepped_ = false;
  bool at_root_ = false;  ///< the last step ended at a root (the next step restarts there)

  std::size_t steps_ = 0;
  StiffIntegrator::Counters counters_;
};

}  // namespace fourbar
