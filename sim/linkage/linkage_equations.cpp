// The linkage simulator's equations (linkage_simulator_state.hpp): the
// scaled state to coordinates (the angles as deviations from the nominal
// motion, offsets and modes by their scales), the right-hand side with its
// quadratures (crank work, each joint's losses and impulses, modal damping),
// the contact witnesses, and the energy books' residual.

#include <algorithm>
#include <cmath>

#include "sim/linkage/linkage_simulator_state.hpp"

namespace fourbar {

namespace {

Vec2 rotated(Vec2 u, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * u.x - s * u.y, s * u.x + c * u.y};
}

}  // namespace

const NominalMotion& LinkageSimulator::Impl::nominal_at(double time) const {
  for (const Entry& e : cache)
    if (e.valid && e.time == time && e.origin == clock.origin_s) return e.motion;
  Entry& e = cache[next_entry];
  next_entry = (next_entry + 1) % cache.size();
  e = {clock.origin_s, time, true, solve_motion(model.rig(), crank.at_local(clock.origin_s, time))};
  return e.motion;
}

void LinkageSimulator::Impl::coordinates(double time, const double* y, LinkageCoordinates& c) const {
  const NominalMotion& nm = nominal_at(time);
  c.crank = nm.crank;
  c.u2 = nm.pose.u2;
  c.u = {rotated(nm.pose.u3, y[0] * delta), rotated(nm.pose.u4, y[1] * delta)};
  c.q_offsets = ZVec::Zero(n);
  c.z_rate = ZVec::Zero(n + 1);
  c.z_rate(0) = nm.omega3_rad_s + y[n] * delta * w;
  c.z_rate(1) = nm.omega4_rad_s + y[n + 1] * delta * w;
  for (int i = 2; i < n; ++i) {
    c.q_offsets(i) = y[i] * pos_scale[static_cast<std::size_t>(i)];
    c.z_rate(i) = y[n + i] * rate_scale[static_cast<std::size_t>(i)];
  }
  c.z_rate(n) = nm.crank.speed_rad_s;
  if (model.all_ideal()) {
    c.prescribed.alpha3_rad_s2 = nm.alpha3_rad_s2;
    c.prescribed.alpha4_rad_s2 = nm.alpha4_rad_s2;
    const NominalMotion unit = solve_motion(model.rig(), CrankState{nm.crank.angle_rad, 1.0, 0.0});
    c.prescribed.ratio3 = unit.omega3_rad_s;
    c.prescribed.ratio4 = unit.omega4_rad_s;
  }
}

std::array<double, kJoints> LinkageSimulator::Impl::chis(const LinkageWorkspace& ws) const {
  std::array<double, kJoints> chi{};
  for (int j : model.clearance_joints()) {
    const auto ju = static_cast<std::size_t>(j);
    chi[ju] = ep[ju].active ? ep[ju].chi
                            : model.hysteresis() / std::max(ws.pair[ju].normal_speed_m_s,
                                                            model.spec().damping_floor_speed_m_s);
  }
  return chi;
}

void LinkageSimulator::Impl::evaluate(double time, const double* y, LinkageCoordinates& c, LinkageWorkspace& ws) const {
  coordinates(time, y, c);
  forward_kinematics(model, c, ws);
  pair_forces(model, chis(ws), ws);
  solve_accelerations(model, c, ws);
}

void LinkageSimulator::Impl::rhs(double time, const double* y, double* dy) {
  LinkageCoordinates c;
  LinkageWorkspace& ws = rhs_ws;
  evaluate(time, y, c, ws);
  const NominalMotion& nm = nominal_at(time);
  dy[0] = y[n] * w;
  dy[1] = y[n + 1] * w;
  for (int i = 2; i < n; ++i)
    dy[i] = y[n + i] * (rate_scale[static_cast<std::size_t>(i)] / pos_scale[static_cast<std::size_t>(i)]);
  dy[n] = (ws.z_accel(0) - nm.alpha3_rad_s2) / (delta * w);
  dy[n + 1] = (ws.z_accel(1) - nm.alpha4_rad_s2) / (delta * w);
  for (int i = 2; i < n; ++i) dy[n + i] = ws.z_accel(i) / rate_scale[static_cast<std::size_t>(i)];
  dy[work_index()] = ws.crank_torque_Nm * c.crank.speed_rad_s / energy;
  const auto& joints = model.clearance_joints();
  for (std::size_t k = 0; k < joints.size(); ++k) {
    const PairState& ps = ws.pair[static_cast<std::size_t>(joints[k])];
    double* q = dy + quad(k);
    q[0] = ps.penetration_m > 0 ? ps.damping_power_W / energy : 0.0;
    q[1] = ps.friction_power_W / energy;
    q[2] = ps.normal_force_N * w / force;
    q[3] = ps.friction_force_N * w / force;
    if (!dry) q[4] = ps.film_power_W / energy;
  }
  if (model.any_elastic()) dy[modal_loss_index()] = ws.modal_damping_power_W / energy;
}

void LinkageSimulator::Impl::witnesses(double time, const double* y, double* g) {
  LinkageCoordinates c;
  coordinates(time, y, c);
  const std::array<double, kJoints> pen = pair_penetrations(model, c);
  const auto& joints = model.clearance_joints();
  for (std::size_t k = 0; k < joints.size(); ++k)
    g[k] = pen[static_cast<std::size_t>(joints[k])] / model.joint(joints[k]).clearance_m;
}

std::vector<double> LinkageSimulator::Impl::state_at(double time) {
  std::vector<double> y;
  integ.interpolate(time, y);
  return y;
}

double LinkageSimulator::Impl::total_energy(const LinkageCoordinates& c, const LinkageWorkspace& ws) const {
  double e = kinetic_energy_J(ws, c) + potential_energy_J(model, ws, c) + ws.strain_energy_J;
  for (int j : model.clearance_joints()) e += ws.pair[static_cast<std::size_t>(j)].elastic_energy_J;
  return e;
}

double LinkageSimulator::Impl::losses(const std::vector<double>& y) const {
  double d = 0;
  for (std::size_t k = 0; k < model.clearance_joints().size(); ++k) {
    d += y[quad(k)] + y[quad(k) + 1];
    if (!dry) d += y[quad(k) + 4];
  }
  if (model.any_elastic()) d += y[modal_loss_index()];
  return d;
}

void LinkageSimulator::Impl::check_energy(double time, const std::vector<double>& y) {
  LinkageCoordinates c;
  LinkageWorkspace ws;
  evaluate(time, y.data(), c, ws);
  const double r = total_energy(c, ws) - diag.energy_start_J - (y[work_index()] - losses(y)) * energy;
  diag.max_energy_residual_J = std::max(diag.max_energy_residual_J, std::abs(r));
}

}  // namespace fourbar
