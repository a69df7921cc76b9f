// The clearance simulator's transitions between smooth segments: starting a
// following or free-flight segment (which moves the local time origin), the
// decision after an impact (rebound, or settle into the following mode), the
// wall-friction stick/slip choice, and the handlers of the located events.

#include <cmath>

#include "sim/three_mode/simulator_state.hpp"

namespace fourbar {

void ClearanceSimulator::Impl::begin_following(double time, double eta, double eta_rate) {
  time = rebase(time);
  seg.mode = ContactMode::following;
  energy_books.work_seed = energy_books.work_closed.value() / scale.energy_J;
  const OdeState y{eta, eta_rate / scale.speed_rad_s, energy_books.work_seed, 0, 0};
  integ->reset(following_ode, time, y);
  seg.t = seg.start = time;
  witness.follow_hist.clear();
  FollowingMotion f = model.following(crank_at(time), eta, eta_rate, wall.friction);
  witness.follow_hist.push_back({time, follow_value(f), f.slip_speed_m_s});
}

void ClearanceSimulator::Impl::begin_free(double time, const LinkMotion& links) {
  time = rebase(time);
  seg.mode = ContactMode::free_flight;
  const OdeState y = free_state(time, links);
  energy_books.work_seed = y[4];
  integ->reset(free_ode, time, y);
  seg.t = seg.start = time;
  const BearingState b = model.bearing(crank_at(time), links);
  seg.armed = -b.gap_m < -scale.arm_depth_m;
  witness.free_prev = {time, -b.gap_m, b.normal_speed_m_s};
}

void ClearanceSimulator::Impl::restart_segment() {
  OdeState y;
  integ->interpolate(seg.t, y);
  const double time = seg.t;
  if (seg.mode == ContactMode::following) {
    const double eta = eta_of(y), eta_rate = eta_rate_of(y);
    close_segment(y);
    begin_following(time, eta, eta_rate);
  } else {
    const LinkMotion m = free_links(time, y);
    const bool was_armed = seg.armed;
    close_segment(y);
    begin_free(time, m);
    seg.armed = was_armed;
  }
}

ContactMode ClearanceSimulator::Impl::after_contact(double time, const LinkMotion& links, ImpactRecord* rec) {
  const CrankState c = crank_at(time);
  const BearingState b = model.bearing(c, links);
  if (b.normal_speed_m_s < -settings.settle_speed_m_s) {
    begin_free(time, links);
    return seg.mode;
  }
  // Remove the remaining normal speed with a plastic impulse (projection
  // onto φ̇ = 0 in the kinetic metric), then ask the following mode.
  const ImpactResult settle = resolve_settle(c, links);
  ++books.diag.settles;
  energy_books.work_impulse.add(c.speed_rad_s * settle.motor_impulse_Nms);
  energy_books.loss.add(settle.energy_loss_J);
  if (rec) {
    rec->settle_normal_impulse_Ns = settle.normal_impulse_Ns;
    rec->settle_energy_loss_J = settle.energy_loss_J;
    rec->settle_motor_impulse_Nms = settle.motor_impulse_Nms;
  }
  double eta, eta_rate;
  to_following(time, settle.after, eta, eta_rate);
  choose_slip(c, eta, eta_rate);
  const FollowingMotion f = model.following(c, eta, eta_rate, wall.friction);
  if (f.normal_force_N > -scale.force_guard_N) {
    begin_following(time, eta, eta_rate);
  } else {
    begin_free(time, f.links);
    seg.armed = false;
  }
  return seg.mode;
}

void ClearanceSimulator::Impl::choose_slip(const CrankState& c, double eta, double& eta_rate) {
  if (wall.friction.mu == 0) return;
  const LinkMotion m = model.following_links(c, eta, eta_rate);
  const double v_t = model.clearance_m() * (eta_rate - m.omega4_rad_s);
  if (std::abs(v_t) > wall.slip_arm_speed_m_s) {
    wall.friction.slip = v_t > 0 ? 1 : -1;
    wall.slip_armed = true;
    return;
  }
  // ω4 is affine in η̇: the rate with zero slip solves η̇ = ω4(η̇).
  const double h4 = model.following_links(c, eta, 0.0).omega4_rad_s;
  const double g4 = model.following_links(c, eta, 1.0).omega4_rad_s - h4;
  const double stuck_rate = h4 / (1.0 - g4);
  const FollowingMotion f = model.following(c, eta, stuck_rate, {wall.friction.mu, 0});
  if (std::abs(f.tangential_force_N) <= wall.friction.mu * f.normal_force_N) {
    energy_books.friction_loss.add(energy_of_links(c, m) - energy_of_links(c, f.links));
    eta_rate = stuck_rate;
    wall.friction.slip = 0;
    ++books.diag.sticks;
  } else {
    wall.friction.slip = f.tangential_force_N > 0 ? -1 : 1;
    wall.slip_armed = false;
  }
}

ImpactResult ClearanceSimulator::Impl::resolve_settle(const CrankState& c, const LinkMotion& links) const {
  const BearingState b = model.bearing(c, links);
  // Normal impulse F that zeroes the normal speed: F = v_n / K_nn.
  const ImpactResult probe = apply_impulse(model, c, links, 1.0, 0.0);
  const double knn = probe.normal_speed_before_m_s - probe.normal_speed_after_m_s;
  return apply_impulse(model, c, links, b.normal_speed_m_s / knn, 0.0);
}

void ClearanceSimulator::Impl::handle_impact(double time) {
  OdeState y;
  integ->interpolate(time, y);
  const double work = work_of(y);
  const LinkMotion before = free_links(time, y);
  const CrankState c = crank_at(time);
  const BearingState b = model.bearing(c, before);
  monitor(b);
  check_energy(time, before, work, energy_books.friction_loss.value());
  close_segment(y);
  ImpactRecord rec;
  rec.time_s = absolute(time);
  rec.crank_angle_rad = crank.at(rec.time_s).angle_rad;
  rec.eta_rad = std::atan2(b.normal.y, b.normal.x);
  rec.theta3_rad = std::atan2(before.u3.y, before.u3.x);
  rec.theta4_rad = std::atan2(before.u4.y, before.u4.x);
  rec.result = resolve_impact(model, c, before, law);
  rec.revolution = books.revolutions_on ? revolution_of(time) : 0;
  const bool counted = b.normal_speed_m_s > settings.settle_speed_m_s;
  (counted ? books.diag.impacts : books.diag.touches) += 1;
  if (rec.result.degenerate) ++books.diag.degenerate_impacts;
  if (rec.result.energy_loss_J < -kEnergyGainFraction * scale.energy_J) ++books.diag.energy_gaining_impacts;
  energy_books.work_impulse.add(c.speed_rad_s * rec.result.motor_impulse_Nms);
  energy_books.loss.add(rec.result.energy_loss_J);
  if (books.revolutions_on && counted && rec.revolution >= 0) {
    RevolutionRecord& r = revolution(rec.revolution);
    ++r.impacts;
    r.sum_normal_impulse_Ns += rec.result.normal_impulse_Ns;
  }
  rec.mode_after = after_contact(time, rec.result.after, &rec);
  if (counted) books.impacts.push_back(rec);
}

void ClearanceSimulator::Impl::handle_loss(double time) {
  OdeState y;
  integ->interpolate(time, y);
  const double work = work_of(y);
  const LinkMotion m = model.following_links(crank_at(time), eta_of(y), eta_rate_of(y));
  check_energy(time, m, work, friction_of(y));
  close_segment(y);
  ++books.diag.contact_losses;
  if (books.revolutions_on) {
    const int k = revolution_of(time);
    if (k >= 0) ++revolution(k).contact_losses;
  }
  begin_free(time, m);
  seg.armed = false;
}

void ClearanceSimulator::Impl::handle_following_event(double time) {
  OdeState y;
  integ->interpolate(time, y);
  const CrankState c = crank_at(time);
  double eta = eta_of(y), eta_rate = eta_rate_of(y);
  const FollowingMotion f = model.following(c, eta, eta_rate, wall.friction);
  if (wall.friction.mu == 0 || f.normal_force_N + scale.force_guard_N <= follow_value(f)) return handle_loss(time);
  const double work = work_of(y);
  check_energy(time, f.links, work, friction_of(y));
  close_segment(y);
  if (wall.friction.slip != 0) {
    ++books.diag.slip_stops;
    choose_slip(c, eta, eta_rate);
  } else {
    wall.friction.slip = f.tangential_force_N > 0 ? -1 : 1;  // friction at μ·N cannot hold: slide
    wall.slip_armed = false;
  }
  begin_following(time, eta, eta_rate);
}

}  // namespace fourbar
