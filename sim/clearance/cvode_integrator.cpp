// SUNDIALS CVODE (variable-order Adams–Moulton, functional iteration: the
// problem is not stiff) in one-step mode; dense output from its Nordsieck
// history via CVodeGetDky.

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <string>

#include "common/error.hpp"
#include "sim/clearance/integrator.hpp"

namespace fourbar {

std::unique_ptr<DenseIntegrator> make_cvode_integrator(double tolerance);

namespace {

void check(int flag, const char* what) {
  if (flag < 0) throw RunError(std::string("CVODE ") + what + " failed (flag " + std::to_string(flag) + ")");
}

void silent_handler(int, const char*, const char*, char*, void*) {}

class CvodeIntegrator final : public DenseIntegrator {
 public:
  explicit CvodeIntegrator(double tol) : tol_(tol) {
    check(SUNContext_Create(nullptr, &ctx_), "context");
    y_ = N_VNew_Serial(kOdeSize, ctx_);
    dky_ = N_VNew_Serial(kOdeSize, ctx_);
    N_VConst(0.0, y_);
    mem_ = CVodeCreate(CV_ADAMS, ctx_);
    if (!mem_) throw RunError("CVODE: cannot create the integrator");
    check(CVodeInit(mem_, &CvodeIntegrator::f, 0.0, y_), "init");
    check(CVodeSStolerances(mem_, tol, tol), "tolerances");
    nls_ = SUNNonlinSol_FixedPoint(y_, 0, ctx_);
    check(CVodeSetNonlinearSolver(mem_, nls_), "nonlinear solver");
    check(CVodeSetUserData(mem_, this), "user data");
    check(CVodeSetMaxNumSteps(mem_, 1'000'000), "max steps");
    check(CVodeSetErrHandlerFn(mem_, silent_handler, nullptr), "error handler");
  }
  ~CvodeIntegrator() override {
    CVodeFree(&mem_);
    SUNNonlinSolFree(nls_);
    N_VDestroy(y_);
    N_VDestroy(dky_);
    SUNContext_Free(&ctx_);
  }

  void reset(OdeSystem& system, double t0, const OdeState& y0) override {
    system_ = &system;
    double* y = N_VGetArrayPointer(y_);
    for (std::size_t i = 0; i < kOdeSize; ++i) y[i] = y0[i];
    check(CVodeReInit(mem_, t0, y_), "reinit");
    t_ = t_prev_ = t0;
    y0_ = y0;
    stepped_ = false;
  }

  double step(double t_stop) override {
    check(CVodeSetStopTime(mem_, t_stop), "stop time");
    double t = t_;
    const int flag = CVode(mem_, t_stop, y_, &t, CV_ONE_STEP);
    if (flag < 0)
      throw RunError("CVODE could not advance past t = " + std::to_string(t_) + " s (flag " +
                     std::to_string(flag) + "); try a looser [clearance] tolerance");
    double h = 0;
    CVodeGetLastStep(mem_, &h);
    t_prev_ = t - h;
    t_ = t;
    ++steps_;
    stepped_ = true;
    return t_;
  }

  double previous_time() const override { return t_prev_; }
  double current_time() const override { return t_; }

  void interpolate(double t, OdeState& y) override {
    if (!stepped_) {  // before the first step only the start point is known
      y = y0_;
      return;
    }
    check(CVodeGetDky(mem_, t, 0, dky_), "dense output");
    const double* d = N_VGetArrayPointer(dky_);
    for (std::size_t i = 0; i < kOdeSize; ++i) y[i] = d[i];
  }

  std::size_t steps() const override { return steps_; }
  const char* name() const override { return "cvode"; }

 private:
  static int f(double t, N_Vector y, N_Vector ydot, void* user) {
    auto* self = static_cast<CvodeIntegrator*>(user);
    const double* yy = N_VGetArrayPointer(y);
    double* dd = N_VGetArrayPointer(ydot);
    OdeState in, out;
    for (std::size_t i = 0; i < kOdeSize; ++i) in[i] = yy[i];
    self->system_->rhs(t, in, out);
    for (std::size_t i = 0; i < kOdeSize; ++i) dd[i] = out[i];
    return 0;
  }

  double tol_;
  SUNContext ctx_ = nullptr;
  N_Vector y_ = nullptr, dky_ = nullptr;
  void* mem_ = nullptr;
  SUNNonlinearSolver nls_ = nullptr;
  OdeSystem* system_ = nullptr;
  double t_ = 0, t_prev_ = 0;
  std::size_t steps_ = 0;
  OdeState y0_{};
  bool stepped_ = false;
};

}  // namespace

std::unique_ptr<DenseIntegrator> make_cvode_integrator(double tolerance) {
  return std::make_unique<CvodeIntegrator>(tolerance);
}

}  // namespace fourbar
