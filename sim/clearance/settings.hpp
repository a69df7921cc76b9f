#pragma once
// The scene's `[clearance]` table: how the three-mode clearance model runs.
// Read and validated once at the boundary (scene loading); immutable after.

#include <optional>

#include "common/toml_section.hpp"

namespace fourbar {

/// Tangential behaviour at an impact (thesis sec. 5.3).
enum class ContactLaw {
  smooth,     ///< no friction: tangential impulse 0 (thesis 5.3.1)
  rough,      ///< no slip: tangential relative velocity 0 after impact (thesis 5.3.2)
  stick_slip  ///< Coulomb μ: stick when |f| ≤ μF, else slide with f = μF against the slip (thesis 5.3.3)
};

/// Which integrator library advances the smooth phases.
enum class IntegratorKind {
  cvode,  ///< SUNDIALS CVODE, variable-order Adams–Moulton (orders 1–12)
  odeint  ///< Boost.Odeint, Dormand–Prince 5(4) with dense output
};

const char* to_string(ContactLaw c);
const char* to_string(IntegratorKind k);

struct ClearanceSettings {
  std::optional<double> radial_clearance_m;  ///< overrides the rig's [clearance] radial_mm
  double restitution = 1.0;                  ///< Newton coefficient e in [0, 1]
  ContactLaw contact = ContactLaw::smooth;
  double friction_coefficient = 0.0;         ///< Coulomb μ (stick-slip only)
  /// μ also acts in the following mode: the pin slides on the bushing wall
  /// against Coulomb friction, or sticks (extension; the thesis's following
  /// mode is frictionless). Needs contact = stick-slip.
  bool following_friction = false;
  double tolerance = 1e-10;                  ///< relative integration tolerance
  IntegratorKind integrator = IntegratorKind::odeint;  // measured 2–3× faster here (bench_clearance)
  /// Normal speeds below this count as resting contact: a rebound slower than
  /// this ends a chattering sequence in the following mode (the Zeno rule).
  double settle_speed_m_s = 1e-6;
  /// Which steady state ends the search (README "Clearance model").
  enum class SteadyCriterion { periodic, statistical, either };
  bool steady_state = false;     ///< run until the motion is steady (see steady_criterion)
  SteadyCriterion steady_criterion = SteadyCriterion::either;
  int statistical_window = 20;          ///< W: turns per window of the statistical criterion
  double statistical_tolerance = 0.05;  ///< relative agreement of the two windows' means
  int max_revolutions = 200;     ///< bound on the turns simulated to reach steady state
  double steady_tolerance = 1e-6;  ///< state repeat tolerance (scaled state, see README)
  int max_period = 8;            ///< longest period (in turns) looked for
  /// Sample every following-mode step at kScanPoints points for events even
  /// when its Runge–Kutta stage values already clear it (tests and benches
  /// compare the two; not a scene key).
  bool full_event_scan = false;
  bool write_impacts = false;       ///< impacts.csv
  bool write_revolutions = false;   ///< revolutions.csv
};

/// Reads `[clearance]` from a scene. `rig_clearance_m` is the rig's value,
/// used when the scene does not override it; the final clearance must be > 0.
ClearanceSettings read_clearance_settings(TomlSection& section, double rig_clearance_m);

const char* to_string(ClearanceSettings::SteadyCriterion c);

}  // namespace fourbar
