#include "sim/integrate/radau_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.hpp"

namespace fourbar {

namespace {

// The Radau IIA(5) constants as in RADAU5: the nodes, the error-estimate
// weights, the eigenvalues of the inverse Radau matrix (u1 real, α ± iβ)
// and its eigenvector transformation T and T⁻¹.
const double kSq6 = std::sqrt(6.0);
const double kC1 = (4.0 - kSq6) / 10.0, kC2 = (4.0 + kSq6) / 10.0;
const double kC1m1 = kC1 - 1.0, kC2m1 = kC2 - 1.0, kC1mc2 = kC1 - kC2;
const double kDd1 = -(13.0 + 7.0 * kSq6) / 3.0, kDd2 = (-13.0 + 7.0 * kSq6) / 3.0, kDd3 = -1.0 / 3.0;
const double kCbrt81 = std::cbrt(81.0), kCbrt9 = std::cbrt(9.0);
const double kU1 = 30.0 / (6.0 + kCbrt81 - kCbrt9);
const double kAlpha0 = (12.0 - kCbrt81 + kCbrt9) / 60.0;
const double kBeta0 = (kCbrt81 + kCbrt9) * std::sqrt(3.0) / 60.0;
const double kCno = kAlpha0 * kAlpha0 + kBeta0 * kBeta0;
const double kAlpha = kAlpha0 / kCno, kBeta = kBeta0 / kCno;
constexpr double kT11 = 9.1232394870892942792e-02, kT12 = -0.14125529502095420843, kT13 = -3.0029194105147424492e-02;
constexpr double kT21 = 0.24171793270710701896, kT22 = 0.20412935229379993199, kT23 = 0.38294211275726193779;
constexpr double kT31 = 0.96604818261509293619;
constexpr double kTi11 = 4.3255798900631553510, kTi12 = 0.33919925181580986954, kTi13 = 0.54177053993587487119;
constexpr double kTi21 = -4.1787185915519047273, kTi22 = -0.32768282076106238708, kTi23 = 0.47662355450055045196;
constexpr double kTi31 = -0.50287263494578687595, kTi32 = 2.5719269498556054292, kTi33 = -0.59603920482822492497;

constexpr double kUround = 2.220446049250313e-16;
constexpr int kNit = 7;            ///< Newton iterations at most
constexpr double kSafe = 0.9;      ///< safety factor of the step-size control
// Keep the Jacobian while the Newton contraction is below this. RADAU5's
// default is 0.001; on the compliant model 0.03 saves ≈ 10 % of the time
// (bench_compliant --radau --profile 1e-13: 3 922 instead of 13 091
// Jacobians for 18 276 instead of 17 979 steps).
constexpr double kThet = 0.03;
constexpr double kFacl = 5.0, kFacr = 1.0 / 8.0;  ///< 1/8 ≤ h_new/h ≤ 5
constexpr double kQuot1 = 1.0, kQuot2 = 1.2;      ///< keep h (and the LU) if h_new/h is inside

}  // namespace

RadauIntegrator::RadauIntegrator(double tolerance, std::size_t coupled, std::size_t size)
    : coupled_(coupled), size_(size) {
  rtol_ = 0.1 * std::pow(tolerance, 2.0 / 3.0);
  atol_ = rtol_;
  fnewt_ = std::max(10 * kUround / rtol_, std::min(0.03, std::pow(rtol_, 2.0 / 3.0 - 1.0)));
  jac_ = Real::Zero(static_cast<Eigen::Index>(size), static_cast<Eigen::Index>(coupled));
}

void RadauIntegrator::set_scale() {
  for (std::size_t i = 0; i < size_; ++i) scal_[i] = atol_ + rtol_ * std::abs(y_[i]);
}

double RadauIntegrator::norm(const StiffState& v) const {
  double s = 0;
  for (std::size_t i = 0; i < size_; ++i) s += (v[i] / scal_[i]) * (v[i] / scal_[i]);
  return std::sqrt(s / static_cast<double>(size_));
}

void RadauIntegrator::initial_step() {
  const double d0 = norm(y_), d1 = norm(f0_);
  h_ = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
}

void RadauIntegrator::reset(StiffSystem& system, double t0, const StiffState& y0) {
  system_ = &system;
  t_ = t0;
  y_ = y0;
  for (std::size_t i = size_; i < kStiffSize; ++i) y_[i] = 0;
  system_->rhs(t_, y_, f0_);
  ++counters_.rhs;
  set_scale();
  g_ = system_->witness(t_, y_);
  first_ = true;
  reject_ = false;
  need_jacobian_ = true;
  theta_ = kThet;
  faccon_ = 1;
  accepted_since_reset_ = 0;
  stepped_ = false;
  at_root_ = false;
  if (!(h_ > 0)) initial_step();
}

void RadauIntegrator::jacobian() {
  StiffState yy = y_, f1;
  const double sqrt_u = std::sqrt(kUround);
  for (std::size_t j = 0; j < coupled_; ++j) {
    const double yj = yy[j];
    const double inc = sqrt_u * std::max(std::abs(yj), 1e-3);
    yy[j] = yj + inc;
    system_->rhs(t_, yy, f1);
    yy[j] = yj;
    for (std::size_t i = 0; i < size_; ++i)
      jac_(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = (f1[i] - f0_[i]) / inc;
  }
  counters_.rhs += static_cast<long>(coupled_);
  ++counters_.jacobians;
  need_jacobian_ = false;
  jac_fresh_ = true;
  need_lu_ = true;
}

void RadauIntegrator::decompose() {
  const auto m = static_cast<Eigen::Index>(coupled_);
  fac1_ = kU1 / h_;
  fac2_ = std::complex<double>(kAlpha / h_, kBeta / h_);
  const Real block = jac_.topRows(m);
  Real e1 = -block;
  e1.diagonal().array() += fac1_;
  lu_real_.compute(e1);
  Cplx e2 = -block.cast<std::complex<double>>();
  e2.diagonal().array() += fac2_;
  lu_cplx_.compute(e2);
  h_lu_ = h_;
  need_lu_ = false;
}

// (fac1·I − J) x = r with J = [A 0; B 0]: x_c = LU⁻¹ r_c, x_q = (r_q + B x_c)/fac1.
void RadauIntegrator::solve_real(StiffState& r) const {
  const auto m = static_cast<Eigen::Index>(coupled_);
  RealVec rc(m);
  for (Eigen::Index i = 0; i < m; ++i) rc(i) = r[static_cast<std::size_t>(i)];
  const RealVec xc = lu_real_.solve(rc);
  for (Eigen::Index i = 0; i < m; ++i) r[static_cast<std::size_t>(i)] = xc(i);
  for (std::size_t i = coupled_; i < size_; ++i) {
    double s = r[i];
    for (Eigen::Index j = 0; j < m; ++j) s += jac_(static_cast<Eigen::Index>(i), j) * xc(j);
    r[i] = s / fac1_;
  }
}

void RadauIntegrator::solve_complex(StiffState& re, StiffState& im) const {
  const auto m = static_cast<Eigen::Index>(coupled_);
  CplxVec rc(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<std::size_t>(i);
    rc(i) = {re[k], im[k]};
  }
  const CplxVec xc = lu_cplx_.solve(rc);
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<std::size_t>(i);
    re[k] = xc(i).real();
    im[k] = xc(i).imag();
  }
  for (std::size_t i = coupled_; i < size_; ++i) {
    const auto row = jac_.row(static_cast<Eigen::Index>(i));
    std::complex<double> s(re[i], im[i]);
    for (Eigen::Index j = 0; j < m; ++j) s += row(j) * xc(j);
    s /= fac2_;
    re[i] = s.real();
    im[i] = s.imag();
  }
}

void RadauIntegrator::starting_values(StiffState& z1, StiffState& z2, StiffState& z3) const {
  z1.fill(0);
  z2.fill(0);
  z3.fill(0);
  if (first_) return;
  const double c3q = h_ / h_dense_, c1q = kC1 * c3q, c2q = kC2 * c3q;
  for (std::size_t i = 0; i < size_; ++i) {
    const double a1 = cont_[1][i], a2 = cont_[2][i], a3 = cont_[3][i];
    z1[i] = c1q * (a1 + (c1q - kC2m1) * (a2 + (c1q - kC1m1) * a3));
    z2[i] = c2q * (a1 + (c2q - kC2m1) * (a2 + (c2q - kC1m1) * a3));
    z3[i] = c3q * (a1 + (c3q - kC2m1) * (a2 + (c3q - kC1m1) * a3));
  }
}

/// The simplified Newton iteration on the stage increments z (Hairer &
/// Wanner IV.8). False: no convergence; h_ is already reduced.
bool RadauIntegrator::newton(double t, StiffState& z1, StiffState& z2, StiffState& z3, int& iterations) {
  StiffState f1, f2, f3, a1, a2, a3, y;
  for (std::size_t i = 0; i < size_; ++i) {
    f1[i] = kTi11 * z1[i] + kTi12 * z2[i] + kTi13 * z3[i];
    f2[i] = kTi21 * z1[i] + kTi22 * z2[i] + kTi23 * z3[i];
    f3[i] = kTi31 * z1[i] + kTi32 * z2[i] + kTi33 * z3[i];
  }
  faccon_ = std::pow(std::max(faccon_, kUround), 0.8);
  theta_ = kThet;
  double dynold = 0, thqold = 0;
  const double alphn = fac2_.real(), betan = fac2_.imag();
  for (int newt = 0;;) {
    if (newt >= kNit) break;
    y = y_;
    for (std::size_t i = 0; i < size_; ++i) y[i] = y_[i] + z1[i];
    system_->rhs(t + kC1 * h_, y, a1);
    for (std::size_t i = 0; i < size_; ++i) y[i] = y_[i] + z2[i];
    system_->rhs(t + kC2 * h_, y, a2);
    for (std::size_t i = 0; i < size_; ++i) y[i] = y_[i] + z3[i];
    system_->rhs(t + h_, y, a3);
    counters_.rhs += 3;
    for (std::size_t i = 0; i < size_; ++i) {
      z1[i] = kTi11 * a1[i] + kTi12 * a2[i] + kTi13 * a3[i] - fac1_ * f1[i];
      const double s2 = kTi21 * a1[i] + kTi22 * a2[i] + kTi23 * a3[i];
      const double s3 = kTi31 * a1[i] + kTi32 * a2[i] + kTi33 * a3[i];
      z2[i] = s2 - f2[i] * alphn + f3[i] * betan;
      z3[i] = s3 - f3[i] * alphn - f2[i] * betan;
    }
    solve_real(z1);
    solve_complex(z2, z3);
    ++newt;
    const double n1 = norm(z1), n2 = norm(z2), n3 = norm(z3);
    const double dyno = std::sqrt((n1 * n1 + n2 * n2 + n3 * n3) / 3.0);
    if (newt > 1 && newt < kNit) {
      const double thq = dyno / dynold;
      theta_ = newt == 2 ? thq : std::sqrt(thq * thqold);
      thqold = thq;
      if (!(theta_ < 0.99)) break;
      faccon_ = theta_ / (1.0 - theta_);
      const double dyth = faccon_ * dyno * std::pow(theta_, kNit - 1 - newt) / fnewt_;
      if (dyth >= 1) {  // would not converge in time: a smaller step
        const double qnewt = std::clamp(dyth, 1e-4, 20.0);
        h_ *= 0.8 * std::pow(qnewt, -1.0 / (4.0 + kNit - 1 - newt));
        ++counters_.newton_failures;
        return false;
      }
    }
    dynold = std::max(dyno, kUround);
    for (std::size_t i = 0; i < size_; ++i) {
      f1[i] += z1[i];
      f2[i] += z2[i];
      f3[i] += z3[i];
      z1[i] = kT11 * f1[i] + kT12 * f2[i] + kT13 * f3[i];
      z2[i] = kT21 * f1[i] + kT22 * f2[i] + kT23 * f3[i];
      z3[i] = kT31 * f1[i] + f2[i];
    }
    if (faccon_ * dyno <= fnewt_) {
      iterations = newt;
      return true;
    }
  }
  h_ *= 0.5;  // diverged or too slow
  ++counters_.newton_failures;
  return false;
}

/// The embedded error estimate, filtered by (fac1·I − J)⁻¹ (RADAU5's ESTRAD).
double RadauIntegrator::error_estimate(const StiffState& z1, const StiffState& z2, const StiffState& z3) {
  const double hee1 = kDd1 / h_, hee2 = kDd2 / h_, hee3 = kDd3 / h_;
  StiffState f2{}, cont{};
  for (std::size_t i = 0; i < size_; ++i) {
    f2[i] = hee1 * z1[i] + hee2 * z2[i] + hee3 * z3[i];
    cont[i] = f2[i] + f0_[i];
  }
  solve_real(cont);
  double err = std::max(norm(cont), 1e-10);
  if (err >= 1 && (first_ || reject_)) {
    StiffState y = y_, f1;
    for (std::size_t i = 0; i < size_; ++i) y[i] = y_[i] + cont[i];
    system_->rhs(t_, y, f1);
    ++counters_.rhs;
    for (std::size_t i = 0; i < size_; ++i) cont[i] = f1[i] + f2[i];
    solve_real(cont);
    err = std::max(norm(cont), 1e-10);
  }
  return err;
}

void RadauIntegrator::interpolate(double t, StiffState& y) const {
  if (!stepped_) {
    y = y_;
    return;
  }
  const double s = (t - x_end_) / h_dense_;
  for (std::size_t i = 0; i < kStiffSize; ++i)
    y[i] = cont_[0][i] + s * (cont_[1][i] + (s - kC2m1) * (cont_[2][i] + (s - kC1m1) * cont_[3][i]));
}

double RadauIntegrator::witness_at(double t) {
  StiffState y;
  interpolate(t, y);
  return system_->witness(t, y);
}

/// Illinois on the dense output over [x_start_, x_end_], the witness having
/// the sign of g_lo at the start and of g_hi at the end: the end of the
/// final bracket where the sign has changed (or the exact zero).
double RadauIntegrator::locate_root(double g_lo, double g_hi) {
  double lo = x_start_, hi = x_end_;
  const double ttol = 100 * kUround * (std::abs(x_end_) + std::abs(h_dense_));
  int side = 0;
  for (int it = 0; it < 200 && hi - lo > ttol; ++it) {
    double m = hi - g_hi * (hi - lo) / (g_hi - g_lo);
    if (!(m > lo && m < hi)) m = 0.5 * (lo + hi);
    // keep the new point ttol/2 inside the bracket so that it always shrinks
    m = std::clamp(m, lo + 0.5 * ttol, hi - 0.5 * ttol);
    const double g = witness_at(m);
    if (g == 0) return m;
    if ((g > 0) == (g_hi > 0)) {
      hi = m;
      g_hi = g;
      if (side == 1) g_lo *= 0.5;
      side = 1;
    } else {
      lo = m;
      g_lo = g;
      if (side == -1) g_hi *= 0.5;
      side = -1;
    }
  }
  return hi;
}

StiffIntegrator::Step RadauIntegrator::step(double t_stop) {
  if (at_root_) reset(*system_, t_, y_);  // the last step ended at a root: go on from there
  if (!(t_stop > t_)) throw RunError("Radau IIA: asked to step to t = " + std::to_string(t_stop) + " s, not after t = " +
                                     std::to_string(t_) + " s");
  StiffIntegrator::Step out;
  out.start = t_;
  const double h_proposed = h_;
  bool clamped = false;
  for (;;) {
    if (t_ + 1.0001 * h_ >= t_stop) {
      h_ = t_stop - t_;
      clamped = true;
    }
    if (!(h_ > 1e-14 * std::max(std::abs(t_), 1.0)) && t_stop - t_ > h_)
      throw RunError("Radau IIA could not advance the compliant contact model past t = " + std::to_string(t_) +
                     " s (step size " + std::to_string(h_) +
                     "); try a looser [clearance] tolerance or a lower stiffness");
    if (need_jacobian_) jacobian();
    if (need_lu_ || h_ != h_lu_) decompose();
    StiffState z1, z2, z3;
    starting_values(z1, z2, z3);
    int newt = 0;
    if (!newton(t_, z1, z2, z3, newt)) {
      reject_ = true;
      clamped = false;
      need_jacobian_ = !jac_fresh_;
      need_lu_ = true;
      continue;
    }
    const double err = error_estimate(z1, z2, z3);
    const double fac = std::min(kSafe, kSafe * (1 + 2 * kNit) / (newt + 2 * kNit));
    double quot = std::max(kFacr, std::min(kFacl, std::pow(err, 0.25) / fac));
    double h_new = h_ / quot;
    if (err >= 1) {  // rejected
      ++counters_.error_failures;
      reject_ = true;
      clamped = false;
      h_ = first_ ? 0.1 * h_ : h_new;
      need_jacobian_ = !jac_fresh_;
      need_lu_ = true;
      continue;
    }
    ++accepted_since_reset_;
    if (accepted_since_reset_ > 1) {  // Gustafsson's predictive controller
      const double facgus = std::clamp((h_acc_ / h_) * std::pow(err * err / err_acc_, 0.25) / kSafe, kFacr, kFacl);
      quot = std::max(quot, facgus);
      h_new = h_ / quot;
    }
    h_acc_ = h_;
    err_acc_ = std::max(1e-2, err);
    // The step: the new state and the collocation polynomial.
    x_start_ = t_;
    x_end_ = t_ + h_;
    h_dense_ = h_;
    for (std::size_t i = 0; i < size_; ++i) {
      const double ynew = y_[i] + z3[i];
      cont_[1][i] = (z2[i] - z3[i]) / kC2m1;
      const double ak = (z1[i] - z2[i]) / kC1mc2;
      const double acont3 = (ak - z1[i] / kC1) / kC2;
      cont_[2][i] = (ak - cont_[1][i]) / kC1m1;
      cont_[3][i] = cont_[2][i] - acont3;
      cont_[0][i] = ynew;
      y_[i] = ynew;
    }
    if (clamped) x_end_ = t_stop;  // the same up to rounding; the step ends exactly at t_stop
    t_ = x_end_;
    stepped_ = true;
    first_ = false;
    ++steps_;
    jac_fresh_ = false;
    if (reject_) h_new = std::min(h_new, h_);
    reject_ = false;
    const double qt = h_new / h_;
    if (!(theta_ <= kThet && qt >= kQuot1 && qt <= kQuot2)) {
      h_ = h_new;
      if (theta_ > kThet) need_jacobian_ = true;
    }
    if (clamped) h_ = std::max(h_, h_proposed);
    // The witness at the end: a sign change ends the step at the root.
    const double g_new = system_->witness(t_, y_);
    const bool crossed = g_ != 0 && (g_new == 0 || (g_new > 0) != (g_ > 0));
    if (crossed) {
      const double tr = g_new == 0 ? t_ : locate_root(g_, g_new);
      const double g_r = g_new == 0 ? 0.0 : witness_at(tr);
      out.root = (g_r > 0 || (g_r == 0 && g_ < 0)) ? 1 : -1;
      t_ = tr;
      interpolate(tr, y_);
      at_root_ = true;
      g_ = g_r;
    } else {
      g_ = g_new;
      system_->rhs(t_, y_, f0_);
      ++counters_.rhs;
      set_scale();
    }
    out.end = t_;
    return out;
  }
}

}  // namespace fourbar
