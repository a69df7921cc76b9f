// Boost.Odeint: Dormand–Prince 5(4) with step-size control and its
// continuous extension (dense output).

#include <boost/numeric/odeint.hpp>

#include "sim/clearance/integrator.hpp"

namespace fourbar {

std::unique_ptr<DenseIntegrator> make_cvode_integrator(double tolerance);

namespace {

namespace odeint = boost::numeric::odeint;

class OdeintIntegrator final : public DenseIntegrator {
 public:
  explicit OdeintIntegrator(double tol)
      : tol_(tol), stepper_(odeint::make_dense_output(tol, tol, odeint::runge_kutta_dopri5<OdeState>())) {}

  void reset(OdeSystem& system, double t0, const OdeState& y0) override {
    system_ = &system;
    // First step: a small fraction of the last accepted one (the controller grows it).
    const double dt0 = h_ > 0 ? 0.25 * h_ : 1e-6;
    stepper_.initialize(y0, t0, dt0);
    t_ = t_prev_ = t0;
    y0_ = y0;
    stepped_ = false;
  }

  double step(double) override {
    auto sys = [this](const OdeState& y, OdeState& dydt, double t) { system_->rhs(t, y, dydt); };
    const auto [a, b] = stepper_.do_step(sys);
    t_prev_ = a;
    t_ = b;
    h_ = b - a;
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
    stepper_.calc_state(t, y);
  }
  std::size_t steps() const override { return steps_; }
  const char* name() const override { return "odeint"; }

 private:
  double tol_;
  odeint::result_of::make_dense_output<odeint::runge_kutta_dopri5<OdeState>>::type stepper_;
  OdeSystem* system_ = nullptr;
  double t_ = 0, t_prev_ = 0, h_ = 0;
  std::size_t steps_ = 0;
  OdeState y0_{};
  bool stepped_ = false;
};

}  // namespace

std::unique_ptr<DenseIntegrator> make_integrator(IntegratorKind kind, double tolerance) {
  if (kind == IntegratorKind::cvode) return make_cvode_integrator(tolerance);
  return std::make_unique<OdeintIntegrator>(tolerance);
}

}  // namespace fourbar
