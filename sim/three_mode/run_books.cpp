// The clearance simulator's books: revolution records and their per-turn
// α3 statistics, the requested samples, the contact-circle and penetration
// monitors, the energy balance checks and the guard against piled-up events.

#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.hpp"
#include "common/units.hpp"
#include "mechanism/kinematics.hpp"
#include "sim/three_mode/simulator_state.hpp"

namespace fourbar {

double ClearanceSimulator::Impl::energy(double time, const LinkMotion& m) const {
  return energy_of_links(crank_at(time), m);
}

double ClearanceSimulator::Impl::energy_of_links(const CrankState& c, const LinkMotion& m) const {
  return model.kinetic_energy_J(c, m) + model.potential_energy_J(c, m);
}

int ClearanceSimulator::Impl::revolution_of(double time) const { return books.revolution_of(crank, clock, time); }

double ClearanceSimulator::Impl::revolution_start(int k) const { return books.revolution_start(crank, k); }

RevolutionRecord& ClearanceSimulator::Impl::revolution(int k) { return books.revolution(crank, k); }

void ClearanceSimulator::Impl::book_interval(double ta, double tb) {
  const bool following = seg.mode == ContactMode::following;
  books.book_interval(crank, clock, ta, tb, following, [this](RevolutionRecord& r) { record_start_state(r); });
  if (following && wall.friction.mu > 0 && wall.friction.slip == 0) books.diag.time_stuck_s += tb - ta;
}

void ClearanceSimulator::Impl::record_start_state(RevolutionRecord& r) {
  OdeState y;
  const double start = local(r.start_time_s);
  integ->interpolate(start, y);
  const LinkMotion m = links_at(start, y);
  const OdeState f = free_state(start, m);
  r.start_state = {f[0], f[1], f[2], f[3]};
  r.start_mode = seg.mode;
  r.has_start_state = true;
}

void ClearanceSimulator::Impl::after_start() {
  OdeState y;
  integ->interpolate(seg.t, y);
  books.diag.energy_start_J = energy(seg.t, links_at(seg.t, y));
  if (books.revolutions_on) record_start_state(revolution(std::max(0, revolution_of(seg.t))));
}

double ClearanceSimulator::Impl::stat_time(long long i) const { return books.stat_time(crank, clock, i); }

void ClearanceSimulator::Impl::emit_statistics(double up_to) {
  books.emit_statistics(crank, clock, up_to, [this](double ts) -> std::optional<double> {
    if (ts < seg.start) return std::nullopt;  // before the start
    OdeState y;
    integ->interpolate(ts, y);
    const CrankState c = crank_at(ts);
    double a3, a4;
    if (seg.mode == ContactMode::following) {
      a3 = model.following(c, eta_of(y), eta_rate_of(y), wall.friction).alpha3_rad_s2;
    } else {
      model.free_accelerations(c, free_links(ts, y), a3, a4);
    }
    return a3 - solve_motion(model.rig(), c).alpha3_rad_s2;
  });
}

void ClearanceSimulator::Impl::emit_samples(double up_to) {
  books.emit_samples(clock, up_to, [this](double absolute_time) { return sample(absolute_time); });
}

ClearanceSample ClearanceSimulator::Impl::sample(double absolute_time) {
  const double time = local(absolute_time);
  OdeState y;
  integ->interpolate(time, y);
  ClearanceSample s;
  s.time_s = absolute_time;
  s.crank = crank_at(time);
  s.mode = seg.mode;
  if (seg.mode == ContactMode::following) {
    const FollowingMotion f = model.following(s.crank, eta_of(y), eta_rate_of(y), wall.friction);
    s.links = f.links;
    s.alpha3_rad_s2 = f.alpha3_rad_s2;
    s.alpha4_rad_s2 = f.alpha4_rad_s2;
    s.bearing_force_N = f.pin_force();
    s.normal_force_N = f.normal_force_N;
    s.crank_torque_Nm = f.crank_torque_Nm;
  } else {
    s.links = free_links(time, y);
    model.free_accelerations(s.crank, s.links, s.alpha3_rad_s2, s.alpha4_rad_s2);
    s.crank_torque_Nm = model.crank_torque_Nm(s.crank, s.links, s.alpha3_rad_s2, {});
  }
  const BearingState b = model.bearing(s.crank, s.links);
  s.gap_m = b.gap_m;
  s.penetration_m = std::max(0.0, -b.gap_m);
  s.eta_rad = std::atan2(b.normal.y, b.normal.x);
  s.kinetic_energy_J = model.kinetic_energy_J(s.crank, s.links);
  s.potential_energy_J = model.potential_energy_J(s.crank, s.links);
  monitor(b);
  s.crank.angle_rad = crank.at(absolute_time).angle_rad;
  return s;
}

void ClearanceSimulator::Impl::monitor(const BearingState& b) {
  const double xi = model.clearance_m();
  if (seg.mode == ContactMode::following) {
    books.diag.max_contact_circle_error = std::max(books.diag.max_contact_circle_error, std::abs(b.gap_m) / xi);
    books.diag.max_contact_normal_speed_m_s =
        std::max(books.diag.max_contact_normal_speed_m_s, std::abs(b.normal_speed_m_s));
  } else {
    books.diag.max_penetration = std::max(books.diag.max_penetration, -b.gap_m / xi);
  }
}

void ClearanceSimulator::Impl::check_energy(double time, const LinkMotion& m, double work, double friction) {
  const double r = energy(time, m) - books.diag.energy_start_J - work - energy_books.work_impulse.value() +
                   energy_books.loss.value() + friction;
  books.diag.max_energy_residual_J = std::max(books.diag.max_energy_residual_J, std::abs(r));
}

void ClearanceSimulator::Impl::zeno_guard(double time) {
  zeno.count = time - zeno.last_event < kZenoSpan_s ? zeno.count + 1 : 0;
  zeno.last_event = time;
  if (zeno.count > kZenoLimit)
    throw RunError("clearance model: events pile up at t = " + std::to_string(absolute(time)) +
                   " s without progress; raise [clearance] settle_speed_mm_s");
}

}  // namespace fourbar
