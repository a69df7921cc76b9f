#pragma once
// Private to the clearance simulator (included only by its .cpp files): the
// per-run state of ClearanceSimulator::Impl and the declarations of its
// stages. Each stage is defined in the file that owns its concept:
//   mode_equations.cpp       state conversion and the two ODE systems
//   event_scan.cpp           event witnesses and the per-step scans
//   contact_transitions.cpp  segment starts, impacts, settles, stick/slip
//   run_books.cpp            revolutions, statistics, samples, monitors, energy
//   simulator.cpp            prepare, the main loop, the public API

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "common/statistics.hpp"
#include "sim/record/local_clock.hpp"
#include "sim/record/run_books.hpp"
#include "sim/three_mode/simulator.hpp"

namespace fourbar {

/// Subintervals per integrator step at which the event witnesses are sampled.
constexpr int kScanPoints = 4;
/// Events closer together than this, many times in a row, mean the run is stuck.
constexpr double kZenoSpan_s = 1e-12;
constexpr int kZenoLimit = 100000;
/// A smooth segment longer than this many crank turns is restarted at a new
/// time origin, so its local time (and local crank angle) stays small.
constexpr double kRestartTurns = 64;

// Guards and tolerances, each relative to the run's own scales (set in prepare()).
/// N_guard as a fraction of the force scale: the contact-loss witness is
/// N + N_guard, so round-off in N near zero cannot flip the mode (see docs/clearance-model.md).
constexpr double kForceGuardFraction = 1e-9;
/// Arm depth as a fraction of ξ: a free flight from the wall counts as
/// "inside" only below this penetration, well above round-off in |e| − ξ.
constexpr double kArmDepthFraction = 1e-11;
/// Slip arm speed in units of ξ·|ω2|: slower slip counts as none (choose_slip
/// then tests sticking), and after a start from rest the slip witness waits for it.
constexpr double kSlipArmSpeedFraction = 1e-9;
/// An impact "gains energy" only past this fraction of the energy scale
/// (below it the balance is round-off).
constexpr double kEnergyGainFraction = 1e-15;
/// Stands for "none yet": the first stage value's min/max bounds and the
/// time of the last event before any; finite, so differences stay finite.
constexpr double kNoneYet = 1e300;
/// Crank angle step of the central difference for the starting η̇ (start_nominal).
constexpr double kRateDifferenceStep_rad = 1e-4;

struct ClearanceSimulator::Impl {
  Impl(const ClearanceModel& m, const CrankMotion& c, const ClearanceSettings& s)
      : model(m), crank(c), settings(s), integ(make_integrator(s.integrator, s.tolerance)) {}

  const ClearanceModel& model;
  const CrankMotion& crank;
  ClearanceSettings settings;
  std::unique_ptr<DenseIntegrator> integ;
  ImpactLaw law{settings.restitution, settings.contact, settings.friction_coefficient};

  // The fields are grouped by the stage that fills them (as MuJoCo's mjData
  // groups its fields by stage).

  /// Scales of the integrated (scaled) state; set once by prepare().
  struct Scales {
    double speed_rad_s = 1;    // |ω2| at the start
    double delta = 1;          // ξ/l3
    double energy_J = 1;
    double force_guard_N = 0;  // N_guard
    double arm_depth_m = 0;    // penetration below which a free flight from the wall counts as "inside"
  } scale;

  // Time is measured locally: the absolute time is origin + t, where the
  // origin moves to each segment's start (long runs keep the resolution of
  // the local time; see crank_motion.hpp). Every time inside Impl is local
  // unless named absolute.
  LocalClock clock;
  CrankState crank_at(double time) const { return clock.crank_at(crank, time); }
  double absolute(double time) const { return clock.absolute(time); }
  double local(double absolute_time) const { return clock.local(absolute_time); }
  /// LocalClock::rebase, with the Zeno guard's last event moved along.
  double rebase(double time);

  /// The current smooth segment; set by the segment starts, advanced by the main loop.
  struct Segment {
    double t = 0;  // the current (local) time
    ContactMode mode = ContactMode::following;
    bool armed = true;  // free flight: the pin has left the wall since the segment start
    double start = 0;   // start time of the current smooth segment
  } seg;

  /// Events closer than kZenoSpan_s in a row (zeno_guard); last_event is a local time, moved by rebase().
  struct ZenoBook {
    int count = 0;
    double last_event = -kNoneYet;
  } zeno;

  // Witness samples carried across steps of one segment (event_scan.cpp).
  struct FreeSample { double t, pen, speed; };
  struct FollowSample { double t, w, slip; };
  struct Witnesses {
    bool stage_filter = false;  // the integrator's right-hand-side calls lie inside its steps
    FreeSample free_prev{};
    std::vector<FollowSample> follow_hist;
  } witness;

  /// What the run records as it passes sample times, events and turn boundaries.
  RunBooks books;

  /// The energy balance's integrals over closed segments and at impacts.
  struct EnergyBooks {
    CompensatedSum work_closed;  // crank work of the closed smooth segments
    // The work component starts each segment at the closed work (scaled), so
    // the integrator's error control on it is as before; the segment's part is
    // y − work_seed, booked into work_closed at the segment's end. (Starting it
    // at 0 tightened that control and moved the chaotic event paths: the
    // wall-friction energy test then missed its bound with CVODE.)
    double work_seed = 0;
    CompensatedSum work_impulse, loss;
    CompensatedSum friction_loss;  // dissipated by wall friction in closed following segments
  } energy_books;

  // Following-mode wall friction (settings.following_friction): μ and the
  // sliding direction (+1/−1) or 0 while stuck; the slip witness is armed
  // once the pin slides faster than slip_arm_speed_m_s after a start from rest.
  struct WallSlip {
    WallFriction friction;
    bool slip_armed = true;
    double slip_arm_speed_m_s = 0;
    double slip_force_per_speed = 0;  // N per m/s: slip speed in the witness's force units
  } wall;

  // ---- state conversion (mode_equations.cpp) ---------------------------

  LinkMotion free_links(double time, const OdeState& y, NominalMotion* nominal_out = nullptr) const;
  OdeState free_state(double time, const LinkMotion& m) const;

  // Following: y = (η, η̇/|ω2|, W/E, D/E, 0) with W the crank work (from
  // work_seed) and D the wall-friction loss of the segment (from 0).
  double eta_of(const OdeState& y) const { return y[0]; }
  double eta_rate_of(const OdeState& y) const { return y[1] * scale.speed_rad_s; }
  double segment_work(const OdeState& y) const;
  double segment_friction(const OdeState& y) const;
  /// Crank work up to now: closed segments plus the open one.
  double work_of(const OdeState& y) const;
  /// Friction loss up to now: closed segments plus the open following one.
  double friction_of(const OdeState& y) const;
  /// Books the open segment's integrals before a new segment starts.
  void close_segment(const OdeState& y);

  LinkMotion links_at(double time, const OdeState& y) const;
  /// The following-mode coordinates of a link motion on the contact circle.
  void to_following(double time, const LinkMotion& m, double& eta, double& eta_rate) const;

  // ---- the two ODE systems (mode_equations.cpp) --------------------------

  struct FollowingOde final : OdeSystem {
    Impl* s;
    /// Range of N + N_guard over the right-hand-side calls since the last
    /// clear(): with a Runge–Kutta integrator these are its stage values
    /// inside the step (and inside rejected, longer trial steps).
    double w_min = 0, w_max = 0;
    void clear() { w_min = kNoneYet, w_max = -kNoneYet; }
    void rhs(double time, const OdeState& y, OdeState& dy) override;
  } following_ode;

  struct FreeOde final : OdeSystem {
    Impl* s;
    /// Largest and smallest penetration |e| − ξ over the right-hand-side
    /// calls since the last clear() (see FollowingOde::w_min).
    double pen_min = 0, pen_max = 0;
    void clear() { pen_min = kNoneYet, pen_max = -kNoneYet; }
    void rhs(double time, const OdeState& y, OdeState& dy) override;
  } free_ode;

  // ---- witnesses and scans (event_scan.cpp) -------------------------------

  /// The following mode's event witness (N): N + N_guard, and with wall
  /// friction also the slip speed times its sliding direction (sliding) or
  /// μ·N − |f| (stuck), whichever is smaller.
  double follow_value(const FollowingMotion& f) const;
  FreeSample free_witness(double time);
  /// N + N_guard at `time`; with `check_drift` also the contact-circle
  /// error (done once per step: it is round-off by construction).
  FollowSample follow_witness(double time, bool check_drift = false);
  /// Scans the free-flight step [ta, tb] for the first impact; returns its time.
  std::optional<double> scan_free(double ta, double tb);
  /// Scans the following step [ta, tb] for contact loss; returns its time.
  std::optional<double> scan_following(double ta, double tb);

  // ---- segment starts and events (contact_transitions.cpp) ----------------

  /// Starts a following segment at local `time` (the origin moves there).
  void begin_following(double time, double eta, double eta_rate);
  /// Starts a free flight at local `time` (the origin moves there).
  void begin_free(double time, const LinkMotion& links);
  /// Restarts the open segment at the current time `t` (the end of a step):
  /// same mode and state, new origin, integrals booked.
  void restart_segment();
  /// Pin on the wall after an impact: free flight, or settle into following.
  /// A settle's impulse, loss and motor impulse are added to `settle` when given.
  ContactMode after_contact(double time, const LinkMotion& links, ImpactRecord* settle = nullptr);
  /// With wall friction, entering the following mode at (η, η̇): slide in the
  /// direction of the slip speed; at (nearly) zero slip stick if μ·N can
  /// hold the pin (η̇ is then set to ω4 exactly, the tiny kinetic energy
  /// change booked as friction loss), else slide the way the needed friction
  /// force cannot hold.
  void choose_slip(const CrankState& c, double eta, double& eta_rate);
  ImpactResult resolve_settle(const CrankState& c, const LinkMotion& links) const;
  void handle_impact(double time);
  void handle_loss(double time);
  /// A following-mode event: contact loss, or with wall friction the slip
  /// speed reaching zero (stick or reverse) or the stuck pin's friction
  /// reaching μ·N (slide).
  void handle_following_event(double time);

  // ---- books (run_books.cpp) -----------------------------------------------

  double energy(double time, const LinkMotion& m) const;
  double energy_of_links(const CrankState& c, const LinkMotion& m) const;
  int revolution_of(double time) const;
  double revolution_start(int k) const;
  RevolutionRecord& revolution(int k);
  /// Mode time and revolution boundaries over [ta, tb] of the current segment.
  void book_interval(double ta, double tb);
  void record_start_state(RevolutionRecord& r);
  /// Books the start energy (and turn 0's start state) once a start has begun its segment.
  void after_start();
  /// Local time of statistics grid point i.
  double stat_time(long long i) const;
  /// α3 − α3,nominal at the statistics grid points up to `up_to`, booked per turn.
  void emit_statistics(double up_to);
  void emit_samples(double up_to);
  /// The sample at an absolute time (reported with the absolute crank angle).
  ClearanceSample sample(double absolute_time);
  void monitor(const BearingState& b);
  void check_energy(double time, const LinkMotion& m, double work, double friction);
  void zeno_guard(double time);

  // ---- the run (simulator.cpp) --------------------------------------------

  void advance_to(double absolute_end);
  void prepare(double t0);
  /// Moves the origin to the absolute start time t0 (local time 0).
  void prepare_origin(double t0);
};

}  // namespace fourbar
