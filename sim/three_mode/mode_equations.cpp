// The clearance simulator's two integrated states and their equations: the
// conversion between a link motion and the scaled state of each mode
// (following: the clearance-link angle η; free flight: the deviations δ3, δ4
// from the nominal mechanism), the work and friction integrals that ride
// along, and the two ODE systems handed to the integrator.

#include <algorithm>
#include <cmath>

#include "mechanism/kinematics.hpp"
#include "sim/three_mode/deviation_state.hpp"
#include "sim/three_mode/simulator_state.hpp"

namespace fourbar {

// ---- state conversion -------------------------------------------------

LinkMotion ClearanceSimulator::Impl::free_links(double time, const OdeState& y, NominalMotion* nominal_out) const {
  const NominalMotion nm = solve_motion(model.rig(), crank_at(time));
  const LinkMotion m = deviation_links(nm, {scale.delta, scale.speed_rad_s}, y.data());
  if (nominal_out) *nominal_out = nm;
  return m;
}

OdeState ClearanceSimulator::Impl::free_state(double time, const LinkMotion& m) const {
  const NominalMotion nm = solve_motion(model.rig(), crank_at(time));
  OdeState y{};
  deviation_state(nm, {scale.delta, scale.speed_rad_s}, m, y.data());
  y[4] = energy_books.work_closed.value() / scale.energy_J;  // crank work, from work_seed
  return y;
}

double ClearanceSimulator::Impl::segment_work(const OdeState& y) const {
  return ((seg.mode == ContactMode::following ? y[2] : y[4]) - energy_books.work_seed) * scale.energy_J;
}

double ClearanceSimulator::Impl::segment_friction(const OdeState& y) const {
  return seg.mode == ContactMode::following ? y[3] * scale.energy_J : 0.0;
}

double ClearanceSimulator::Impl::work_of(const OdeState& y) const {
  return energy_books.work_closed.value() + segment_work(y);
}

double ClearanceSimulator::Impl::friction_of(const OdeState& y) const {
  return energy_books.friction_loss.value() + segment_friction(y);
}

void ClearanceSimulator::Impl::close_segment(const OdeState& y) {
  energy_books.work_closed.add(segment_work(y));
  energy_books.friction_loss.add(segment_friction(y));
}

LinkMotion ClearanceSimulator::Impl::links_at(double time, const OdeState& y) const {
  if (seg.mode == ContactMode::following) return model.following_links(crank_at(time), eta_of(y), eta_rate_of(y));
  return free_links(time, y);
}

void ClearanceSimulator::Impl::to_following(double time, const LinkMotion& m, double& eta, double& eta_rate) const {
  const CrankState c = crank_at(time);
  const BearingState b = model.bearing(c, m);
  const Rig& rig = model.rig();
  const Vec2 u2 = unit(c.angle_rad);
  const Vec2 e_dot = rig.crank.length_m * c.speed_rad_s * u2.perp() + rig.coupler.length_m * m.omega3_rad_s * m.u3.perp() -
                     rig.rocker.length_m * m.omega4_rad_s * m.u4.perp();
  eta = std::atan2(b.normal.y, b.normal.x);
  eta_rate = dot(e_dot, b.normal.perp()) / model.clearance_m();
}

// ---- the two ODE systems ---------------------------------------------

void ClearanceSimulator::Impl::FollowingOde::rhs(double time, const OdeState& y, OdeState& dy) {
  const CrankState c = s->crank_at(time);
  const FollowingMotion f = s->model.following(c, s->eta_of(y), s->eta_rate_of(y), s->wall.friction);
  const double w = s->follow_value(f);
  w_min = std::min(w_min, w);
  w_max = std::max(w_max, w);
  dy[0] = s->eta_rate_of(y);
  dy[1] = f.eta_accel_rad_s2 / s->scale.speed_rad_s;
  dy[2] = f.crank_torque_Nm * c.speed_rad_s / s->scale.energy_J;
  dy[3] = s->wall.friction.mu > 0 ? -f.tangential_force_N * f.slip_speed_m_s / s->scale.energy_J : 0.0;
  dy[4] = 0;
}

void ClearanceSimulator::Impl::FreeOde::rhs(double time, const OdeState& y, OdeState& dy) {
  const CrankState c = s->crank_at(time);
  NominalMotion nm;
  const LinkMotion m = s->free_links(time, y, &nm);
  const double pen = -s->model.bearing(c, nm.pose.u2, m).gap_m;
  pen_min = std::min(pen_min, pen);
  pen_max = std::max(pen_max, pen);
  double a3, a4;
  s->model.free_accelerations(c, nm.pose.u2, m, a3, a4);
  const double rate_scale = s->scale.delta * s->scale.speed_rad_s;
  dy[0] = y[2] * s->scale.speed_rad_s;
  dy[1] = y[3] * s->scale.speed_rad_s;
  dy[2] = (a3 - nm.alpha3_rad_s2) / rate_scale;
  dy[3] = (a4 - nm.alpha4_rad_s2) / rate_scale;
  dy[4] = s->model.crank_torque_Nm(c, nm.pose.u2, m, a3, {}) * c.speed_rad_s / s->scale.energy_J;
}

}  // namespace fourbar
