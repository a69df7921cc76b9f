// The compliant simulator's books: each contact from onset to release (peak
// force, penetration, duration, impulses, loss), the revolution records and
// their per-turn α3 statistics, the requested samples and the energy check.

#include <algorithm>
#include <cmath>

#include <boost/math/tools/minima.hpp>

#include "common/units.hpp"
#include "sim/compliant/compliant_state.hpp"
#include "sim/integrate/event_root.hpp"

namespace fourbar {

int CompliantSimulator::Impl::revolution_of(double time) const { return books.revolution_of(crank, clock, time); }

double CompliantSimulator::Impl::revolution_start(int k) const { return books.revolution_start(crank, k); }

RevolutionRecord& CompliantSimulator::Impl::revolution(int k) { return books.revolution(crank, k); }

void CompliantSimulator::Impl::book_interval(double ta, double tb) {
  books.book_interval(crank, clock, ta, tb, ep.active, [this](RevolutionRecord& r) { record_start_state(r); });
}

void CompliantSimulator::Impl::record_start_state(RevolutionRecord& r) {
  const StiffState y = state_at(local(r.start_time_s));
  r.start_state = {y[0], y[1], y[2], y[3]};
  r.start_mode = ep.active ? ContactMode::following : ContactMode::free_flight;
  r.has_start_state = true;
}

double CompliantSimulator::Impl::stat_time(long long i) const { return books.stat_time(crank, clock, i); }

void CompliantSimulator::Impl::emit_statistics(double up_to) {
  books.emit_statistics(crank, clock, up_to, [this](double ts) -> std::optional<double> {
    if (absolute(ts) < start_abs_s) return std::nullopt;  // before the start
    const ContactState k = evaluate(ts, state_at(ts));
    return k.alpha3_rad_s2 - k.nominal.alpha3_rad_s2;
  });
}

void CompliantSimulator::Impl::emit_samples(double up_to) {
  books.emit_samples(clock, up_to, [this](double absolute_time) { return sample(absolute_time); });
}

ClearanceSample CompliantSimulator::Impl::sample(double absolute_time) {
  const double time = local(absolute_time);
  const ContactState k = evaluate(time, state_at(time));
  ClearanceSample s;
  s.time_s = absolute_time;
  s.crank = crank_at(time);
  s.mode = k.penetration_m > 0 ? ContactMode::following : ContactMode::free_flight;
  s.links = k.links;
  s.alpha3_rad_s2 = k.alpha3_rad_s2;
  s.alpha4_rad_s2 = k.alpha4_rad_s2;
  s.bearing_force_N = k.pin_force_N;
  s.normal_force_N = k.normal_force_N;
  s.crank_torque_Nm = k.crank_torque_Nm;
  s.gap_m = k.bearing.gap_m;
  s.penetration_m = std::max(0.0, k.penetration_m);
  s.eta_rad = std::atan2(k.bearing.normal.y, k.bearing.normal.x);
  s.kinetic_energy_J = model.kinetic_energy_J(s.crank, s.links);
  s.potential_energy_J = model.potential_energy_J(s.crank, s.links);
  s.crank.angle_rad = crank.at(absolute_time).angle_rad;
  return s;
}

void CompliantSimulator::Impl::track_contact(double ta, double tb) {
  if (!ep.active || !(tb > ta)) return;
  const double w = scale.deviation.speed_rad_s;
  auto at = [&](double time) {
    const ContactState k = evaluate_contact(time, state_at(time));
    books.diag.max_penetration = std::max(books.diag.max_penetration, k.penetration_m / model.clearance_m());
    ep.rec.max_penetration_m = std::max(ep.rec.max_penetration_m, k.penetration_m);
    return k;
  };
  // The step's middle and end; a middle above both ends and above the peak
  // so far is refined by Brent's method on the dense output (the step's
  // start was the previous step's end).
  const double tm = 0.5 * (ta + tb);
  const ContactState km = at(tm), kb = at(tb);
  double best = std::max(km.normal_force_N, kb.normal_force_N);
  if (km.normal_force_N > kb.normal_force_N && km.normal_force_N > ep.rec.peak_force_N) {
    const auto r = boost::math::tools::brent_find_minima([&](double x) { return -at(x).normal_force_N; }, ta, tb, 40);
    best = std::max(best, -r.second);
  }
  ep.rec.peak_force_N = std::max(ep.rec.peak_force_N, best);
  // First cycle: compression until δ̇ < 0, restitution until δ̇ > 0 again
  // (then the pin stays on the wall) or the release (a root of δ).
  if (ep.phase < 2) {
    const double rate_b = kb.bearing.normal_speed_m_s;
    if (ep.phase == 0 && rate_b < 0) ep.phase = 1;
    if (ep.phase == 1 && rate_b > 0) {
      auto rate = [&](double x) { return evaluate_contact(x, state_at(x)).bearing.normal_speed_m_s; };
      const double rate_a = rate(ta);
      const double tc = rate_a < 0 ? locate_root(rate, ta, tb, rate_a, rate_b) : ta;
      ep.impact_impulse_Ns = state_at(tc)[kImpulseN] * scale.force_N / w;
      ep.phase = 2;
    }
  }
}

void CompliantSimulator::Impl::onset(double time, StiffState& y) {
  const ContactState k = evaluate(time, y);
  ep.active = true;
  ep.phase = 0;
  ep.impact_impulse_Ns = 0;
  ep.chi_s_per_m = hysteresis / std::max(k.bearing.normal_speed_m_s, settings.compliant.damping_floor_speed_m_s);
  ep.onset_abs_s = absolute(time);
  ep.loss_at_onset = y[kContactLoss] + y[kFrictionLoss];
  ImpactRecord& r = ep.rec;
  r = ImpactRecord{};
  r.time_s = ep.onset_abs_s;
  r.crank_angle_rad = crank.at(r.time_s).angle_rad;
  r.eta_rad = std::atan2(k.bearing.normal.y, k.bearing.normal.x);
  r.theta3_rad = std::atan2(k.links.u3.y, k.links.u3.x);
  r.theta4_rad = std::atan2(k.links.u4.y, k.links.u4.x);
  r.revolution = books.revolutions_on ? revolution_of(time) : 0;
  r.result.normal_speed_before_m_s = k.bearing.normal_speed_m_s;
  r.result.tangential_speed_before_m_s = k.bearing.tangential_speed_m_s;
  r.max_penetration_m = std::max(0.0, k.penetration_m);
  y[kImpulseN] = y[kImpulseT] = 0;
}

void CompliantSimulator::Impl::release(double time, const StiffState& y) {
  const ContactState k = evaluate(time, y);
  ImpactRecord& r = ep.rec;
  const double w = scale.deviation.speed_rad_s;
  const double impulse = y[kImpulseN] * scale.force_N / w;
  r.contact_impulse_Ns = impulse;
  r.result.normal_impulse_Ns = ep.phase == 2 ? ep.impact_impulse_Ns : impulse;
  r.result.tangential_impulse_Ns = y[kImpulseT] * scale.force_N / w;
  r.result.after = k.links;
  r.result.normal_speed_after_m_s = k.bearing.normal_speed_m_s;
  r.result.tangential_speed_after_m_s = k.bearing.tangential_speed_m_s;
  r.result.energy_loss_J = (y[kContactLoss] + y[kFrictionLoss] - ep.loss_at_onset) * scale.energy_J;
  r.contact_duration_s = absolute(time) - ep.onset_abs_s;
  r.mode_after = ep.phase == 2 ? ContactMode::following : ContactMode::free_flight;
  // Every contact begins with an impact (counted when faster than the settle
  // speed, with its first-cycle impulse); a contact that outlived its first
  // cycle ends in a contact loss.
  const bool counted = r.result.normal_speed_before_m_s > settings.settle_speed_m_s;
  (counted ? books.diag.impacts : books.diag.touches) += 1;
  if (books.revolutions_on && counted && r.revolution >= 0) {
    RevolutionRecord& rev = revolution(r.revolution);
    ++rev.impacts;
    rev.sum_normal_impulse_Ns += r.result.normal_impulse_Ns;
  }
  if (ep.phase == 2) {
    ++books.diag.contact_losses;
    if (books.revolutions_on) {
      const int k_rev = revolution_of(time);
      if (k_rev >= 0) ++revolution(k_rev).contact_losses;
    }
  }
  books.impacts.push_back(r);
  ep.active = false;
}

void CompliantSimulator::Impl::check_energy(double time, const StiffState& y) {
  const ContactState k = evaluate(time, y);
  const double r = total_energy_J(k, time) - books.diag.energy_start_J -
                   (y[kWork] - y[kContactLoss] - y[kFrictionLoss] - y[kFilmLoss]) * scale.energy_J;
  books.diag.max_energy_residual_J = std::max(books.diag.max_energy_residual_J, std::abs(r));
}

}  // namespace fourbar
