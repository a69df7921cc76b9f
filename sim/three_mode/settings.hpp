#pragma once
// The scene's `[clearance]` table: which clearance model (three-mode or
// compliant) and how it runs. Read and validated once at the boundary (scene
// loading); immutable after.

#include <optional>

#include "common/toml_section.hpp"
#include "sim/contact/contact_force.hpp"
#include "sim/contact/film_force.hpp"
#include "sim/integrate/integrator_options.hpp"

namespace fourbar {

/// Tangential behaviour at an impact (thesis sec. 5.3).
enum class ContactLaw {
  smooth,     ///< no friction: tangential impulse 0 (thesis 5.3.1)
  rough,      ///< no slip: tangential relative velocity 0 after impact (thesis 5.3.2)
  stick_slip  ///< Coulomb μ: stick when |f| ≤ μF, else slide with f = μF against the slip (thesis 5.3.3)
};

/// Which clearance model: the thesis's three modes with instantaneous
/// impacts, or a continuous (compliant) contact force.
enum class ClearanceKind { three_mode, compliant };

const char* to_string(ContactLaw c);
const char* to_string(ClearanceKind k);

/// The compliant model's contact (model = "compliant"; docs/clearance-model.md "Compliant contact").
struct CompliantSettings {
  DampingLaw damping = DampingLaw::calibrated;
  /// K in N/mⁿ: given (contact_stiffness_N_per_m_n) or computed from the
  /// rig's bearing (contact_stiffness.hpp) when the scene is loaded.
  double stiffness_N_per_m_n = 0;
  bool stiffness_given = false;
  double exponent = 1.5;                    ///< n
  double friction_stick_speed_m_s = 1e-4;   ///< v0 of the friction law
  double friction_slip_speed_m_s = 1e-3;    ///< v1 of the friction law
  /// Approach speeds below this use it in χ = c(e)/v⁻ (a contact that begins
  /// at rest, e.g. the start on the wall, would otherwise get infinite damping).
  double damping_floor_speed_m_s = 1e-5;
  /// The lubricated bearing (docs/compliant.md "Lubricated bearing"): the
  /// short-bearing film force while ε < ε_t, the dry contact at the wall.
  /// viscosity_Pa_s from the scene (viscosity_given) or the rig's
  /// lubricant_viscosity_Pa_s; radius, length and clearance resolved from the
  /// rig when the scene is loaded. viscosity_Pa_s = 0: a dry bearing.
  JournalFilm film;
  StiffMethod method = StiffMethod::bdf;  ///< benches only (no scene key)
  bool viscosity_given = false;
  bool film_keys_given = false;  ///< film or film_break_eccentricity given (need a lubricant)
};

struct ClearanceSettings {
  ClearanceKind model = ClearanceKind::three_mode;
  CompliantSettings compliant;               ///< model = compliant only
  std::optional<double> radial_clearance_m;  ///< overrides the rig's [clearance] radial_mm
  double restitution = 1.0;                  ///< Newton coefficient e in [0, 1]
  ContactLaw contact = ContactLaw::smooth;
  double friction_coefficient = 0.0;         ///< Coulomb μ (stick-slip, or the compliant model's wall friction)
  /// μ also acts in the following mode: the pin slides on the bushing wall
  /// against Coulomb friction, or sticks (extension; the thesis's following
  /// mode is frictionless). Needs contact = stick-slip.
  bool following_friction = false;
  double tolerance = 1e-10;                  ///< relative integration tolerance
  IntegratorKind integrator = IntegratorKind::odeint;  // measured 2–3× faster here (bench_clearance)
  /// Normal speeds below this count as resting contact: a rebound slower than
  /// this ends a chattering sequence in the following mode (the Zeno rule).
  double settle_speed_m_s = 1e-6;
  /// Which steady state ends the search (docs/clearance-model.md).
  enum class SteadyCriterion { periodic, statistical, either };
  bool steady_state = false;     ///< run until the motion is steady (see steady_criterion)
  SteadyCriterion steady_criterion = SteadyCriterion::either;
  int statistical_window = 20;          ///< W: turns per window of the statistical criterion
  double statistical_tolerance = 0.05;  ///< relative agreement of the two windows' means
  int max_revolutions = 200;     ///< bound on the turns simulated to reach steady state
  double steady_tolerance = 1e-6;  ///< state repeat tolerance (scaled state, see docs/clearance-model.md)
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
/// The compliant model's stiffness is left 0 unless given: the scene resolves
/// it from the rig (resolve_contact_stiffness, contact_stiffness.hpp).
ClearanceSettings read_clearance_settings(TomlSection& section, double rig_clearance_m);

/// The compliant model's own keys of `[clearance]` (compliant_settings.cpp).
void read_compliant_settings(TomlSection& section, ClearanceSettings& settings);

const char* to_string(ClearanceSettings::SteadyCriterion c);

}  // namespace fourbar
