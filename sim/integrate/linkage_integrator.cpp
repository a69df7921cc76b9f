#include "sim/integrate/linkage_integrator.hpp"

#include <arkode/arkode_arkstep.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/error.hpp"
#include "sim/integrate/sundials_flags.hpp"
#include "sim/integrate/sundials_kernels.hpp"
#include "sim/integrate/second_order_linear_solver.hpp"

namespace fourbar {

namespace {

constexpr SundialsCheck check_linkage{"SUNDIALS (linkage)"};

constexpr long kJacobianAge = 1000;  ///< steps between Jacobians when Newton keeps converging

/// The books' (work, dissipation, impulses: the components from `coupled` on)
/// absolute tolerance, as a share of the state's. No right-hand side reads
/// them, so their local errors are not damped by the dynamics; over a
/// sustained contact with the regularised friction law they all have one sign
/// and add up step after step (rigid links, B, 0.254 mm, e 0.5, μ 0.3,
/// 1000 rpm, tol 1e-10: the energy residual grew 4.4e-11 of the scale a step
/// over 250 steps to 1.04e-8, above the stress grid's 1e-8). A hundredth of
/// the tolerance on them: bench/stress_linkage 432/432 for BDF (worst
/// 5.1e-9) and Adams (5.6e-9), was 431 and 429; the speed case's steps
/// unchanged (bench/elastic_linkage_work_precision, docs/linkage-model.md).
constexpr double kBookToleranceShare = 0.01;

int linkage_rhs(double t, N_Vector y, N_Vector ydot, void* user) {
  auto* self = static_cast<LinkageIntegrator*>(user);
  try {
    self->ode().rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
  } catch (...) {
    self->pending = std::current_exception();
    return -1;  // unrecoverable: CVode returns, step() rethrows
  }
  return 0;
}

int linkage_roots(double t, N_Vector y, double* g, void* user) {
  auto* self = static_cast<LinkageIntegrator*>(user);
  try {
    self->ode().witnesses(t, N_VGetArrayPointer(y), g);
  } catch (...) {
    self->pending = std::current_exception();
    return -1;
  }
  return 0;
}

/// Forward differences over the coupled columns, increment √u·max(|y_j|, 1e-3)
/// (the state is scaled to order one), as stiff_integrator.cpp.
int linkage_jacobian(double t, N_Vector y, N_Vector fy, SUNMatrix J, void* user, N_Vector, N_Vector, N_Vector) {
  auto* self = static_cast<LinkageIntegrator*>(user);
  const std::size_t n = self->size();
  std::vector<double>& yy = self->scratch0;
  std::vector<double>& f1 = self->scratch1;
  const double* y0 = N_VGetArrayPointer(y);
  const double* f0 = N_VGetArrayPointer(fy);
  yy.assign(y0, y0 + n);
  f1.resize(n);
  SUNMatZero(J);
  const double sqrt_u = std::sqrt(2.220446049250313e-16);
  for (std::size_t j = 0; j < self->coupled(); ++j) {
    const double yj = yy[j];
    const double inc = sqrt_u * std::max(std::abs(yj), 1e-3);
    yy[j] = yj + inc;
    try {
      self->ode().rhs(t, yy.data(), f1.data());
    } catch (...) {
      self->pending = std::current_exception();
      return -1;
    }
    yy[j] = yj;
    double* col = SUNDenseMatrix_Column(J, static_cast<sunindextype>(j));
    for (std::size_t i = 0; i < n; ++i) col[i] = (f1[i] - f0[i]) / inc;
  }
  return 0;
}

}  // namespace

struct LinkageIntegrator::Cvode {
  LinkageMethod method = LinkageMethod::bdf;
  bool ark() const { return method != LinkageMethod::bdf && method != LinkageMethod::adams; }
  SUNContext ctx = nullptr;
  N_Vector y = nullptr, dky = nullptr, atol = nullptr, ele = nullptr, ewt = nullptr;
  SUNMatrix jac = nullptr;
  SUNLinearSolver ls = nullptr;
  void* mem = nullptr;
  double tol = 0;
  bool initialised = false;
};

LinkageIntegrator::LinkageIntegrator(double tolerance, std::size_t size, std::size_t coupled, std::size_t roots,
                                     LinkageMethod method)
    : cv_(std::make_unique<Cvode>()), size_(size), coupled_(coupled), roots_(roots) {
  if (!(coupled <= size && size > 0)) throw std::logic_error("LinkageIntegrator: size out of range");
  Cvode& c = *cv_;
  c.method = method;
  c.tol = tolerance;
  check_linkage(SUNContext_Create(nullptr, &c.ctx), "context");
  const auto n = static_cast<sunindextype>(size);
  c.y = new_serial_vector(n, c.ctx);
  c.dky = new_serial_vector(n, c.ctx);
  c.ele = new_serial_vector(n, c.ctx);
  c.ewt = new_serial_vector(n, c.ctx);
  N_VConst(0.0, c.y);
  c.atol = new_serial_vector(n, c.ctx);
  double* atol = N_VGetArrayPointer(c.atol);
  for (std::size_t i = 0; i < size; ++i) atol[i] = i < coupled ? tolerance : kBookToleranceShare * tolerance;
  if (!c.ark()) {
    c.mem = CVodeCreate(method == LinkageMethod::adams ? CV_ADAMS : CV_BDF, c.ctx);
    if (!c.mem) throw RunError("CVODE (linkage): cannot create the integrator");
  }
  c.jac = new_dense_matrix(n, n, c.ctx);
  c.ls = second_order_linear_solver(c.ctx, size, coupled / 2);
  if (!c.ls) throw RunError("SUNDIALS (linkage): cannot create the linear solver");
}

LinkageIntegrator::~LinkageIntegrator() {
  Cvode& c = *cv_;
  if (c.ark())
    ARKStepFree(&c.mem);
  else
    CVodeFree(&c.mem);
  SUNLinSolFree(c.ls);
  SUNMatDestroy(c.jac);
  N_VDestroy(c.y);
  N_VDestroy(c.dky);
  N_VDestroy(c.ele);
  N_VDestroy(c.ewt);
  N_VDestroy(c.atol);
  SUNContext_Free(&c.ctx);
}

void LinkageIntegrator::reset(LinkageOde& ode, double t0, const std::vector<double>& y0) {
  Cvode& c = *cv_;
  ode_ = &ode;
  std::copy(y0.begin(), y0.begin() + static_cast<std::ptrdiff_t>(size_), N_VGetArrayPointer(c.y));
  y0_ = y0;
  t_ = t0;
  stepped_ = false;
  if (c.ark()) {
    reset_arkode(t0);
    return;
  }
  if (!c.initialised) {
    check_linkage(CVodeInit(c.mem, linkage_rhs, t0, c.y), "init");
    check_linkage(CVodeSVtolerances(c.mem, c.tol, c.atol), "tolerances");
    check_linkage(CVodeSetUserData(c.mem, this), "user data");
    check_linkage(CVodeSetLinearSolver(c.mem, c.ls, c.jac), "linear solver");
    check_linkage(CVodeSetJacFn(c.mem, linkage_jacobian), "Jacobian");
    check_linkage(CVodeSetMaxNumSteps(c.mem, 1'000'000), "max steps");
    // The Jacobian is re-evaluated only when Newton fails to converge, not
    // every 51 steps: it is nearly constant between contact changes (the
    // modes are linear), and Newton still converges in ~1 iteration a step
    // with a 1000-step-old one (elastic 4+4 modes, tol 1e-9: 48 Jacobians a
    // turn instead of 696, same steps and error; docs/linkage-model.md).
    check_linkage(CVodeSetJacEvalFrequency(c.mem, kJacobianAge), "Jacobian age");
    check_linkage(CVodeSetErrHandlerFn(c.mem, silent_sundials_handler, nullptr), "error handler");
    check_linkage(CVodeRootInit(c.mem, static_cast<int>(roots_), linkage_roots), "root finding");
    c.initialised = true;
  } else {
    const Counters k = counters();
    before_reset_ = k;
    check_linkage(CVodeReInit(c.mem, t0, c.y), "reinit");
  }
}

void LinkageIntegrator::reset_arkode(double t0) {
  Cvode& c = *cv_;
  const bool explicit_rk = c.method == LinkageMethod::erk;
  if (!c.initialised) {
    c.mem = explicit_rk ? ARKStepCreate(linkage_rhs, nullptr, t0, c.y, c.ctx) : ARKStepCreate(nullptr, linkage_rhs, t0, c.y, c.ctx);
    if (!c.mem) throw RunError("ARKODE (linkage): cannot create the integrator");
    check_linkage(ARKStepSVtolerances(c.mem, c.tol, c.atol), "tolerances");
    check_linkage(ARKStepSetUserData(c.mem, this), "user data");
    if (explicit_rk) {
      check_linkage(ARKStepSetTableNum(c.mem, ARKODE_DIRK_NONE, ARKODE_VERNER_8_5_6), "ERK table");
    } else {
      check_linkage(ARKStepSetLinearSolver(c.mem, c.ls, c.jac), "linear solver");
      check_linkage(ARKStepSetJacFn(c.mem, linkage_jacobian), "Jacobian");
      const ARKODE_DIRKTableID table =
          c.method == LinkageMethod::esdirk4 ? ARKODE_ESDIRK436L2SA_6_3_4 : ARKODE_ESDIRK547L2SA2_7_4_5;
      check_linkage(ARKStepSetTableNum(c.mem, table, ARKODE_ERK_NONE), "ESDIRK table");
    }
    check_linkage(ARKStepSetInterpolantDegree(c.mem, ARK_INTERP_MAX_DEGREE), "interpolant");
    check_linkage(ARKStepSetMaxNumSteps(c.mem, 1'000'000), "max steps");
    check_linkage(ARKStepSetErrHandlerFn(c.mem, silent_sundials_handler, nullptr), "error handler");
    check_linkage(ARKStepRootInit(c.mem, static_cast<int>(roots_), linkage_roots), "root finding");
    c.initialised = true;
  } else {
    before_reset_ = counters();
    check_linkage(explicit_rk ? ARKStepReInit(c.mem, linkage_rhs, nullptr, t0, c.y) : ARKStepReInit(c.mem, nullptr, linkage_rhs, t0, c.y),
          "reinit");
  }
}

LinkageIntegrator::Step LinkageIntegrator::step(double t_stop) {
  Cvode& c = *cv_;
  double t = t_;
  int flag = 0;
  bool root = false;
  if (c.ark()) {
    check_linkage(ARKStepSetStopTime(c.mem, t_stop), "stop time");
    flag = ARKStepEvolve(c.mem, t_stop, c.y, &t, ARK_ONE_STEP);
    root = flag == ARK_ROOT_RETURN;
  } else {
    check_linkage(CVodeSetStopTime(c.mem, t_stop), "stop time");
    flag = CVode(c.mem, t_stop, c.y, &t, CV_ONE_STEP);
    root = flag == CV_ROOT_RETURN;
  }
  if (pending) std::rethrow_exception(std::exchange(pending, nullptr));
  if (flag < 0)
    throw RunError(std::string(c.ark() ? "ARKODE" : "CVODE") + " could not advance the linkage model past t = " + std::to_string(t_) + " s (flag " +
                   std::to_string(flag) + "); try a looser [linkage] tolerance or a lower contact stiffness");
  Step s;
  s.start = t_;
  s.end = t;
  s.roots.assign(roots_, 0);
  if (root) {
    std::vector<int> found(roots_, 0);
    check_linkage(c.ark() ? ARKStepGetRootInfo(c.mem, found.data()) : CVodeGetRootInfo(c.mem, found.data()), "root info");
    for (std::size_t i = 0; i < roots_; ++i) s.roots[i] = found[i] > 0 ? 1 : (found[i] < 0 ? -1 : 0);
    s.any_root = true;
  }
  t_ = t;
  const double* p = N_VGetArrayPointer(c.y);
  y_end_.assign(p, p + size_);
  ++steps_;
  stepped_ = true;
  return s;
}

LinkageIntegrator::StepReport LinkageIntegrator::last_step_report() {
  Cvode& c = *cv_;
  StepReport r;
  if (!stepped_) return r;
  if (c.ark()) {
    check_linkage(ARKStepGetLastStep(c.mem, &r.step_s), "last step");
    check_linkage(ARKStepGetEstLocalErrors(c.mem, c.ele), "local errors");
    check_linkage(ARKStepGetErrWeights(c.mem, c.ewt), "error weights");
  } else {
    check_linkage(CVodeGetLastStep(c.mem, &r.step_s), "last step");
    check_linkage(CVodeGetLastOrder(c.mem, &r.order), "last order");
    check_linkage(CVodeGetEstLocalErrors(c.mem, c.ele), "local errors");
    check_linkage(CVodeGetErrWeights(c.mem, c.ewt), "error weights");
  }
  const double* e = N_VGetArrayPointer(c.ele);
  const double* w = N_VGetArrayPointer(c.ewt);
  for (std::size_t i = 0; i < size_; ++i)
    if (const double v = std::abs(e[i] * w[i]); v > r.weighted_error) {
      r.weighted_error = v;
      r.limiting = i;
    }
  return r;
}

void LinkageIntegrator::interpolate(double t, std::vector<double>& y) {
  if (!stepped_) {
    y = y0_;
    return;
  }
  if (t == t_) {
    y = y_end_;
    return;
  }
  check_linkage(cv_->ark() ? ARKStepGetDky(cv_->mem, t, 0, cv_->dky) : CVodeGetDky(cv_->mem, t, 0, cv_->dky), "dense output");
  const double* p = N_VGetArrayPointer(cv_->dky);
  y.assign(p, p + size_);
}

LinkageIntegrator::Counters LinkageIntegrator::since_reset() const {
  Counters c;
  if (!cv_->initialised) return c;
  if (cv_->ark()) {
    long fe = 0, fi = 0, setups = 0;
    ARKStepGetNumRhsEvals(cv_->mem, &fe, &fi);
    c.rhs = fe + fi;
    if (cv_->method != LinkageMethod::erk) {
      ARKStepGetNumJacEvals(cv_->mem, &c.jacobians);
      ARKStepGetNumNonlinSolvConvFails(cv_->mem, &c.newton_failures);
    }
    ARKStepGetNumErrTestFails(cv_->mem, &c.error_failures);
    (void)setups;
    return c;
  }
  CVodeGetNumRhsEvals(cv_->mem, &c.rhs);
  CVodeGetNumJacEvals(cv_->mem, &c.jacobians);
  CVodeGetNumErrTestFails(cv_->mem, &c.error_failures);
  CVodeGetNumNonlinSolvConvFails(cv_->mem, &c.newton_failures);
  return c;
}

LinkageIntegrator::Counters LinkageIntegrator::counters() const {
  Counters c = since_reset();
  c.rhs += before_reset_.rhs;
  c.jacobians += before_reset_.jacobians;
  c.error_failures += before_reset_.error_failures;
  c.newton_failures += before_reset_.newton_failures;
  return c;
}

}  // namespace fourbar
