#include "sim/integrate/stiff_integrator.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <stdexcept>
#include <cmath>
#include <string>

#include "common/error.hpp"
#include "sim/integrate/sundials_flags.hpp"
#include "sim/integrate/sundials_kernels.hpp"
#include "sim/integrate/radau_integrator.hpp"

namespace fourbar {

namespace {

constexpr SundialsCheck check_bdf{"CVODE (BDF)"};

/// The first N_VGetLength(v) components (the rest of `a` zero).
void copy_in(N_Vector v, StiffState& a) {
  const double* p = N_VGetArrayPointer(v);
  const auto n = static_cast<std::size_t>(N_VGetLength(v));
  std::copy(p, p + n, a.begin());
  std::fill(a.begin() + static_cast<std::ptrdiff_t>(n), a.end(), 0.0);
}

void copy_out(const StiffState& a, N_Vector v) {
  const auto n = static_cast<std::ptrdiff_t>(N_VGetLength(v));
  std::copy(a.begin(), a.begin() + n, N_VGetArrayPointer(v));
}

}  // namespace

struct StiffIntegrator::Cvode {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr, dky = nullptr;
  SUNMatrix jac = nullptr;
  SUNLinearSolver ls = nullptr;
  SUNNonlinearSolver fixed_point = nullptr;  ///< Adams with functional iteration only
  void* mem = nullptr;
  double tol = 0;
  bool initialised = false;
};

namespace {

int rhs_fn(double t, N_Vector y, N_Vector ydot, void* user) {
  auto* self = static_cast<StiffIntegrator*>(user);
  StiffState in, out;
  copy_in(y, in);
  self->system().rhs(t, in, out);
  copy_out(out, ydot);
  return 0;
}

int root_fn(double t, N_Vector y, double* g, void* user) {
  auto* self = static_cast<StiffIntegrator*>(user);
  StiffState in;
  copy_in(y, in);
  g[0] = self->system().witness(t, in);
  return 0;
}

/// Forward differences over the coupled columns with the increment
/// √u·max(|y_j|, 1e-3) (the state is scaled to order one); the quadrature
/// columns stay zero.
int jac_fn(double t, N_Vector y, N_Vector fy, SUNMatrix J, void* user, N_Vector, N_Vector, N_Vector) {
  auto* self = static_cast<StiffIntegrator*>(user);
  StiffState yy, f0, f1;
  copy_in(y, yy);
  copy_in(fy, f0);
  SUNMatZero(J);
  const double sqrt_u = std::sqrt(2.220446049250313e-16);
  for (std::size_t j = 0; j < self->coupled(); ++j) {
    const double yj = yy[j];
    const double inc = sqrt_u * std::max(std::abs(yj), 1e-3);
    yy[j] = yj + inc;
    self->system().rhs(t, yy, f1);
    yy[j] = yj;
    double* col = SUNDenseMatrix_Column(J, static_cast<sunindextype>(j));
    for (std::size_t i = 0; i < self->size(); ++i) col[i] = (f1[i] - f0[i]) / inc;
  }
  return 0;
}

}  // namespace

StiffIntegrator::StiffIntegrator(double tolerance, std::size_t coupled, std::size_t size, StiffMethod method)
    : cv_(std::make_unique<Cvode>()), coupled_(coupled), size_(size) {
  if (!(coupled <= size && size <= kStiffSize)) throw std::logic_error("StiffIntegrator: size out of range");
  if (method == StiffMethod::radau5) {
    radau_ = std::make_unique<RadauIntegrator>(tolerance, coupled, size);
    return;
  }
  Cvode& c = *cv_;
  c.tol = tolerance;
  check_bdf(SUNContext_Create(nullptr, &c.ctx), "context");
  const auto n = static_cast<sunindextype>(size);
  c.y = new_serial_vector(n, c.ctx);
  c.dky = new_serial_vector(n, c.ctx);
  N_VConst(0.0, c.y);
  c.mem = CVodeCreate(method == StiffMethod::bdf ? CV_BDF : CV_ADAMS, c.ctx);
  if (!c.mem) throw RunError("CVODE (BDF): cannot create the integrator");
  if (method == StiffMethod::adams_fixed_point) {
    c.fixed_point = SUNNonlinSol_FixedPoint(c.y, 0, c.ctx);
  } else {
    c.jac = new_dense_matrix(n, n, c.ctx);
    c.ls = SUNLinSol_Dense(c.y, c.jac, c.ctx);
  }
}

StiffIntegrator::~StiffIntegrator() {
  if (radau_) return;
  Cvode& c = *cv_;
  CVodeFree(&c.mem);
  if (c.fixed_point) SUNNonlinSolFree(c.fixed_point);
  if (c.ls) SUNLinSolFree(c.ls);
  if (c.jac) SUNMatDestroy(c.jac);
  N_VDestroy(c.y);
  N_VDestroy(c.dky);
  SUNContext_Free(&c.ctx);
}

void StiffIntegrator::reset(StiffSystem& system, double t0, const StiffState& y0) {
  if (radau_) {
    system_ = &system;
    return radau_->reset(system, t0, y0);
  }
  Cvode& c = *cv_;
  system_ = &system;
  copy_out(y0, c.y);
  y0_ = y0;
  t_ = t0;
  stepped_ = false;
  if (!c.initialised) {
    check_bdf(CVodeInit(c.mem, rhs_fn, t0, c.y), "init");
    check_bdf(CVodeSStolerances(c.mem, c.tol, c.tol), "tolerances");
    check_bdf(CVodeSetUserData(c.mem, this), "user data");
    if (c.fixed_point) {
      check_bdf(CVodeSetNonlinearSolver(c.mem, c.fixed_point), "nonlinear solver");
    } else {
      check_bdf(CVodeSetLinearSolver(c.mem, c.ls, c.jac), "linear solver");
      check_bdf(CVodeSetJacFn(c.mem, jac_fn), "Jacobian");
    }
    check_bdf(CVodeSetMaxNumSteps(c.mem, 1'000'000), "max steps");
    check_bdf(CVodeSetErrHandlerFn(c.mem, silent_sundials_handler, nullptr), "error handler");
    check_bdf(CVodeRootInit(c.mem, 1, root_fn), "root finding");
    c.initialised = true;
  } else {
    before_reset_ = counters();
    check_bdf(CVodeReInit(c.mem, t0, c.y), "reinit");
  }
}

StiffIntegrator::Step StiffIntegrator::step(double t_stop) {
  if (radau_) {
    ++steps_;
    return radau_->step(t_stop);
  }
  Cvode& c = *cv_;
  check_bdf(CVodeSetStopTime(c.mem, t_stop), "stop time");
  double t = t_;
  const int flag = CVode(c.mem, t_stop, c.y, &t, CV_ONE_STEP);
  if (flag < 0)
    throw RunError("CVODE (BDF) could not advance the compliant contact model past t = " + std::to_string(t_) +
                   " s (flag " + std::to_string(flag) + "); try a looser [clearance] tolerance or a lower stiffness");
  Step s;
  s.start = t_;
  s.end = t;
  if (flag == CV_ROOT_RETURN) {
    int found = 0;
    check_bdf(CVodeGetRootInfo(c.mem, &found), "root info");
    s.root = found > 0 ? 1 : -1;
  }
  t_ = t;
  copy_in(c.y, y_end_);
  ++steps_;
  stepped_ = true;
  return s;
}

StiffIntegrator::Counters StiffIntegrator::counters() const {
  if (radau_) return radau_->counters();
  Counters c = since_reset();
  c.rhs += before_reset_.rhs;
  c.jacobians += before_reset_.jacobians;
  c.error_failures += before_reset_.error_failures;
  c.newton_failures += before_reset_.newton_failures;
  return c;
}

StiffIntegrator::Counters StiffIntegrator::since_reset() const {
  Counters c;
  if (!cv_->initialised) return c;
  CVodeGetNumRhsEvals(cv_->mem, &c.rhs);
  CVodeGetNumJacEvals(cv_->mem, &c.jacobians);
  CVodeGetNumErrTestFails(cv_->mem, &c.error_failures);
  CVodeGetNumNonlinSolvConvFails(cv_->mem, &c.newton_failures);
  return c;
}

void StiffIntegrator::interpolate(double t, StiffState& y) {
  if (radau_) return radau_->interpolate(t, y);
  if (!stepped_) {
    y = y0_;
    return;
  }
  if (t == t_) {  // the step's end: CVODE's own output, what the dense output gives there
    y = y_end_;
    return;
  }
  check_bdf(CVodeGetDky(cv_->mem, t, 0, cv_->dky), "dense output");
  copy_in(cv_->dky, y);
}

}  // namespace fourbar
