#pragma once
// SUNDIALS CVODE in its stiff mode — BDF orders 1–5, Newton iteration with a
// dense direct linear solver (or, for comparison, Adams–Moulton) — for the compliant contact model, whose contact
// phases are stiff (a Hertz spring of 1e10 N/m^1.5 with hysteresis damping
// on a 0.05 kg effective mass). One step at a time with dense output, and
// CVODE's root finding on one witness (the penetration) so that contact
// onset and release end a step exactly there.
//
// The Jacobian is a difference quotient over the first `coupled` state
// components only: the rest are quadratures (work, dissipation, impulse)
// that no right-hand side depends on, so their columns are zero and are not
// differenced (4 right-hand-side calls per Jacobian instead of 10).

#include <array>
#include <cstddef>
#include <memory>

#include "sim/integrate/integrator_options.hpp"

namespace fourbar {

inline constexpr std::size_t kStiffSize = 10;
using StiffState = std::array<double, kStiffSize>;

class RadauIntegrator;

class StiffSystem {
 public:
  virtual ~StiffSystem() = default;
  virtual void rhs(double t, const StiffState& y, StiffState& dydt) = 0;
  /// The root witness: its zeros end a step.
  virtual double witness(double t, const StiffState& y) = 0;
};

class StiffIntegrator {
 public:
  /// `tolerance` relative and absolute on the scaled state; the Jacobian
  /// differences the first `coupled` components.
  /// `size` ≤ kStiffSize: the components integrated (the rest read as 0).
  /// `method`: BDF (the default), one of the Adams modes or Radau IIA (settings.hpp).
  StiffIntegrator(double tolerance, std::size_t coupled, std::size_t size = kStiffSize,
                  StiffMethod method = StiffMethod::bdf);
  ~StiffIntegrator();
  StiffIntegrator(const StiffIntegrator&) = delete;
  StiffIntegrator& operator=(const StiffIntegrator&) = delete;

  /// (Re)starts at (t0, y0): order 1, history dropped.
  void reset(StiffSystem& system, double t0, const StiffState& y0);

  struct Step {
    double start = 0, end = 0;  ///< interpolate() is valid on [start, end]
    int root = 0;               ///< +1 / −1: the witness crossed zero upward / downward at `end`
  };
  /// One step, never past `t_stop`; ends early at a root of the witness.
  Step step(double t_stop);
  void interpolate(double t, StiffState& y);

  std::size_t steps() const { return steps_; }
  /// CVODE's counters since construction (summed over restarts) (for benches): right-hand sides,
  /// Jacobians, error-test and Newton convergence failures.
  struct Counters {
    long rhs = 0, jacobians = 0, error_failures = 0, newton_failures = 0;
  };
  Counters counters() const;

 private:
  Counters since_reset() const;
  Counters before_reset_;

 public:
  StiffSystem& system() { return *system_; }
  std::size_t coupled() const { return coupled_; }
  std::size_t size() const { return size_; }

 private:
  struct Cvode;
  std::unique_ptr<Cvode> cv_;
  std::unique_ptr<RadauIntegrator> radau_;  ///< StiffMethod::radau5 (radau_integrator.hpp), else null
  StiffSystem* system_ = nullptr;
  std::size_t coupled_;
  std::size_t size_;
  std::size_t steps_ = 0;
  double t_ = 0;
  bool stepped_ = false;
  StiffState y0_{};
  StiffState y_end_{};  ///< the state at t_ (the last step's end)
};

}  // namespace fourbar
