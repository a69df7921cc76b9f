// The linkage simulator's contacts (linkage_simulator_state.hpp): a clearance
// joint's contact opens at its witness's upward root and closes at the
// downward one; in between each step's pairs give the peak force and
// penetration and the end of the impact's first compression–restitution
// cycle (its impulse). Contact and free-flight times per joint.

#include <algorithm>
#include <cmath>

#include "sim/integrate/event_root.hpp"
#include "sim/linkage/linkage_simulator_state.hpp"

namespace fourbar {

std::size_t LinkageSimulator::Impl::slot(int joint) const {
  const auto& js = model.clearance_joints();
  return static_cast<std::size_t>(std::find(js.begin(), js.end(), joint) - js.begin());
}

PairState LinkageSimulator::Impl::pair_of_state(int j, double time, const double* y) const {
  LinkageCoordinates c;
  LinkageWorkspace ws;
  coordinates(time, y, c);
  forward_kinematics(model, c, ws);
  return ws.pair[static_cast<std::size_t>(j)];
}

void LinkageSimulator::Impl::onset(int j, double time, std::vector<double>& y) {
  const PairState ps = pair_of_state(j, time, y.data());
  Episode& e = ep[static_cast<std::size_t>(j)];
  e.active = true;
  e.phase = 0;
  e.chi = model.hysteresis() / std::max(ps.normal_speed_m_s, model.spec().damping_floor_speed_m_s);
  e.onset_abs = absolute(time);
  const std::size_t q = quad(slot(j));
  e.loss_at_onset = y[q] + y[q + 1];
  LinkageContact& r = e.rec;
  r = LinkageContact{};
  r.joint = j;
  r.time_s = e.onset_abs;
  r.crank_angle_rad = crank.at(r.time_s).angle_rad;
  r.eta_rad = std::atan2(ps.normal.y, ps.normal.x);
  r.approach_speed_m_s = ps.normal_speed_m_s;
  r.tangential_speed_m_s = ps.tangential_speed_m_s;
  r.max_penetration_m = std::max(0.0, ps.penetration_m);
  y[q + 2] = y[q + 3] = 0;
}

void LinkageSimulator::Impl::release(int j, double time, const std::vector<double>& y) {
  const PairState ps = pair_of_state(j, time, y.data());
  Episode& e = ep[static_cast<std::size_t>(j)];
  LinkageContact& r = e.rec;
  const std::size_t q = quad(slot(j));
  r.contact_impulse_Ns = y[q + 2] * force / w;
  if (e.phase != 2) r.impact_impulse_Ns = r.contact_impulse_Ns;
  r.energy_loss_J = (y[q] + y[q + 1] - e.loss_at_onset) * energy;
  r.release_time_s = absolute(time);
  r.release_crank_angle_rad = crank.at(r.release_time_s).angle_rad;
  r.release_eta_rad = std::atan2(ps.normal.y, ps.normal.x);
  r.duration_s = r.release_time_s - e.onset_abs;
  r.contact_lost = e.phase == 2;
  r.impact = r.approach_speed_m_s > model.spec().settle_speed_m_s;
  LinkageJointBooks& b = diag.joint[static_cast<std::size_t>(j)];
  (r.impact ? b.impacts : b.touches) += 1;
  if (r.contact_lost) ++b.contact_losses;
  contacts.push_back(r);
  e.active = false;
}

const std::array<PairState, kJoints>& LinkageSimulator::Impl::pairs_at(double time, LinkageWorkspace& ws) {
  LinkageCoordinates c;
  integ.interpolate(time, track_state);
  coordinates(time, track_state.data(), c);
  pair_kinematics(model, c, ws);
  pair_forces(model, chis(ws), ws);
  return ws.pair;
}

void LinkageSimulator::Impl::track(double ta, double tb) {
  bool any = false, impact = false;
  for (int j : model.clearance_joints()) {
    const Episode& e = ep[static_cast<std::size_t>(j)];
    any = any || e.active;
    impact = impact || (e.active && e.phase < 2);
  }
  if (!any || !(tb > ta)) return;
  LinkageWorkspace mid_ws, end_ws;
  const std::array<PairState, kJoints>* mid = impact ? &pairs_at(0.5 * (ta + tb), mid_ws) : nullptr;
  const std::array<PairState, kJoints>& end = pairs_at(tb, end_ws);
  for (int j : model.clearance_joints()) {
    const auto ju = static_cast<std::size_t>(j);
    Episode& e = ep[ju];
    if (!e.active) continue;
    LinkageJointBooks& b = diag.joint[ju];
    for (const PairState* ps : {mid ? &(*mid)[ju] : &end[ju], &end[ju]}) {
      e.rec.peak_force_N = std::max(e.rec.peak_force_N, ps->normal_force_N);
      e.rec.max_penetration_m = std::max(e.rec.max_penetration_m, ps->penetration_m);
      b.max_penetration_m = std::max(b.max_penetration_m, ps->penetration_m);
    }
    if (e.phase < 2) {
      const double rate_b = end[ju].normal_speed_m_s;
      if (e.phase == 0 && rate_b < 0) e.phase = 1;
      if (e.phase == 1 && rate_b > 0) {
        auto rate = [&](double x) {
          LinkageWorkspace ws;
          return pairs_at(x, ws)[ju].normal_speed_m_s;
        };
        const double rate_a = rate(ta);
        const double tc = rate_a < 0 ? locate_root(rate, ta, tb, rate_a, rate_b) : ta;
        e.rec.impact_impulse_Ns = state_at(tc)[quad(slot(j)) + 2] * force / w;
        e.phase = 2;
      }
    }
  }
}

void LinkageSimulator::Impl::book_interval(double ta, double tb) {
  for (int j : model.clearance_joints()) {
    LinkageJointBooks& b = diag.joint[static_cast<std::size_t>(j)];
    (ep[static_cast<std::size_t>(j)].active ? b.contact_time_s : b.free_time_s) += tb - ta;
  }
}

}  // namespace fourbar
