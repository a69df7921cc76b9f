// SUNDIALS CVODE (variable-order Adams–Moulton, functional iteration: the
// problem is not stiff) in one-step mode; dense output from its Nordsieck
// history via CVodeGetDky.

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <string>

#include "common/error.hpp"
#include "sim/integrate/sundials_flags.hpp"
#include "sim/integrate/sundials_kernels.hpp"
#include "sim/integrate/integrator.hpp"

namespace fourbar {

std::unique_ptr<DenseIntegrator> make_cvode_integrator(double tolerance);

namespace {

constexpr SundialsCheck check_cvode{"CVODE"};

class CvodeIntegrator final : public DenseIntegrator {
 public:
  explicit CvodeIntegrator(double tol) {
    check_cvode(SUNContext_Create(nullptr, &ctx_), "context");
    y_ = new_serial_vector(kOdeSize, ctx_);
    dky_ = new_serial_vector(kOdeSize, ctx_);
    N_VConst(0.0, y_);
    mem_ = CVodeCreate(CV_ADAMS, ctx_);
    if (!mem_) throw RunError("CVODE: cannot create the integrator");
    check_cvode(CVodeInit(mem_, &CvodeIntegrator::f, 0.0, y_), "init");
    check_cvode(CVodeSStolerances(mem_, tol, tol), "tolerances");
    nls_ = SUNNonlinSol_FixedPoint(y_, 0, ctx_);
    check_cvode(CVodeSetNonlinearSolver(mem_, nls_), "nonlinear solver");
    check_cvode(CVodeSetUserData(mem_, this), "user data");
    check_cvode(CVodeSetMaxNumSteps(mem_, 1'000'000), "max steps");
    check_cvode(CVodeSetErrHandlerFn(mem_, silent_sundials_handler, nullptr), "error handler");
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
    check_cvode(CVodeReInit(mem_, t0, y_), "reinit");
    t_cvode_ = t0;
  }

  std::pair<double, double> do_step(double t_stop) override {
    check_cvode(CVodeSetStopTime(mem_, t_stop), "stop time");
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
    check_cvode(CVodeGetDky(mem_, t, 0, dky_), "dense output");
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
