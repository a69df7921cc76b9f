// SUNDIALS CVODE (variable-order Adams–Moulton, functional iteration: the
// problem is not stiff) in one-step mode; dense output from its Nordsieck
// history via CVodeGetDky.

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <string>

#include "common/error.hpp"
#include "sim/integrate/integrator.hpp"

namespace fourbar {

std::unique_ptr<DenseIntegrator> make_cvode_integrator(double tolerance);

namespace {

void check(int flag, const char* what) {
  if (flag < 0) throw RunError(std::string("CVODE ") + what + " failed (flag " + std::to_string(flag) + ")");
}

void silent_handler(int, const char*, const char*, char*, void*) {}

class CvodeIntegrator final : public DenseIntegrator {
 public:
  explicit CvodeIntegrator(double tol) {
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

  const char* name() const override { return "cvode"; }

 protected:
  void do_reset(double t0, const OdeState& y0) override {
    double* y = N_VGetArrayPointer(y_);
    for (std::size_t i = 0; i < kOdeSize; ++i) y[i] = y0[i];
    check(CVodeReInit(mem_, t0, y_), "reinit");
    t_cvode_ = t0;
  }

  std::pair<double, double> do_step(double t_stop) override {
    check(CVodeSetStopTime(mem_, t_stop), "stop time");
    double t = t_cvode_;
    const int flag = CVode(mem_, t_stop, y_, &t, CV_ONE_STEP);
    if (flag < 0)
      throw RunError("CVODE could not advance past t = " + std::to_string(t_cvode_) + " s (flag " +
                     std::to_string(flag) + "); try a looser [clearance] tolerance");
    double h = 0;
    CVodeGetLastStep(mem_, &h);
    t_cvode_ = t;
    return {t - h, t};
  }

  void do_interpolate(double t, OdeState& y) override {
    check(CVodeGetDky(mem_, t, 0, dky_), "dense output");
    const double* d = N_VGetArrayPointer(dky_);
    for (std::size_t i = 0; i < kOdeSize; ++i) y[i] = d[i];
  }

 private:
  static int f(double t, N_Vector y, N_Vector ydot, void* user) {
    auto* self = static_cast<CvodeIntegrator*>(user);
    const double* yy = N_VGetArrayPointer(y);
    double* dd = N_VGetArrayPointer(ydot);
    OdeState in, out;
    for (std::size_t i = 0; i < kOdeSize; ++i) in[i] = yy[i];
    self->system().rhs(t, in, out);
    for (std::size_t i = 0; i < kOdeSize; ++i) dd[i] = out[i];
    return 0;
  }

  SUNContext ctx_ = nullptr;
  N_Vector y_ = nullptr, dky_ = nullptr;
  void* mem_ = nullptr;
  SUNNonlinearSolver nls_ = nullptr;
  double t_cvode_ = 0;
};

}  // namespace

std::unique_ptr<DenseIntegrator> make_cvode_integrator(double tolerance) {
  return std::make_unique<CvodeIntegrator>(tolerance);
}

}  // namespace fourbar
