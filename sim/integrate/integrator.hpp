#pragma once
// A dense-output ODE integrator behind one small interface, so the simulator
// can run on SUNDIALS CVODE or Boost.Odeint (and tests can compare the two).
// The state has a fixed size; modes that need fewer components keep the rest 0.
// Both integrators see a scaled state (every component of order one), so one
// relative and one absolute tolerance fit every component.

#include <array>
#include <cstddef>
#include <memory>
#include <utility>

#include "sim/integrate/integrator_options.hpp"

namespace fourbar {

inline constexpr std::size_t kOdeSize = 5;
using OdeState = std::array<double, kOdeSize>;

class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual void rhs(double t, const OdeState& y, OdeState& dydt) = 0;
};

/// Common bookkeeping (times, step count, the start point before the first
/// step); the library-specific parts are the do_* hooks.
class DenseIntegrator {
 public:
  virtual ~DenseIntegrator() = default;
  /// (Re)starts at (t0, y0) with `system`; the order/step history is dropped.
  void reset(OdeSystem& system, double t0, const OdeState& y0) {
    system_ = &system;
    t_ = t_prev_ = t0;
    y0_ = y0;
    stepped_ = false;
    do_reset(t0, y0);
  }
  /// Takes one step (CVODE never past `t_stop`); returns the new time.
  double step(double t_stop) {
    const auto [a, b] = do_step(t_stop);
    t_prev_ = a;
    t_ = b;
    ++steps_;
    stepped_ = true;
    return t_;
  }
  /// Start of the last step; interpolate() is valid on [previous_time, current_time].
  double previous_time() const { return t_prev_; }
  double current_time() const { return t_; }
  void interpolate(double t, OdeState& y) {
    if (!stepped_) {  // before the first step only the start point is known
      y = y0_;
      return;
    }
    do_interpolate(t, y);
  }
  std::size_t steps() const { return steps_; }
  virtual const char* name() const = 0;
  /// True when every right-hand-side call during step() lies inside the
  /// interval of the step taken or of a longer rejected trial of it (one-step
  /// Runge–Kutta methods), so those calls sample the step for events.
  virtual bool stages_inside_step() const { return false; }

 protected:
  virtual void do_reset(double t0, const OdeState& y0) = 0;
  /// One step; returns its start and end time.
  virtual std::pair<double, double> do_step(double t_stop) = 0;
  virtual void do_interpolate(double t, OdeState& y) = 0;
  OdeSystem& system() { return *system_; }

 private:
  OdeSystem* system_ = nullptr;
  double t_ = 0, t_prev_ = 0;
  std::size_t steps_ = 0;
  OdeState y0_{};
  bool stepped_ = false;
};

/// `tolerance` is used as relative and absolute tolerance on the scaled state.
std::unique_ptr<DenseIntegrator> make_integrator(IntegratorKind kind, double tolerance);

}  // namespace fourbar
