#pragma once
// Private to the compliant simulator (included only by its .cpp files): the
// per-run state of CompliantSimulator::Impl and the declarations of its
// stages:
//   compliant_equations.cpp  the contact at one state, the ODE, state conversion
//   compliant_books.cpp      contacts, revolutions, statistics, samples, energy
//   compliant_simulator.cpp  starts, the main loop, the public API

#include <array>
#include <cstddef>
#include <vector>

#include "mechanism/kinematics.hpp"
#include "sim/compliant/compliant_simulator.hpp"
#include "sim/contact/contact_force.hpp"
#include "sim/three_mode/deviation_state.hpp"
#include "sim/integrate/stiff_integrator.hpp"
#include "sim/record/local_clock.hpp"
#include "sim/record/run_books.hpp"

namespace fourbar {

/// Components of the integrated state: 0–3 the scaled deviations
/// (deviation_state.hpp); then the quadratures, scaled by the energy scale E
/// or by the force scale F_s over |ω2|.
enum StiffComponent : std::size_t {
  kWork = 4,          ///< crank work W/E
  kContactLoss = 5,   ///< contact damping dissipation D_c/E
  kFrictionLoss = 6,  ///< friction dissipation D_f/E
  kImpulseN = 7,      ///< ∫F_n dt·|ω2|/F_s since the contact's onset
  kImpulseT = 8,      ///< ∫F_t dt·|ω2|/F_s since the contact's onset
  kFilmLoss = 9       ///< work of the lubricant film's force, W_f/E (0 dry)
};
/// State components the right-hand side depends on (differenced in the Jacobian).
inline constexpr std::size_t kCoupled = 4;
/// A segment longer than this many turns restarts at a new time origin.
inline constexpr double kCompliantRestartTurns = 64;

/// Everything of the contact at one instant.
struct ContactState {
  NominalMotion nominal;
  LinkMotion links;
  BearingState bearing;
  double penetration_m = 0;  ///< |e| − ξ (< 0: a gap)
  double normal_force_N = 0, friction_force_N = 0;
  FilmForce film;            ///< the lubricant film's force on the pin along n and t (film_force.hpp)
  Vec2 pin_force_N;          ///< (F_film,r − F_n)·n + (F_t + F_film,t)·t
  double alpha3_rad_s2 = 0, alpha4_rad_s2 = 0, crank_torque_Nm = 0;
};

struct CompliantSimulator::Impl final : StiffSystem {
  Impl(const ClearanceModel& m, const CrankMotion& c, const ClearanceSettings& s);

  const ClearanceModel& model;
  const CrankMotion& crank;
  ClearanceSettings settings;
  NormalForceLaw law;
  FrictionLaw friction;
  JournalFilm film;  ///< viscosity 0: a dry bearing
  double hysteresis = 0;  ///< c(e)
  StiffIntegrator integ;

  struct Scales {
    DeviationScales deviation;
    double energy_J = 1;
    double force_N = 1;  ///< F_s
  } scale;

  /// Local time: absolute = origin + local (moved at every restart).
  LocalClock clock;
  double t = 0;          ///< current local time
  double seg_start = 0;  ///< local start of the current integration segment
  double start_abs_s = 0;  ///< absolute start time of the run
  CrankState crank_at(double time) const { return clock.crank_at(crank, time); }
  /// The nominal motion at the last few (origin, local time) pairs: a step's
  /// Newton iterations, Jacobian columns and root function share one time,
  /// and the nominal kinematics is most of a right-hand side's cost.
  struct NominalCache {
    struct Entry {
      double origin_s = 0, time = 0;
      bool valid = false;
      NominalMotion motion;
    };
    std::array<Entry, 4> entries;
    std::size_t next = 0;
  };
  mutable NominalCache nominal_cache;
  const NominalMotion& nominal_at(double time) const;
  double absolute(double time) const { return clock.absolute(time); }
  double local(double absolute_time) const { return clock.local(absolute_time); }

  /// The open contact (onset to release).
  struct Episode {
    bool active = false;
    /// 0 compression (δ̇ > 0), 1 restitution, 2 past the first cycle: δ̇
    /// turned positive again without a release, so the pin stays on the wall
    /// (the compliant form of the following mode; its release is a contact loss).
    int phase = 0;
    double impact_impulse_Ns = 0;  ///< ∫F_n dt over the first cycle (onset to release or phase 2)
    double chi_s_per_m = 0;   ///< χ = c(e)/max(v⁻, floor)
    double onset_abs_s = 0;
    double loss_at_onset = 0;  ///< (D_c + D_f)/E at onset
    ImpactRecord rec;
  } ep;

  /// Samples, contacts (books.impacts), revolutions, diagnostics.
  RunBooks books;

  // ---- equations (compliant_equations.cpp) ----
  ContactState evaluate(double time, const StiffState& y) const;
  /// The part of evaluate() up to the contact forces (nominal motion, links,
  /// bearing, penetration, normal and friction force): no film, no
  /// accelerations, no crank torque. For the contact's books.
  ContactState evaluate_contact(double time, const StiffState& y) const;
  void rhs(double time, const StiffState& y, StiffState& dy) override;
  double witness(double time, const StiffState& y) override;
  /// The state of a link motion at `time`, quadratures taken from `q`.
  StiffState state_of(double time, const LinkMotion& m, const StiffState& q) const;
  StiffState state_at(double time);
  double mechanical_energy_J(double time, const LinkMotion& m) const;
  /// Mechanical energy plus the contact's elastic energy.
  double total_energy_J(const ContactState& k, double time) const;

  // ---- books (compliant_books.cpp) ----
  int revolution_of(double time) const;
  double revolution_start(int k) const;
  RevolutionRecord& revolution(int k);
  void book_interval(double ta, double tb);
  void record_start_state(RevolutionRecord& r);
  double stat_time(long long i) const;
  void emit_statistics(double up_to);
  void emit_samples(double up_to);
  ClearanceSample sample(double absolute_time);
  /// Peak force and penetration of the open contact over [ta, tb], and the
  /// end of its first compression–restitution cycle (located on the dense output).
  void track_contact(double ta, double tb);
  void onset(double time, StiffState& y);
  void release(double time, const StiffState& y);
  void check_energy(double time, const StiffState& y);

  // ---- the run (compliant_simulator.cpp) ----
  void prepare(double t0);
  /// Restarts the integrator at local `time` with state y (origin moved there).
  void restart(double time, const StiffState& y);
  void begin(const LinkMotion& links, double approach_speed_m_s);
  void advance_to(double absolute_end);
};

}  // namespace fourbar
