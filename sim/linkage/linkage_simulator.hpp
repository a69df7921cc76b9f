#pragma once
// The linkage model's run: the scaled deviation state (as the compliant
// model's deviation_state.hpp: coordinates about the nominal mechanism, the
// angles scaled by ξ/l3, each joint offset by its own ξ, rates by |ω2| too),
// quadratures of the motor work and, per clearance joint, of its contact
// damping, friction and film dissipation and its impulses; CVODE BDF with
// one witness per clearance joint (the penetration over ξ). At a root the
// contact of that joint begins (its damping χ = c(e)/v⁻ fixed by the approach
// speed) or ends (recorded), and the integrator restarts. The state layout
// with clearance at the coupler–rocker joint only is the compliant model's,
// component for component.

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "sim/drive/crank_motion.hpp"
#include "sim/linkage/linkage_model.hpp"
#include "sim/linkage/linkage_sample.hpp"
#include "sim/linkage/linkage_sensor.hpp"

namespace fourbar {

/// A start: link directions and rates, and per joint the pin's offset and
/// its rate (used for the joints that place a body; the cut joint's
/// eccentricity follows from the rest), and the modal coordinates η and
/// rates of the coupler [0] and rocker [1] (start() refuses a non-zero or
/// non-finite entry on a rigid link or past its modes). An all-ideal linkage
/// takes u3, u4 and the rates from the nominal motion whatever is given.
struct LinkageStart {
  Vec2 u3, u4;
  double omega3_rad_s = 0, omega4_rad_s = 0;
  std::array<Vec2, kJoints> eccentricity_m{}, eccentricity_rate_m_s{};
  std::array<std::array<double, 4>, 2> modal_m{}, modal_rate_m_s{};
};

/// One contact of one joint, onset to release.
struct LinkageContact {
  int joint = 0;
  double time_s = 0, crank_angle_rad = 0, eta_rad = 0;
  double approach_speed_m_s = 0, tangential_speed_m_s = 0;  ///< at the onset
  bool impact = false;         ///< approach faster than the settle speed
  bool contact_lost = false;   ///< the pin stayed on the wall past its first cycle: its release is a contact loss
  double release_time_s = 0, release_crank_angle_rad = 0, release_eta_rad = 0;
  double duration_s = 0, peak_force_N = 0, max_penetration_m = 0;
  double impact_impulse_Ns = 0, contact_impulse_Ns = 0, energy_loss_J = 0;
};

struct LinkageJointBooks {
  double free_time_s = 0, contact_time_s = 0, max_penetration_m = 0;
  int impacts = 0, touches = 0, contact_losses = 0;
  double contact_loss_J = 0, friction_loss_J = 0, film_loss_J = 0;  ///< dissipated so far
};

struct LinkageDiagnostics {
  std::array<LinkageJointBooks, kJoints> joint{};
  double crank_work_J = 0, energy_start_J = 0, energy_end_J = 0, dissipated_J = 0;
  double modal_damping_loss_J = 0;  ///< elastic links' 2ζωM damping (part of dissipated_J)
  double energy_residual_J = 0, max_energy_residual_J = 0, energy_scale_J = 1;
  std::size_t steps = 0;
};

/// One integrator step of a step trace: where it ended, its size and order,
/// and the state component that set it (LinkageSimulator::state_component).
struct LinkageStepTrace {
  double end_time_s = 0, step_s = 0, weighted_error = 0;
  int order = 0;
  std::size_t limiting = 0;
};

class LinkageSimulator {
 public:
  LinkageSimulator(const LinkageModel& model, const CrankMotion& crank);
  ~LinkageSimulator();

  void start(double t0, const LinkageStart& s);
  /// The nominal links at t0 with every pin centred and moving with its bushing.
  void start_centred(double t0);
  void set_sample_times(std::vector<double> times);
  /// Accelerometers whose tangential reading each sample records.
  void set_sensors(std::vector<LinkSensor> sensors);
  void advance_to(double t_end);

  double time() const;
  const std::vector<LinkageSample>& samples() const;
  /// Every contact released so far.
  const std::vector<LinkageContact>& contacts() const;
  LinkageDiagnostics diagnostics();
  std::string integrator_counters() const;
  /// Appends a record of every following step to `out` (nullptr stops);
  /// costs two error-vector reads a step, for benchmarks and diagnosis.
  void trace_steps(std::vector<LinkageStepTrace>* out);
  /// The integrator's state component i by name: "theta3", "coupler eta2",
  /// "crank_coupler d_x" and the same with " rate"; "books" past them.
  std::string state_component(std::size_t i) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fourbar
