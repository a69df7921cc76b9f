#pragma once
// What a clearance run records: the mode names, the motion at the requested
// sample times, the counted impacts, the per-turn records and the run's
// diagnostics (its energy balance among them). Plain data, filled by
// ClearanceSimulator (simulator.hpp) and read by its callers.

#include <array>
#include <cstddef>

#include "mechanism/kinematics.hpp"
#include "mechanism/vec2.hpp"
#include "sim/record/impact_result.hpp"
#include "sim/record/link_motion.hpp"

namespace fourbar {

enum class ContactMode { free_flight = 0, following = 1 };

/// The motion at one requested sample time.
struct ClearanceSample {
  double time_s = 0;
  CrankState crank;
  ContactMode mode = ContactMode::following;
  LinkMotion links;
  double alpha3_rad_s2 = 0, alpha4_rad_s2 = 0;
  Vec2 bearing_force_N;  ///< force of the bushing on the pin (0 in free flight)
  double crank_torque_Nm = 0;
  double gap_m = 0;      ///< ξ − |e|
  double normal_force_N = 0;  ///< normal contact force (N in following, 0 in free flight; compliant: F_n)
  double penetration_m = 0;   ///< max(0, |e| − ξ): the compliant contact's δ (round-off in the three-mode model)
  double eta_rad = 0;    ///< direction of e (bushing centre → pin)
  double kinetic_energy_J = 0, potential_energy_J = 0;
};

struct ImpactRecord {
  double time_s = 0, crank_angle_rad = 0, eta_rad = 0;
  /// Coupler and rocker angles θ3, θ4 at the impact (the compliant model: at the contact's onset).
  double theta3_rad = 0, theta4_rad = 0;
  int revolution = 0;
  ImpactResult result;  ///< three-mode: the Newton impact itself
  ContactMode mode_after = ContactMode::free_flight;
  /// Three-mode: the plastic impulse that stopped a rebound slower than the
  /// settle speed (0 when the pin flew off). result + settle is the total.
  double settle_normal_impulse_Ns = 0, settle_energy_loss_J = 0, settle_motor_impulse_Nms = 0;
  /// Compliant model: one contact from onset (time_s) to release. result's
  /// normal impulse is that of the first compression–restitution cycle (the
  /// impact); contact_impulse_Ns that of the whole contact; mode_after is
  /// following when the pin stayed on the wall after the first cycle.
  double peak_force_N = 0, contact_duration_s = 0, max_penetration_m = 0, contact_impulse_Ns = 0;
};

struct RevolutionRecord {
  int index = 0;
  double start_time_s = 0, end_time_s = 0;
  int impacts = 0;                  ///< impacts approaching faster than the settle speed
  double sum_normal_impulse_Ns = 0;  ///< ΣF over those impacts
  int contact_losses = 0;
  double following_time_s = 0, free_time_s = 0;
  /// RMS of α3 − α3,nominal over the turn (uniform in crank angle), when
  /// set_revolution_statistics() asked for it; 0 otherwise.
  double alpha3_deviation_rms_rad_s2 = 0;
  double alpha3_deviation_sum_sq = 0;  ///< running Σ(α3 − α3,nom)² of those samples
  int alpha3_deviation_samples = 0;
  /// State at the start of the turn, scaled (δ3, δ4 by ξ/l3; rates by |ω2|·ξ/l3) + mode.
  std::array<double, 4> start_state{};
  ContactMode start_mode = ContactMode::following;
  bool has_start_state = false;
};

struct ClearanceDiagnostics {
  std::size_t steps = 0, impacts = 0, touches = 0, contact_losses = 0, settles = 0;
  std::size_t degenerate_impacts = 0, energy_gaining_impacts = 0;
  std::size_t filtered_steps = 0;       ///< steps cleared of events by their Runge–Kutta stage values alone
  double max_contact_circle_error = 0;  ///< max ||e| − ξ|/ξ in following mode
  double max_contact_normal_speed_m_s = 0;  ///< max |n·ė| in following mode
  double max_penetration = 0;           ///< max (|e| − ξ)/ξ in free flight (0 if never out)
  double crank_work_J = 0;              ///< ∫τ·ω2 dt in the smooth phases
  double motor_impulse_work_J = 0;      ///< Σ ω2·τ̂ at impacts
  double impact_loss_J = 0;             ///< Σ energy dissipated at impacts and settles (compliant: contact damping)
  double friction_loss_J = 0;           ///< dissipated by wall friction in the following mode
  double film_loss_J = 0;               ///< compliant, lubricated: −∫F_film·(v_pin − v_bushing) dt (the film's net dissipation)
  double energy_start_J = 0, energy_end_J = 0;
  double elastic_energy_end_J = 0;      ///< compliant: K·δⁿ⁺¹/(n + 1) stored in the contact at the end
  double energy_residual_J = 0;         ///< ΔE − work + losses (impact and friction) at the end
  double max_energy_residual_J = 0;     ///< largest |residual| seen at any event or the end
  double energy_scale_J = 0;
  double time_following_s = 0, time_free_s = 0;
  std::size_t sticks = 0;               ///< wall friction: times the pin stuck to the bushing
  std::size_t slip_stops = 0;           ///< wall friction: slip speed reached zero while sliding
  double time_stuck_s = 0;              ///< wall friction: time stuck (part of time_following_s)
};

}  // namespace fourbar
