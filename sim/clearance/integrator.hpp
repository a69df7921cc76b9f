#pragma once
// A dense-output ODE integrator behind one small interface, so the simulator
// can run on SUNDIALS CVODE or Boost.Odeint (and tests can compare the two).
// The state has a fixed size; modes that need fewer components keep the rest 0.
// Both integrators see a scaled state (every component of order one), so one
// relative and one absolute tolerance fit every component.

#include <array>
#include <cstddef>
#include <memory>

#include "sim/clearance/settings.hpp"

namespace fourbar {

inline constexpr std::size_t kOdeSize = 5;
using OdeState = std::array<double, kOdeSize>;

class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual void rhs(double t, const OdeState& y, OdeState& dydt) = 0;
};

class DenseIntegrator {
 public:
  virtual ~DenseIntegrator() = default;
  /// (Re)starts at (t0, y0) with `system`; the order/step history is dropped.
  virtual void reset(OdeSystem& system, double t0, const OdeState& y0) = 0;
  /// Takes one step (CVODE never past `t_stop`); returns the new time.
  virtual double step(double t_stop) = 0;
  /// Start of the last step; interpolate() is valid on [previous_time, current_time].
  virtual double previous_time() const = 0;
  virtual double current_time() const = 0;
  virtual void interpolate(double t, OdeState& y) = 0;
  virtual std::size_t steps() const = 0;
  virtual const char* name() const = 0;
};

/// `tolerance` is used as relative and absolute tolerance on the scaled state.
std::unique_ptr<DenseIntegrator> make_integrator(IntegratorKind kind, double tolerance);

}  // namespace fourbar
