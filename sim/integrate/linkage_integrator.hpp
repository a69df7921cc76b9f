#pragma once
// SUNDIALS CVODE BDF (Newton, dense direct solver) for the linkage model: the
// stiff integrator the compliant model uses (sim/integrate/stiff_integrator.hpp),
// with the problem size set at reset instead of at compile time and several
// witnesses at once (one per clearance joint), each root reported with its
// direction (SIM-DESIGN-NOTES §3.1, §5 OdeProblem). As there, the Jacobian
// differences only the first `coupled` components: the rest are quadratures
// (work, dissipation, impulses) that no right-hand side reads.

#include <cstddef>
#include <exception>
#include <memory>
#include <vector>

namespace fourbar {

class LinkageOde {
 public:
  virtual ~LinkageOde() = default;
  virtual void rhs(double t, const double* y, double* dydt) = 0;
  /// The witnesses g[0..roots) at (t, y): a zero ends a step.
  virtual void witnesses(double t, const double* y, double* g) = 0;
};

/// The stepping method: CVODE's variable-order BDF (1–5), or ARKODE's ARKStep
/// with an L-stable ESDIRK table (order 4: ESDIRK436L2SA_6_3_4, order 5:
/// ESDIRK547L2SA2_7_4_5; Newton with the same dense Jacobian) or an explicit
/// Verner 8-5-6 (order 6, no Jacobian), or CVODE's variable-order Adams–Moulton
/// (1–12) with the same Newton iteration and linear solver as BDF.
enum class LinkageMethod { bdf, esdirk4, esdirk5, erk, adams };

class LinkageIntegrator {
 public:
  /// Relative and absolute `tolerance` on the scaled state (absolute a
  /// hundredth of it on the books after the first `coupled`, see the .cpp);
  /// `size` components, the first `coupled` differenced for the Jacobian;
  /// `roots` witnesses.
  LinkageIntegrator(double tolerance, std::size_t size, std::size_t coupled, std::size_t roots,
                    LinkageMethod method = LinkageMethod::bdf);
  ~LinkageIntegrator();
  LinkageIntegrator(const LinkageIntegrator&) = delete;
  LinkageIntegrator& operator=(const LinkageIntegrator&) = delete;

  /// (Re)starts at (t0, y0): order 1, history dropped.
  void reset(LinkageOde& ode, double t0, const std::vector<double>& y0);

  struct Step {
    double start = 0, end = 0;  ///< interpolate() is valid on [start, end]
    /// Per witness: +1 / −1 it crossed zero upward / downward at `end`, else 0.
    std::vector<int> roots;
    bool any_root = false;
  };
  /// One step, never past `t_stop`; ends early at a root of any witness.
  Step step(double t_stop);
  void interpolate(double t, std::vector<double>& y);

  std::size_t size() const { return size_; }
  std::size_t coupled() const { return coupled_; }
  std::size_t steps() const { return steps_; }
  LinkageOde& ode() { return *ode_; }
  /// Right-hand sides, Jacobians, error-test and Newton failures since construction.
  struct Counters {
    long rhs = 0, jacobians = 0, error_failures = 0, newton_failures = 0;
  };
  Counters counters() const;
  /// The last step's size and order (0 for ARKODE's fixed tables) and the
  /// component whose weighted local-error estimate |e_i|·w_i was the
  /// largest: the one that set the step (bench/elastic_linkage_work_precision --steps).
  struct StepReport {
    double step_s = 0, weighted_error = 0;
    int order = 0;
    std::size_t limiting = 0;
  };
  StepReport last_step_report();

 private:
  Counters since_reset() const;
  void reset_arkode(double t0);
  struct Cvode;
  std::unique_ptr<Cvode> cv_;
  LinkageOde* ode_ = nullptr;
  std::size_t size_, coupled_, roots_;
  std::size_t steps_ = 0;
  double t_ = 0;
  bool stepped_ = false;
  std::vector<double> y0_, y_end_;
  Counters before_reset_;

 public:
  std::vector<double> scratch0, scratch1, scratch2;  ///< Jacobian work vectors (used by the CVODE callbacks)
  /// An exception thrown by the problem inside a CVODE callback: the callback
  /// returns CVODE's "unrecoverable" code and step() rethrows it here, so no
  /// C++ exception unwinds through CVODE's C frames.
  std::exception_ptr pending;
};

}  // namespace fourbar
