// Boost.Odeint: Dormand–Prince 5(4) with step-size control and its
// continuous extension (dense output).

#include <boost/numeric/odeint.hpp>

#include "sim/integrate/integrator.hpp"

namespace fourbar {

std::unique_ptr<DenseIntegrator> make_cvode_integrator(double tolerance);

namespace {

namespace odeint = boost::numeric::odeint;

class OdeintIntegrator final : public DenseIntegrator {
 public:
  explicit OdeintIntegrator(double tol)
      : stepper_(odeint::make_dense_output(tol, tol, odeint::runge_kutta_dopri5<OdeState>())) {}
  const char* name() const override { return "odeint"; }
  bool stages_inside_step() const override { return true; }

 protected:
  void do_reset(double t0, const OdeState& y0) override {
    // First step: a small fraction of the last accepted one (the controller grows it).
    stepper_.initialize(y0, t0, h_ > 0 ? 0.25 * h_ : 1e-6);
  }

  std::pair<double, double> do_step(double) override {
    auto sys = [this](const OdeState& y, OdeState& dydt, double t) { system().rhs(t, y, dydt); };
    const auto [a, b] = stepper_.do_step(sys);
    h_ = b - a;
    return {a, b};
  }

  void do_interpolate(double t, OdeState& y) override { stepper_.calc_state(t, y); }

 private:
  odeint::result_of::make_dense_output<odeint::runge_kutta_dopri5<OdeState>>::type stepper_;
  double h_ = 0;
};

}  // namespace

std::unique_ptr<DenseIntegrator> make_integrator(IntegratorKind kind, double tolerance) {
  if (kind == IntegratorKind::cvode) return make_cvode_integrator(tolerance);
  return std::make_unique<OdeintIntegrator>(tolerance);
}

}  // namespace fourbar
