// The clearance simulator's run: preparing the scales and the local time
// origin, the main loop that steps the integrator, scans each step for events
// and hands them on, and the public ClearanceSimulator API. The concepts it
// drives live in mode_equations.cpp, event_scan.cpp, contact_transitions.cpp
// and run_books.cpp, over the state declared in simulator_state.hpp.

#include "sim/three_mode/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "common/units.hpp"
#include "mechanism/kinetostatics.hpp"
#include "sim/three_mode/simulator_state.hpp"

namespace fourbar {

// ---- local clock ------------------------------------------------------------

double ClearanceSimulator::Impl::rebase(double time) {
  const double r = clock.rebase(time);
  zeno.last_event = (zeno.last_event - time) + r;
  return r;
}

// ---- prepare ----------------------------------------------------------------

void ClearanceSimulator::Impl::prepare(double t0) {
  const CrankState c = crank.at(t0);
  scale.speed_rad_s = std::abs(c.speed_rad_s) > 0 ? std::abs(c.speed_rad_s) : 1.0;
  scale.delta = model.clearance_m() / model.rig().coupler.length_m;
  scale.energy_J = model.energy_scale_J(c.speed_rad_s);
  if (!(scale.energy_J > 0)) scale.energy_J = 1.0;  // a rig at rest without gravity
  scale.force_guard_N = kForceGuardFraction * model.force_scale_N(c.speed_rad_s);
  scale.arm_depth_m = kArmDepthFraction * model.clearance_m();
  wall.friction = {settings.following_friction ? settings.friction_coefficient : 0.0, 1};
  wall.slip_arm_speed_m_s = kSlipArmSpeedFraction * model.clearance_m() * scale.speed_rad_s;
  wall.slip_force_per_speed = model.force_scale_N(c.speed_rad_s) / (model.clearance_m() * scale.speed_rad_s);
  books.rev_dir = c.speed_rad_s < 0 ? -1 : 1;
  following_ode.s = this;
  free_ode.s = this;
  witness.stage_filter = integ->stages_inside_step();
  books.diag.energy_scale_J = scale.energy_J;
  prepare_origin(t0);
}

void ClearanceSimulator::Impl::prepare_origin(double t0) {
  clock.origin_s = t0;
  seg.t = seg.start = 0;
  zeno.last_event = -kNoneYet;
}

// ---- the main loop ------------------------------------------------------------

void ClearanceSimulator::Impl::advance_to(double absolute_end) {
  for (;;) {
    const double t_end = local(absolute_end);  // the origin moves with each segment
    if (!(seg.t < t_end)) break;
    if (seg.t == integ->current_time() && (seg.t - seg.start) * scale.speed_rad_s > kRestartTurns * units::kTwoPi)
      restart_segment();
    double tb = integ->current_time();
    if (tb <= seg.t) {
      following_ode.clear();
      free_ode.clear();
      tb = integ->step(t_end);
    }  // else: the rest of an earlier step is still unused
    const double ta = seg.t;
    tb = std::min(tb, t_end);
    ++books.diag.steps;
    const std::optional<double> ev = seg.mode == ContactMode::following ? scan_following(ta, tb) : scan_free(ta, tb);
    const double t_stop = ev ? *ev : tb;
    emit_samples(t_stop);
    emit_statistics(t_stop);
    book_interval(ta, t_stop);
    seg.t = t_stop;
    if (!ev) continue;
    zeno_guard(t_stop);
    if (seg.mode == ContactMode::following) handle_following_event(t_stop);
    else handle_impact(t_stop);
  }
}

// ---- public API ---------------------------------------------------------------

ClearanceSimulator::ClearanceSimulator(const ClearanceModel& model, const CrankMotion& crank,
                                       const ClearanceSettings& settings)
    : impl_(std::make_unique<Impl>(model, crank, settings)) {}

ClearanceSimulator::~ClearanceSimulator() = default;

void ClearanceSimulator::set_sample_times(std::vector<double> times) {
  impl_->books.sample_times = std::move(times);
  impl_->books.next_sample = 0;
  // One allocation for every sample asked for (a fit's run holds ~10^5):
  // growing by doubling copied them and touched twice the memory.
  impl_->books.samples.reserve(impl_->books.samples.size() + impl_->books.sample_times.size());
}

void ClearanceSimulator::set_revolution_statistics(int samples_per_turn) {
  impl_->books.stats_per_turn = samples_per_turn;
  impl_->books.next_stat = 0;
}

void ClearanceSimulator::set_revolution_origin(double crank_angle_rad) {
  impl_->books.revolutions_on = true;
  impl_->books.rev_origin_rad = crank_angle_rad;
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
  const double h = kRateDifferenceStep_rad / s.scale.speed_rad_s;
  auto rel = [&](double time) { return eta0 + std::remainder(direction(time) - eta0, units::kTwoPi); };
  const double rate = (rel(-2 * h) - 8 * rel(-h) + 8 * rel(h) - rel(2 * h)) / (12 * h);
  const CrankState c = s.crank_at(0.0);
  double eta_rate = rate;
  s.choose_slip(c, eta0, eta_rate);
  const FollowingMotion f = s.model.following(c, eta0, eta_rate, s.wall.friction);
  if (f.normal_force_N > -s.scale.force_guard_N) {
    s.begin_following(0.0, eta0, eta_rate);
  } else {
    s.begin_free(0.0, f.links);
    s.seg.armed = false;
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

double ClearanceSimulator::time() const { return impl_->absolute(impl_->seg.t); }
ContactMode ClearanceSimulator::mode() const { return impl_->seg.mode; }

LinkMotion ClearanceSimulator::current_links() {
  OdeState y;
  impl_->integ->interpolate(impl_->seg.t, y);
  return impl_->links_at(impl_->seg.t, y);
}

const std::vector<ClearanceSample>& ClearanceSimulator::samples() const { return impl_->books.samples; }
const std::vector<ImpactRecord>& ClearanceSimulator::impacts() const { return impl_->books.impacts; }
const std::vector<RevolutionRecord>& ClearanceSimulator::revolutions() const { return impl_->books.revolutions; }

ClearanceDiagnostics ClearanceSimulator::diagnostics() {
  Impl& s = *impl_;
  OdeState y;
  s.integ->interpolate(s.seg.t, y);
  const LinkMotion m = s.links_at(s.seg.t, y);
  const double work = s.work_of(y);
  const double friction = s.friction_of(y);
  s.check_energy(s.seg.t, m, work, friction);
  ClearanceDiagnostics d = s.books.diag;
  d.crank_work_J = work;
  d.motor_impulse_work_J = s.energy_books.work_impulse.value();
  d.impact_loss_J = s.energy_books.loss.value();
  d.energy_end_J = s.energy(s.seg.t, m);
  d.friction_loss_J = friction;
  d.energy_residual_J = d.energy_end_J - d.energy_start_J - work - d.motor_impulse_work_J + d.impact_loss_J + friction;
  d.steps = s.integ->steps();
  return d;
}

}  // namespace fourbar
