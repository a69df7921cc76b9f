#pragma once
// The three-mode clearance simulator (thesis ch. 6, redone): following mode,
// free flight and impacts, switched by events located on the integrator's
// dense output.
//
// Following mode (ch. 3) is integrated in its one minimal coordinate, the
// clearance-link angle η (ClearanceModel::following): the pin stays on the
// contact circle by construction, so no projection or drift correction is
// needed; the residual |e| − ξ is still measured and reported. Free flight
// (ch. 4) is integrated in the deviations δ3 = θ3 − θ3,nom(t), δ4 = θ4 − θ4,nom(t)
// from the nominal mechanism, which keeps full relative precision in the
// eccentricity (|e| ≤ ξ ≪ link lengths). A quadrature of the crank power τ·ω2
// rides along for the energy balance.
//
// Events, each located by bracketing and TOMS 748 root finding on the dense
// output to within 1e-13 s (never by stepping over and back):
//  * contact loss: N + N_guard crosses zero downward (thesis sec. 3.5: the
//    bearing reaction turning tensile; the magnitude guard N_guard = 1e-9 of
//    the force scale makes the switch robust to round-off — see README);
//    local minima of N between samples are checked with Brent's method;
//  * impact: the penetration |e| − ξ crosses zero upward (eq. 4.4-5); local
//    maxima between samples are checked so grazing double roots are not lost.
// After an impact: free flight when the pin leaves faster than the settle
// speed v_s; otherwise the remaining normal speed is removed by a plastic
// impulse and the following mode continues if its contact force is
// compressive (N > −N_guard), else free flight from rest on the wall. With
// e < 1 every impact multiplies the rebound speed by e, so a chattering
// sequence reaches v_s after finitely many impacts and ends in the following
// mode (Siconos-style velocity- then acceleration-level decision).

#include <memory>
#include <vector>

#include "sim/clearance/crank_motion.hpp"
#include "sim/clearance/impact.hpp"
#include "sim/clearance/integrator.hpp"
#include "sim/clearance/model.hpp"
#include "sim/clearance/settings.hpp"

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
  double eta_rad = 0;    ///< direction of e (bushing centre → pin)
  double kinetic_energy_J = 0, potential_energy_J = 0;
};

struct ImpactRecord {
  double time_s = 0, crank_angle_rad = 0, eta_rad = 0;
  int revolution = 0;
  ImpactResult result;
  ContactMode mode_after = ContactMode::free_flight;
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
  double impact_loss_J = 0;             ///< Σ energy dissipated at impacts and settles
  double friction_loss_J = 0;           ///< dissipated by wall friction in the following mode
  double energy_start_J = 0, energy_end_J = 0;
  double energy_residual_J = 0;         ///< ΔE − work + losses (impact and friction) at the end
  double max_energy_residual_J = 0;     ///< largest |residual| seen at any event or the end
  double energy_scale_J = 0;
  double time_following_s = 0, time_free_s = 0;
  std::size_t sticks = 0;               ///< wall friction: times the pin stuck to the bushing
  std::size_t slip_stops = 0;           ///< wall friction: slip speed reached zero while sliding
  double time_stuck_s = 0;              ///< wall friction: time stuck (part of time_following_s)
};

class ClearanceSimulator {
 public:
  ClearanceSimulator(const ClearanceModel& model, const CrankMotion& crank, const ClearanceSettings& settings);
  ~ClearanceSimulator();

  /// Starts at t0 in the following mode with the clearance link along the
  /// nominal bearing force (thesis sec. 3.4, 6.1), or in free flight when that
  /// force would be tensile.
  void start_nominal(double t0);
  /// Starts in the following mode with a given clearance-link angle and rate.
  void start_following(double t0, double eta_rad, double eta_rate_rad_s);
  /// Starts in free flight from a given link motion (must be inside the bushing).
  void start_free(double t0, const LinkMotion& links);

  /// Times at which samples are wanted (ascending, ≥ the start time); the
  /// samples appear in samples() as the run passes them.
  void set_sample_times(std::vector<double> times);
  /// Revolution boundaries: crank angle where turn 0 starts (turns follow every 2π).
  void set_revolution_origin(double crank_angle_rad);

  /// Per-turn RMS of α3 − α3,nominal from `samples_per_turn` samples per
  /// turn, uniform in crank angle (needs set_revolution_origin; 0 = off).
  void set_revolution_statistics(int samples_per_turn);

  /// Runs until t_end (may be called again with a later time).
  void advance_to(double t_end);

  double time() const;
  ContactMode mode() const;
  /// Link motion at the current time.
  LinkMotion current_links();

  const std::vector<ClearanceSample>& samples() const;
  const std::vector<ImpactRecord>& impacts() const;
  const std::vector<RevolutionRecord>& revolutions() const;
  /// Diagnostics up to now (energy terms evaluated at the current time).
  ClearanceDiagnostics diagnostics();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fourbar
