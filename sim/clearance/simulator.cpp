#include "sim/clearance/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <boost/math/tools/minima.hpp>

#include "common/error.hpp"
#include "common/statistics.hpp"
#include "common/units.hpp"
#include "mechanism/kinetostatics.hpp"
#include "sim/clearance/event_root.hpp"

namespace fourbar {

namespace {

/// Subintervals per integrator step at which the event witnesses are sampled.
constexpr int kScanPoints = 4;
/// Events closer together than this, many times in a row, mean the run is stuck.
constexpr double kZenoSpan_s = 1e-12;
constexpr int kZenoLimit = 100000;
/// A smooth segment longer than this many crank turns is restarted at a new
/// time origin, so its local time (and local crank angle) stays small.
constexpr double kRestartTurns = 64;

Vec2 rotate(Vec2 u, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * u.x - s * u.y, s * u.x + c * u.y};
}

/// Angle of b relative to a, in (−π, π].
double angle_between(Vec2 a, Vec2 b) { return std::atan2(cross(a, b), dot(a, b)); }

}  // namespace

struct ClearanceSimulator::Impl {
  Impl(const ClearanceModel& m, const CrankMotion& c, const ClearanceSettings& s)
      : model(m), crank(c), settings(s), integ(make_integrator(s.integrator, s.tolerance)) {}

  const ClearanceModel& model;
  const CrankMotion& crank;
  ClearanceSettings settings;
  std::unique_ptr<DenseIntegrator> integ;
  ImpactLaw law{settings.restitution, settings.contact, settings.friction_coefficient};

  // Scales of the integrated (scaled) state.
  double speed_scale = 1;   // |ω2| at the start
  double delta_scale = 1;   // ξ/l3
  double energy_scale = 1;  // J
  double force_guard = 0;   // N_guard
  double arm_depth = 0;     // penetration below which a free flight from the wall counts as "inside"

  // Time is measured locally: the absolute time is origin + t, where the
  // origin moves to each segment's start (long runs keep the resolution of
  // the local time; see crank_motion.hpp). Every time inside Impl is local
  // unless named absolute.
  double origin = 0;
  CrankState crank_at(double time) const { return crank.at_local(origin, time); }
  double absolute(double time) const { return origin + time; }
  double local(double absolute_time) const { return absolute_time - origin; }

  /// Moves the origin to the local time `time`; returns that instant in the
  /// new local time (the rounding remainder of origin + time, ~1e-13 s at most).
  double rebase(double time) {
    const double o = origin + time;
    const double r = std::abs(origin) >= std::abs(time) ? (origin - o) + time : (time - o) + origin;
    last_event = (last_event - time) + r;
    origin = o;
    return r;
  }

  // Current segment.
  double t = 0;
  ContactMode mode = ContactMode::following;
  bool armed = true;         // free flight: the pin has left the wall since the segment start
  double segment_start = 0;  // start time of the current smooth segment
  int zeno_count = 0;
  bool stage_filter = false;  // the integrator's right-hand-side calls lie inside its steps
  double last_event = -1e300;

  // Witness samples carried across steps of one segment.
  struct FreeSample { double t, pen, speed; };
  struct FollowSample { double t, w, slip; };
  FreeSample free_prev{};
  std::vector<FollowSample> follow_hist;

  // Books.
  std::vector<double> sample_times;
  std::size_t next_sample = 0;
  std::vector<ClearanceSample> samples;
  std::vector<ImpactRecord> impacts;
  std::vector<RevolutionRecord> revolutions;
  bool revolutions_on = false;
  int stats_per_turn = 0;        // α3-deviation samples per turn (0 = off)
  long long next_stat = 0;       // index of the next one, counted from the revolution origin
  double rev_origin = 0;
  int rev_dir = 1;
  ClearanceDiagnostics diag;
  CompensatedSum work_closed;  // crank work of the closed smooth segments
  // The work component starts each segment at the closed work (scaled), so
  // the integrator's error control on it is as before; the segment's part is
  // y − work_seed, booked into work_closed at the segment's end. (Starting it
  // at 0 tightened that control and moved the chaotic event paths: the
  // wall-friction energy test then missed its bound with CVODE.)
  double work_seed = 0;
  CompensatedSum work_impulse, loss;
  // Following-mode wall friction (settings.following_friction): μ and the
  // sliding direction (+1/−1) or 0 while stuck; the slip witness is armed
  // once the pin slides faster than slip_arm_speed after a start from rest.
  WallFriction wall;
  bool slip_armed = true;
  double slip_arm_speed = 0;    // m/s
  double slip_force_per_speed = 0;  // N per m/s: slip speed in the witness's force units
  CompensatedSum friction_loss;  // dissipated by wall friction in closed following segments

  // ---- state conversion -------------------------------------------------

  struct FreeNominal {
    CrankState crank;
    NominalMotion nominal;
  };

  LinkMotion free_links(double time, const OdeState& y, NominalMotion* nominal_out = nullptr) const {
    const NominalMotion nm = solve_motion(model.rig(), crank_at(time));
    LinkMotion m;
    m.u3 = rotate(nm.pose.u3, y[0] * delta_scale);
    m.u4 = rotate(nm.pose.u4, y[1] * delta_scale);
    m.omega3_rad_s = nm.omega3_rad_s + y[2] * delta_scale * speed_scale;
    m.omega4_rad_s = nm.omega4_rad_s + y[3] * delta_scale * speed_scale;
    if (nominal_out) *nominal_out = nm;
    return m;
  }

  OdeState free_state(double time, const LinkMotion& m) const {
    const NominalMotion nm = solve_motion(model.rig(), crank_at(time));
    OdeState y{};
    y[0] = angle_between(nm.pose.u3, m.u3) / delta_scale;
    y[1] = angle_between(nm.pose.u4, m.u4) / delta_scale;
    y[2] = (m.omega3_rad_s - nm.omega3_rad_s) / (delta_scale * speed_scale);
    y[3] = (m.omega4_rad_s - nm.omega4_rad_s) / (delta_scale * speed_scale);
    y[4] = work_closed.value() / energy_scale;  // crank work, from work_seed
    return y;
  }

  // Following: y = (η, η̇/|ω2|, W/E, D/E, 0) with W the crank work (from
  // work_seed) and D the wall-friction loss of the segment (from 0).
  double eta_of(const OdeState& y) const { return y[0]; }
  double eta_rate_of(const OdeState& y) const { return y[1] * speed_scale; }
  double segment_work(const OdeState& y) const {
    return ((mode == ContactMode::following ? y[2] : y[4]) - work_seed) * energy_scale;
  }
  double segment_friction(const OdeState& y) const {
    return mode == ContactMode::following ? y[3] * energy_scale : 0.0;
  }
  /// Crank work up to now: closed segments plus the open one.
  double work_of(const OdeState& y) const { return work_closed.value() + segment_work(y); }
  /// Friction loss up to now: closed segments plus the open following one.
  double friction_of(const OdeState& y) const { return friction_loss.value() + segment_friction(y); }
  /// Books the open segment's integrals before a new segment starts.
  void close_segment(const OdeState& y) {
    work_closed.add(segment_work(y));
    friction_loss.add(segment_friction(y));
  }

  /// The following mode's event witness (N): N + N_guard, and with wall
  /// friction also the slip speed times its sliding direction (sliding) or
  /// μ·N − |f| (stuck), whichever is smaller.
  double follow_value(const FollowingMotion& f) const {
    double w = f.normal_force_N + force_guard;
    if (wall.mu > 0) {
      if (wall.slip != 0) {
        if (slip_armed) w = std::min(w, wall.slip * f.slip_speed_m_s * slip_force_per_speed);
      } else {
        w = std::min(w, wall.mu * (f.normal_force_N + force_guard) - std::abs(f.tangential_force_N));
      }
    }
    return w;
  }

  LinkMotion links_at(double time, const OdeState& y) const {
    if (mode == ContactMode::following) return model.following_links(crank_at(time), eta_of(y), eta_rate_of(y));
    return free_links(time, y);
  }

  // ---- the two ODE systems ---------------------------------------------

  struct FollowingOde final : OdeSystem {
    Impl* s;
    /// Range of N + N_guard over the right-hand-side calls since the last
    /// clear(): with a Runge–Kutta integrator these are its stage values
    /// inside the step (and inside rejected, longer trial steps).
    double w_min = 0, w_max = 0;
    void clear() { w_min = 1e300, w_max = -1e300; }
    void rhs(double time, const OdeState& y, OdeState& dy) override {
      const CrankState c = s->crank_at(time);
      const FollowingMotion f = s->model.following(c, s->eta_of(y), s->eta_rate_of(y), s->wall);
      const double w = s->follow_value(f);
      w_min = std::min(w_min, w);
      w_max = std::max(w_max, w);
      dy[0] = s->eta_rate_of(y);
      dy[1] = f.eta_accel_rad_s2 / s->speed_scale;
      dy[2] = f.crank_torque_Nm * c.speed_rad_s / s->energy_scale;
      dy[3] = s->wall.mu > 0 ? -f.tangential_force_N * f.slip_speed_m_s / s->energy_scale : 0.0;
      dy[4] = 0;
    }
  } following_ode;

  struct FreeOde final : OdeSystem {
    Impl* s;
    /// Largest and smallest penetration |e| − ξ over the right-hand-side
    /// calls since the last clear() (see FollowingOde::w_min).
    double pen_min = 0, pen_max = 0;
    void clear() { pen_min = 1e300, pen_max = -1e300; }
    void rhs(double time, const OdeState& y, OdeState& dy) override {
      const CrankState c = s->crank_at(time);
      NominalMotion nm;
      const LinkMotion m = s->free_links(time, y, &nm);
      const double pen = -s->model.bearing(c, nm.pose.u2, m).gap_m;
      pen_min = std::min(pen_min, pen);
      pen_max = std::max(pen_max, pen);
      double a3, a4;
      s->model.free_accelerations(c, nm.pose.u2, m, a3, a4);
      const double rate_scale = s->delta_scale * s->speed_scale;
      dy[0] = y[2] * s->speed_scale;
      dy[1] = y[3] * s->speed_scale;
      dy[2] = (a3 - nm.alpha3_rad_s2) / rate_scale;
      dy[3] = (a4 - nm.alpha4_rad_s2) / rate_scale;
      dy[4] = s->model.crank_torque_Nm(c, nm.pose.u2, m, a3, {}) * c.speed_rad_s / s->energy_scale;
    }
  } free_ode;

  // ---- witnesses -----------------------------------------------------------

  FreeSample free_witness(double time) {
    OdeState y;
    integ->interpolate(time, y);
    const BearingState b = model.bearing(crank_at(time), free_links(time, y));
    return {time, -b.gap_m, b.normal_speed_m_s};
  }

  /// N + N_guard at `time`; with `check_drift` also the contact-circle
  /// error (done once per step: it is round-off by construction).
  FollowSample follow_witness(double time, bool check_drift = false) {
    OdeState y;
    integ->interpolate(time, y);
    const CrankState c = crank_at(time);
    const FollowingMotion f = model.following(c, eta_of(y), eta_rate_of(y), wall);
    if (check_drift) monitor(model.bearing(c, f.links));
    if (!slip_armed && wall.slip * f.slip_speed_m_s > slip_arm_speed) slip_armed = true;
    return {time, follow_value(f), f.slip_speed_m_s};
  }

  /// Scans the free-flight step [ta, tb] for the first impact; returns its time.
  std::optional<double> scan_free(double ta, double tb) {
    auto pen = [this](double x) { return free_witness(x).pen; };
    auto spd = [this](double x) { return free_witness(x).speed; };
    FreeSample prev = free_prev;
    if (prev.t != ta) prev = free_witness(ta);
    if (armed && stage_filter && !settings.full_event_scan) {
      // As in scan_following: the pin stays inside by more than the spread
      // of the step's stage and end penetrations.
      const FreeSample end = free_witness(tb);
      const double lo = std::min({free_ode.pen_min, prev.pen, end.pen});
      const double hi = std::max({free_ode.pen_max, prev.pen, end.pen});
      if (-hi > hi - lo) {
        ++diag.filtered_steps;
        free_prev = end;
        return std::nullopt;
      }
    }
    for (int i = 1; i <= kScanPoints; ++i) {
      const double ti = i == kScanPoints ? tb : ta + (tb - ta) * i / kScanPoints;
      const FreeSample cur = free_witness(ti);
      if (!armed) {
        if (cur.pen < -arm_depth) {
          armed = true;
        } else if (cur.speed > 0) {
          // Past the deepest point of this flight: find it, then look ahead.
          double tmin = prev.t, pmin = prev.pen;
          if (prev.speed < 0) {
            tmin = locate_root(spd, prev.t, cur.t, prev.speed, cur.speed);
            pmin = pen(tmin);
          }
          if (cur.pen < 0) {
            armed = true;  // coming back from inside: the crossing ahead is an impact
          } else if (pmin < -arm_depth) {
            armed = true;
            return locate_root(pen, tmin, cur.t, pmin, cur.pen);
          } else if (cur.pen > arm_depth) {
            armed = true;
            return tmin;  // the pin never left the wall beyond round-off: a touch
          }
          // Else still on the wall within round-off (|pen| ≤ arm depth), e.g.
          // just after a contact loss at N = −N_guard: a touch here would
          // restart the same state at the same time, so wait.
        }
        prev = cur;
        continue;
      }
      if (cur.pen >= 0) return locate_root(pen, prev.t, cur.t, prev.pen, cur.pen);
      if (prev.speed > 0 && cur.speed < 0) {
        // A local maximum of the penetration between samples: a grazing double root?
        const double tmax = locate_root(spd, prev.t, cur.t, prev.speed, cur.speed);
        const double pmax = pen(tmax);
        if (pmax >= 0) return locate_root(pen, prev.t, tmax, prev.pen, pmax);
      }
      prev = cur;
    }
    free_prev = prev;
    return std::nullopt;
  }

  /// Scans the following step [ta, tb] for contact loss; returns its time.
  std::optional<double> scan_following(double ta, double tb) {
    auto w = [this](double x) { return follow_witness(x).w; };
    if (follow_hist.empty() || follow_hist.back().t != ta) {
      follow_hist.clear();
      follow_hist.push_back(follow_witness(ta));
    }
    if (stage_filter && !settings.full_event_scan) {
      // The step's stage values and both ends stay positive by more than
      // their spread: w cannot reach zero inside (a parabola through them
      // dips at most 0.26 of the spread below the lowest), so the step end
      // is the only sample needed.
      const FollowSample end = follow_witness(tb, true);
      const double lo = std::min({following_ode.w_min, follow_hist.back().w, end.w});
      const double hi = std::max({following_ode.w_max, follow_hist.back().w, end.w});
      if (lo > hi - lo) {
        ++diag.filtered_steps;
        follow_hist.push_back(end);
        if (follow_hist.size() > 2) follow_hist.erase(follow_hist.begin());
        return std::nullopt;
      }
    }
    for (int i = 1; i <= kScanPoints; ++i) {
      const double ti = i == kScanPoints ? tb : ta + (tb - ta) * i / kScanPoints;
      const FollowSample cur = follow_witness(ti, i == kScanPoints);
      const FollowSample prev = follow_hist.back();
      if (cur.w <= 0) return locate_root(w, prev.t, cur.t, prev.w, cur.w);
      if (follow_hist.size() >= 2) {
        // Sampled local minimum: does a parabola through the three samples dip below zero?
        const FollowSample a = follow_hist[follow_hist.size() - 2];
        if (prev.w < a.w && prev.w < cur.w) {
          const double h1 = prev.t - a.t, h2 = cur.t - prev.t;
          const double d1 = (prev.w - a.w) / h1, d2 = (cur.w - prev.w) / h2;
          const double curv = 2 * (d2 - d1) / (h1 + h2);
          const double slope_mid = d1 + 0.5 * curv * h1;  // slope at prev
          const double dip = prev.w - slope_mid * slope_mid / (2 * curv);
          if (dip <= 0.5 * prev.w) {
            // Search only where the dense output is valid: the current step.
            const double lo = std::max(a.t, integ->previous_time());
            const double wlo = lo == a.t ? a.w : w(lo);
            const auto [tmin, wmin] = boost::math::tools::brent_find_minima(w, lo, cur.t, 40);
            if (wmin <= 0) return locate_root(w, lo, tmin, wlo, wmin);
          }
        }
      }
      follow_hist.push_back(cur);
      if (follow_hist.size() > 2) follow_hist.erase(follow_hist.begin());
    }
    return std::nullopt;
  }

  // ---- segment starts --------------------------------------------------------

  /// Starts a following segment at local `time` (the origin moves there).
  void begin_following(double time, double eta, double eta_rate) {
    time = rebase(time);
    mode = ContactMode::following;
    work_seed = work_closed.value() / energy_scale;
    const OdeState y{eta, eta_rate / speed_scale, work_seed, 0, 0};
    integ->reset(following_ode, time, y);
    t = segment_start = time;
    follow_hist.clear();
    FollowingMotion f = model.following(crank_at(time), eta, eta_rate, wall);
    follow_hist.push_back({time, follow_value(f), f.slip_speed_m_s});
  }

  /// Starts a free flight at local `time` (the origin moves there).
  void begin_free(double time, const LinkMotion& links) {
    time = rebase(time);
    mode = ContactMode::free_flight;
    const OdeState y = free_state(time, links);
    work_seed = y[4];
    integ->reset(free_ode, time, y);
    t = segment_start = time;
    const BearingState b = model.bearing(crank_at(time), links);
    armed = -b.gap_m < -arm_depth;
    free_prev = {time, -b.gap_m, b.normal_speed_m_s};
  }

  /// The following-mode coordinates of a link motion on the contact circle.
  void to_following(double time, const LinkMotion& m, double& eta, double& eta_rate) const {
    const CrankState c = crank_at(time);
    const BearingState b = model.bearing(c, m);
    const Rig& rig = model.rig();
    const Vec2 u2 = unit(c.angle_rad);
    const Vec2 e_dot = rig.crank.length_m * c.speed_rad_s * u2.perp() + rig.coupler.length_m * m.omega3_rad_s * m.u3.perp() -
                       rig.rocker.length_m * m.omega4_rad_s * m.u4.perp();
    eta = std::atan2(b.normal.y, b.normal.x);
    eta_rate = dot(e_dot, b.normal.perp()) / model.clearance_m();
  }

  /// Pin on the wall after an impact: free flight, or settle into following.
  ContactMode after_contact(double time, const LinkMotion& links) {
    const CrankState c = crank_at(time);
    const BearingState b = model.bearing(c, links);
    if (b.normal_speed_m_s < -settings.settle_speed_m_s) {
      begin_free(time, links);
      return mode;
    }
    // Remove the remaining normal speed with a plastic impulse (projection
    // onto φ̇ = 0 in the kinetic metric), then ask the following mode.
    const ImpactResult settle = resolve_settle(c, links);
    ++diag.settles;
    work_impulse.add(c.speed_rad_s * settle.motor_impulse_Nms);
    loss.add(settle.energy_loss_J);
    double eta, eta_rate;
    to_following(time, settle.after, eta, eta_rate);
    choose_slip(c, eta, eta_rate);
    const FollowingMotion f = model.following(c, eta, eta_rate, wall);
    if (f.normal_force_N > -force_guard) {
      begin_following(time, eta, eta_rate);
    } else {
      begin_free(time, f.links);
      armed = false;
    }
    return mode;
  }

  /// With wall friction, entering the following mode at (η, η̇): slide in the
  /// direction of the slip speed; at (nearly) zero slip stick if μ·N can
  /// hold the pin (η̇ is then set to ω4 exactly, the tiny kinetic energy
  /// change booked as friction loss), else slide the way the needed friction
  /// force cannot hold.
  void choose_slip(const CrankState& c, double eta, double& eta_rate) {
    if (wall.mu == 0) return;
    const LinkMotion m = model.following_links(c, eta, eta_rate);
    const double v_t = model.clearance_m() * (eta_rate - m.omega4_rad_s);
    if (std::abs(v_t) > slip_arm_speed) {
      wall.slip = v_t > 0 ? 1 : -1;
      slip_armed = true;
      return;
    }
    // ω4 is affine in η̇: the rate with zero slip solves η̇ = ω4(η̇).
    const double h4 = model.following_links(c, eta, 0.0).omega4_rad_s;
    const double g4 = model.following_links(c, eta, 1.0).omega4_rad_s - h4;
    const double stuck_rate = h4 / (1.0 - g4);
    const FollowingMotion f = model.following(c, eta, stuck_rate, {wall.mu, 0});
    if (std::abs(f.tangential_force_N) <= wall.mu * f.normal_force_N) {
      friction_loss.add(energy_of_links(c, m) - energy_of_links(c, f.links));
      eta_rate = stuck_rate;
      wall.slip = 0;
      ++diag.sticks;
    } else {
      wall.slip = f.tangential_force_N > 0 ? -1 : 1;
      slip_armed = false;
    }
  }

  ImpactResult resolve_settle(const CrankState& c, const LinkMotion& links) const {
    const BearingState b = model.bearing(c, links);
    // Normal impulse F that zeroes the normal speed: F = v_n / K_nn.
    const ImpactResult probe = apply_impulse(model, c, links, 1.0, 0.0);
    const double knn = probe.normal_speed_before_m_s - probe.normal_speed_after_m_s;
    return apply_impulse(model, c, links, b.normal_speed_m_s / knn, 0.0);
  }

  // ---- books -------------------------------------------------------------------

  double energy(double time, const LinkMotion& m) const { return energy_of_links(crank_at(time), m); }
  double energy_of_links(const CrankState& c, const LinkMotion& m) const {
    return model.kinetic_energy_J(c, m) + model.potential_energy_J(c, m);
  }

  int revolution_of(double time) const {
    const double turns = (crank.at(absolute(time)).angle_rad - rev_origin) * rev_dir / units::kTwoPi;
    return static_cast<int>(std::floor(turns + 1e-12));
  }

  double revolution_start(int k) const { return crank.time_at_angle(rev_origin + rev_dir * units::kTwoPi * k); }

  RevolutionRecord& revolution(int k) {
    while (static_cast<int>(revolutions.size()) <= k) {
      RevolutionRecord r;
      r.index = static_cast<int>(revolutions.size());
      r.start_time_s = revolution_start(r.index);
      r.end_time_s = revolution_start(r.index + 1);
      revolutions.push_back(r);
    }
    return revolutions[k];
  }

  /// Mode time and revolution boundaries over [ta, tb] of the current segment.
  void book_interval(double ta, double tb) {
    (mode == ContactMode::following ? diag.time_following_s : diag.time_free_s) += tb - ta;
    if (mode == ContactMode::following && wall.mu > 0 && wall.slip == 0) diag.time_stuck_s += tb - ta;
    if (!revolutions_on) return;
    int k = std::max(0, revolution_of(ta));
    double a = ta;
    for (;;) {
      RevolutionRecord& r = revolution(k);
      const double end = local(r.end_time_s);
      const double b = std::min(tb, end);
      if (b > a) (mode == ContactMode::following ? r.following_time_s : r.free_time_s) += b - a;
      if (end > tb) break;
      // Reached the start of turn k + 1: record its state once.
      RevolutionRecord& next = revolution(k + 1);
      if (!next.has_start_state) record_start_state(next);
      a = end;
      ++k;
      if (a >= tb) break;
    }
  }

  void record_start_state(RevolutionRecord& r) {
    OdeState y;
    const double start = local(r.start_time_s);
    integ->interpolate(start, y);
    const LinkMotion m = links_at(start, y);
    const OdeState f = free_state(start, m);
    r.start_state = {f[0], f[1], f[2], f[3]};
    r.start_mode = mode;
    r.has_start_state = true;
  }

  /// Local time of statistics grid point i.
  double stat_time(long long i) const {
    return local(crank.time_at_angle(rev_origin + rev_dir * units::kTwoPi * static_cast<double>(i) / stats_per_turn));
  }

  /// α3 − α3,nominal at the statistics grid points up to `up_to`, booked per turn.
  void emit_statistics(double up_to) {
    if (stats_per_turn <= 0) return;
    for (double ts = stat_time(next_stat); ts <= up_to; ts = stat_time(++next_stat)) {
      if (ts < segment_start) continue;  // before the start
      OdeState y;
      integ->interpolate(ts, y);
      const CrankState c = crank_at(ts);
      double a3, a4;
      if (mode == ContactMode::following) {
        a3 = model.following(c, eta_of(y), eta_rate_of(y), wall).alpha3_rad_s2;
      } else {
        model.free_accelerations(c, free_links(ts, y), a3, a4);
      }
      const double d = a3 - solve_motion(model.rig(), c).alpha3_rad_s2;
      RevolutionRecord& r = revolution(static_cast<int>(next_stat / stats_per_turn));
      r.alpha3_deviation_sum_sq += d * d;
      ++r.alpha3_deviation_samples;
      r.alpha3_deviation_rms_rad_s2 = std::sqrt(r.alpha3_deviation_sum_sq / r.alpha3_deviation_samples);
    }
  }

  void emit_samples(double up_to) {
    while (next_sample < sample_times.size() && local(sample_times[next_sample]) <= up_to) {
      samples.push_back(sample(sample_times[next_sample]));
      ++next_sample;
    }
  }

  /// The sample at an absolute time (reported with the absolute crank angle).
  ClearanceSample sample(double absolute_time) {
    const double time = local(absolute_time);
    OdeState y;
    integ->interpolate(time, y);
    ClearanceSample s;
    s.time_s = absolute_time;
    s.crank = crank_at(time);
    s.mode = mode;
    if (mode == ContactMode::following) {
      const FollowingMotion f = model.following(s.crank, eta_of(y), eta_rate_of(y), wall);
      s.links = f.links;
      s.alpha3_rad_s2 = f.alpha3_rad_s2;
      s.alpha4_rad_s2 = f.alpha4_rad_s2;
      s.bearing_force_N = f.pin_force();
      s.crank_torque_Nm = f.crank_torque_Nm;
    } else {
      s.links = free_links(time, y);
      model.free_accelerations(s.crank, s.links, s.alpha3_rad_s2, s.alpha4_rad_s2);
      s.crank_torque_Nm = model.crank_torque_Nm(s.crank, s.links, s.alpha3_rad_s2, {});
    }
    const BearingState b = model.bearing(s.crank, s.links);
    s.gap_m = b.gap_m;
    s.eta_rad = std::atan2(b.normal.y, b.normal.x);
    s.kinetic_energy_J = model.kinetic_energy_J(s.crank, s.links);
    s.potential_energy_J = model.potential_energy_J(s.crank, s.links);
    monitor(b);
    s.crank.angle_rad = crank.at(absolute_time).angle_rad;
    return s;
  }

  void monitor(const BearingState& b) {
    const double xi = model.clearance_m();
    if (mode == ContactMode::following) {
      diag.max_contact_circle_error = std::max(diag.max_contact_circle_error, std::abs(b.gap_m) / xi);
      diag.max_contact_normal_speed_m_s = std::max(diag.max_contact_normal_speed_m_s, std::abs(b.normal_speed_m_s));
    } else {
      diag.max_penetration = std::max(diag.max_penetration, -b.gap_m / xi);
    }
  }

  void check_energy(double time, const LinkMotion& m, double work, double friction) {
    const double r = energy(time, m) - diag.energy_start_J - work - work_impulse.value() + loss.value() + friction;
    diag.max_energy_residual_J = std::max(diag.max_energy_residual_J, std::abs(r));
  }

  void zeno_guard(double time) {
    zeno_count = time - last_event < kZenoSpan_s ? zeno_count + 1 : 0;
    last_event = time;
    if (zeno_count > kZenoLimit)
      throw RunError("clearance model: events pile up at t = " + std::to_string(absolute(time)) +
                     " s without progress; raise [clearance] settle_speed_mm_s");
  }

  // ---- events --------------------------------------------------------------------

  void handle_impact(double time) {
    OdeState y;
    integ->interpolate(time, y);
    const double work = work_of(y);
    const LinkMotion before = free_links(time, y);
    const CrankState c = crank_at(time);
    const BearingState b = model.bearing(c, before);
    monitor(b);
    check_energy(time, before, work, friction_loss.value());
    close_segment(y);
    ImpactRecord rec;
    rec.time_s = absolute(time);
    rec.crank_angle_rad = crank.at(rec.time_s).angle_rad;
    rec.eta_rad = std::atan2(b.normal.y, b.normal.x);
    rec.result = resolve_impact(model, c, before, law);
    rec.revolution = revolutions_on ? revolution_of(time) : 0;
    const bool counted = b.normal_speed_m_s > settings.settle_speed_m_s;
    (counted ? diag.impacts : diag.touches) += 1;
    if (rec.result.degenerate) ++diag.degenerate_impacts;
    if (rec.result.energy_loss_J < -1e-15 * energy_scale) ++diag.energy_gaining_impacts;
    work_impulse.add(c.speed_rad_s * rec.result.motor_impulse_Nms);
    loss.add(rec.result.energy_loss_J);
    if (revolutions_on && counted && rec.revolution >= 0) {
      RevolutionRecord& r = revolution(rec.revolution);
      ++r.impacts;
      r.sum_normal_impulse_Ns += rec.result.normal_impulse_Ns;
    }
    rec.mode_after = after_contact(time, rec.result.after);
    if (counted) impacts.push_back(rec);
  }

  void handle_loss(double time) {
    OdeState y;
    integ->interpolate(time, y);
    const double work = work_of(y);
    const LinkMotion m = model.following_links(crank_at(time), eta_of(y), eta_rate_of(y));
    check_energy(time, m, work, friction_of(y));
    close_segment(y);
    ++diag.contact_losses;
    if (revolutions_on) {
      const int k = revolution_of(time);
      if (k >= 0) ++revolution(k).contact_losses;
    }
    begin_free(time, m);
    armed = false;
  }

  /// A following-mode event: contact loss, or with wall friction the slip
  /// speed reaching zero (stick or reverse) or the stuck pin's friction
  /// reaching μ·N (slide).
  void handle_following_event(double time) {
    OdeState y;
    integ->interpolate(time, y);
    const CrankState c = crank_at(time);
    double eta = eta_of(y), eta_rate = eta_rate_of(y);
    const FollowingMotion f = model.following(c, eta, eta_rate, wall);
    if (wall.mu == 0 || f.normal_force_N + force_guard <= follow_value(f)) return handle_loss(time);
    const double work = work_of(y);
    check_energy(time, f.links, work, friction_of(y));
    close_segment(y);
    if (wall.slip != 0) {
      ++diag.slip_stops;
      choose_slip(c, eta, eta_rate);
    } else {
      wall.slip = f.tangential_force_N > 0 ? -1 : 1;  // friction at μ·N cannot hold: slide
      slip_armed = false;
    }
    begin_following(time, eta, eta_rate);
  }

  // ---- the main loop -----------------------------------------------------------------

  /// Restarts the open segment at the current time `t` (the end of a step):
  /// same mode and state, new origin, integrals booked.
  void restart_segment() {
    OdeState y;
    integ->interpolate(t, y);
    const double time = t;
    if (mode == ContactMode::following) {
      const double eta = eta_of(y), eta_rate = eta_rate_of(y);
      close_segment(y);
      begin_following(time, eta, eta_rate);
    } else {
      const LinkMotion m = free_links(time, y);
      const bool was_armed = armed;
      close_segment(y);
      begin_free(time, m);
      armed = was_armed;
    }
  }

  void advance_to(double absolute_end) {
    for (;;) {
      const double t_end = local(absolute_end);  // the origin moves with each segment
      if (!(t < t_end)) break;
      if (t == integ->current_time() && (t - segment_start) * speed_scale > kRestartTurns * units::kTwoPi)
        restart_segment();
      double tb = integ->current_time();
      if (tb <= t) {
        following_ode.clear();
        free_ode.clear();
        tb = integ->step(t_end);
      }  // else: the rest of an earlier step is still unused
      const double ta = t;
      tb = std::min(tb, t_end);
      ++diag.steps;
      const std::optional<double> ev = mode == ContactMode::following ? scan_following(ta, tb) : scan_free(ta, tb);
      const double t_stop = ev ? *ev : tb;
      emit_samples(t_stop);
      emit_statistics(t_stop);
      book_interval(ta, t_stop);
      t = t_stop;
      if (!ev) continue;
      zeno_guard(t_stop);
      if (mode == ContactMode::following) handle_following_event(t_stop);
      else handle_impact(t_stop);
    }
  }

  void prepare(double t0) {
    const CrankState c = crank.at(t0);
    speed_scale = std::abs(c.speed_rad_s) > 0 ? std::abs(c.speed_rad_s) : 1.0;
    delta_scale = model.clearance_m() / model.rig().coupler.length_m;
    energy_scale = model.energy_scale_J(c.speed_rad_s);
    if (!(energy_scale > 0)) energy_scale = 1.0;  // a rig at rest without gravity
    force_guard = 1e-9 * model.force_scale_N(c.speed_rad_s);
    arm_depth = 1e-11 * model.clearance_m();
    wall = {settings.following_friction ? settings.friction_coefficient : 0.0, 1};
    slip_arm_speed = 1e-9 * model.clearance_m() * speed_scale;
    slip_force_per_speed = model.force_scale_N(c.speed_rad_s) / (model.clearance_m() * speed_scale);
    rev_dir = c.speed_rad_s < 0 ? -1 : 1;
    following_ode.s = this;
    free_ode.s = this;
    stage_filter = integ->stages_inside_step();
    diag.energy_scale_J = energy_scale;
    prepare_origin(t0);
  }

  /// Moves the origin to the absolute start time t0 (local time 0).
  void prepare_origin(double t0) {
    origin = t0;
    t = segment_start = 0;
    last_event = -1e300;
  }

  void after_start() {
    OdeState y;
    integ->interpolate(t, y);
    diag.energy_start_J = energy(t, links_at(t, y));
    if (revolutions_on) record_start_state(revolution(std::max(0, revolution_of(t))));
  }
};

ClearanceSimulator::ClearanceSimulator(const ClearanceModel& model, const CrankMotion& crank,
                                       const ClearanceSettings& settings)
    : impl_(std::make_unique<Impl>(model, crank, settings)) {}

ClearanceSimulator::~ClearanceSimulator() = default;

void ClearanceSimulator::set_sample_times(std::vector<double> times) {
  impl_->sample_times = std::move(times);
  impl_->next_sample = 0;
}

void ClearanceSimulator::set_revolution_statistics(int samples_per_turn) {
  impl_->stats_per_turn = samples_per_turn;
  impl_->next_stat = 0;
}

void ClearanceSimulator::set_revolution_origin(double crank_angle_rad) {
  impl_->revolutions_on = true;
  impl_->rev_origin = crank_angle_rad;
}

void ClearanceSimulator::start_nominal(double t0) {
  Impl& s = *impl_;
  s.prepare(t0);
  const Rig& rig = s.model.rig();
  // Clearance link along the nominal bearing force (thesis sec. 3.4): the
  // bushing pushes the pin along −n, so n = −F_nominal/|F_nominal|.
  auto direction = [&](double time) {
    const NominalMotion nm = solve_motion(rig, s.crank_at(time));
    const Vec2 f = solve_loads(rig, nm).bearing_N;
    return std::atan2(-f.y, -f.x);
  };
  const double eta0 = direction(0.0);  // local times from here on
  // Its rate by a 4th-order central difference of the nominal force angle.
  const double h = 1e-4 / s.speed_scale;
  auto rel = [&](double time) { return eta0 + std::remainder(direction(time) - eta0, units::kTwoPi); };
  const double rate = (rel(-2 * h) - 8 * rel(-h) + 8 * rel(h) - rel(2 * h)) / (12 * h);
  const CrankState c = s.crank_at(0.0);
  double eta_rate = rate;
  s.choose_slip(c, eta0, eta_rate);
  const FollowingMotion f = s.model.following(c, eta0, eta_rate, s.wall);
  if (f.normal_force_N > -s.force_guard) {
    s.begin_following(0.0, eta0, eta_rate);
  } else {
    s.begin_free(0.0, f.links);
    s.armed = false;
  }
  s.after_start();
}

void ClearanceSimulator::start_following(double t0, double eta_rad, double eta_rate_rad_s) {
  impl_->prepare(t0);
  double eta_rate = eta_rate_rad_s;
  impl_->choose_slip(impl_->crank_at(0.0), eta_rad, eta_rate);
  impl_->begin_following(0.0, eta_rad, eta_rate);
  impl_->after_start();
}

void ClearanceSimulator::start_free(double t0, const LinkMotion& links) {
  impl_->prepare(t0);
  impl_->begin_free(0.0, links);
  impl_->after_start();
}

void ClearanceSimulator::advance_to(double t_end) { impl_->advance_to(t_end); }

double ClearanceSimulator::time() const { return impl_->absolute(impl_->t); }
ContactMode ClearanceSimulator::mode() const { return impl_->mode; }

LinkMotion ClearanceSimulator::current_links() {
  OdeState y;
  impl_->integ->interpolate(impl_->t, y);
  return impl_->links_at(impl_->t, y);
}

const std::vector<ClearanceSample>& ClearanceSimulator::samples() const { return impl_->samples; }
const std::vector<ImpactRecord>& ClearanceSimulator::impacts() const { return impl_->impacts; }
const std::vector<RevolutionRecord>& ClearanceSimulator::revolutions() const { return impl_->revolutions; }

ClearanceDiagnostics ClearanceSimulator::diagnostics() {
  Impl& s = *impl_;
  OdeState y;
  s.integ->interpolate(s.t, y);
  const LinkMotion m = s.links_at(s.t, y);
  const double work = s.work_of(y);
  const double friction = s.friction_of(y);
  s.check_energy(s.t, m, work, friction);
  ClearanceDiagnostics d = s.diag;
  d.crank_work_J = work;
  d.motor_impulse_work_J = s.work_impulse.value();
  d.impact_loss_J = s.loss.value();
  d.energy_end_J = s.energy(s.t, m);
  d.friction_loss_J = friction;
  d.energy_residual_J = d.energy_end_J - d.energy_start_J - work - d.motor_impulse_work_J + d.impact_loss_J + friction;
  d.steps = s.integ->steps();
  return d;
}

}  // namespace fourbar
