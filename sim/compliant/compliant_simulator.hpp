#pragma once
// The compliant (continuous-force) clearance simulator: the pin flies freely
// inside the clearance circle; with penetration δ = |e| − ξ > 0 the bushing
// pushes it back with the normal force F_n(δ, δ̇) of contact_force.hpp along
// the line of centres, plus the regularised Coulomb friction along the wall.
// One smooth ODE for the whole run — the free-flight deviations δ3, δ4 from
// the nominal mechanism and their rates (deviation_state.hpp), with the crank
// work, the contact and friction dissipation and the contact's impulses as
// quadratures — integrated by CVODE BDF with a dense Jacobian
// (stiff_integrator.hpp). CVODE's root finding on δ = 0 ends a step at every
// contact onset and release: at onset the approach speed v⁻ fixes the
// damping χ = c(e)/v⁻ of that contact and the integrator restarts; at release
// the contact is recorded (peak force, duration, impulse, loss).
//
// Every contact begins with an impact (n and ΣF of the turn it began in, with
// the impulse of its first compression–restitution cycle). A contact whose
// penetration rate turns positive again without a release has settled on the
// wall — the compliant form of the following mode — and its release is a
// contact loss. The same interface and records as ClearanceSimulator
// (simulator.hpp): both are ClearanceSimulations (sim/record/clearance_simulation.hpp).

#include <memory>
#include <string>
#include <vector>

#include "sim/drive/crank_motion.hpp"
#include "sim/three_mode/model.hpp"
#include "sim/record/clearance_simulation.hpp"
#include "sim/record/run_records.hpp"
#include "sim/three_mode/settings.hpp"

namespace fourbar {

class CompliantSimulator final : public ClearanceSimulation {
 public:
  /// `settings.compliant.stiffness_N_per_m_n` must be resolved (> 0).
  CompliantSimulator(const ClearanceModel& model, const CrankMotion& crank, const ClearanceSettings& settings);
  ~CompliantSimulator() override;

  /// Starts at t0 with the pin pressed into the wall along the nominal
  /// bearing force, at the static penetration (|F|/K)^(1/n) and the nominal
  /// force direction's rate (free flight when the nominal force is zero).
  void start_nominal(double t0) override;
  /// Starts from a given link motion (any eccentricity; in contact when |e| > ξ,
  /// with the damping of an approach at the floor speed).
  void start_free(double t0, const LinkMotion& links) override;

  void set_sample_times(std::vector<double> times) override;
  void set_revolution_origin(double crank_angle_rad) override;
  void set_revolution_statistics(int samples_per_turn) override;
  void advance_to(double t_end) override;

  double time() const override;
  /// following while in contact (δ > 0), else free_flight.
  ContactMode mode() const override;
  LinkMotion current_links() override;

  const std::vector<ClearanceSample>& samples() const override;
  /// Every contact released so far (impacts and following phases; a contact
  /// still open at the end is not listed).
  const std::vector<ImpactRecord>& impacts() const override;
  const std::vector<RevolutionRecord>& revolutions() const override;
  ClearanceDiagnostics diagnostics() override;
  /// The BDF integrator's counters: "rhs N, jacobians N, error-test failures N, Newton failures N".
  std::string integrator_counters() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fourbar
