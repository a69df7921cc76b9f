// The clearance simulator's run: preparing the scales and the local time
// origin, the main loop that steps the integrator, scans each step for events
// and hands them on, and the public ClearanceSimulator API. The concepts it
// drives live in mode_equations.cpp, event_scan.cpp, contact_transitions.cpp
// and run_books.cpp, over the state declared in simulator_state.hpp.

#include "sim/clearance/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/units.hpp"
#include "mechanism/kinetostatics.hpp"
#include "sim/clearance/simulator_state.hpp"

namespace fourbar {

double ClearanceSimulator::Impl::rebase(double time) {
  const double o = origin + time;
  const double r = std::abs(origin) >= std::abs(time) ? (origin - o) + time : (time - o) + origin;
  last_event = (last_event - time) + r;
  origin = o;
  return r;
}

void ClearanceSimulator::Impl::prepare(double t0) {
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

void ClearanceSimulator::Impl::prepare_origin(double t0) {
  origin = t0;
  t = segment_start = 0;
  last_event = -1e300;
}

void ClearanceSimulator::Impl::advance_to(double absolute_end) {
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
