// The compliant simulator's equations: the contact at one state (bearing
// geometry, normal and friction force, accelerations, motor torque), the
// ODE with its quadratures, the root witness, and the state conversion.

#include <algorithm>
#include <cmath>

#include "sim/compliant/compliant_state.hpp"

namespace fourbar {

const NominalMotion& CompliantSimulator::Impl::nominal_at(double time) const {
  NominalCache& cache = nominal_cache;
  for (const NominalCache::Entry& e : cache.entries)
    if (e.valid && e.time == time && e.origin_s == clock.origin_s) return e.motion;
  NominalCache::Entry& e = cache.entries[cache.next];
  cache.next = (cache.next + 1) % cache.entries.size();
  e = {clock.origin_s, time, true, solve_motion(model.rig(), crank_at(time))};
  return e.motion;
}

ContactState CompliantSimulator::Impl::evaluate_contact(double time, const StiffState& y) const {
  ContactState k;
  k.nominal = nominal_at(time);
  k.links = deviation_links(k.nominal, scale.deviation, y.data());
  k.bearing = model.bearing(k.nominal.crank, k.nominal.pose.u2, k.links);
  k.penetration_m = -k.bearing.gap_m;
  if (k.penetration_m > 0) {
    // A contact whose onset was not seen (entered and left inside one step)
    // takes its damping from the present approach speed.
    const double chi = ep.active ? ep.chi_s_per_m
                                 : hysteresis / std::max(k.bearing.normal_speed_m_s,
                                                         settings.compliant.damping_floor_speed_m_s);
    k.normal_force_N = normal_force_N(law, k.penetration_m, k.bearing.normal_speed_m_s, chi);
    k.friction_force_N = friction_force_N(friction, k.normal_force_N, k.bearing.tangential_speed_m_s);
  }
  return k;
}

ContactState CompliantSimulator::Impl::evaluate(double time, const StiffState& y) const {
  ContactState k = evaluate_contact(time, y);
  const CrankState& c = k.nominal.crank;
  const Vec2 u2 = k.nominal.pose.u2;
  if (film.viscosity_Pa_s > 0) {
    // ε, ε̇ and ε·ω̄ = ε·(ω3 + ω4) − 2·ε·φ̇ with |e|·φ̇ = v_t + ω4·|e| (film_force.hpp).
    const double xi = model.clearance_m();
    const double eps = (xi - k.bearing.gap_m) / xi;
    const double whirl = eps * (k.links.omega3_rad_s - k.links.omega4_rad_s) - 2.0 * k.bearing.tangential_speed_m_s / xi;
    k.film = film_force(film, eps, k.bearing.normal_speed_m_s / xi, whirl);
  }
  k.pin_force_N = (k.film.radial_N - k.normal_force_N) * k.bearing.normal +
                  (k.friction_force_N + k.film.tangential_N) * k.bearing.normal.perp();
  model.forced_accelerations(c, u2, k.links, k.pin_force_N, k.alpha3_rad_s2, k.alpha4_rad_s2);
  k.crank_torque_Nm = model.crank_torque_Nm(c, u2, k.links, k.alpha3_rad_s2, k.pin_force_N);
  return k;
}

void CompliantSimulator::Impl::rhs(double time, const StiffState& y, StiffState& dy) {
  const ContactState k = evaluate(time, y);
  const double w = scale.deviation.speed_rad_s;
  const double rate_scale = scale.deviation.delta * w;
  dy[0] = y[2] * w;
  dy[1] = y[3] * w;
  dy[2] = (k.alpha3_rad_s2 - k.nominal.alpha3_rad_s2) / rate_scale;
  dy[3] = (k.alpha4_rad_s2 - k.nominal.alpha4_rad_s2) / rate_scale;
  dy[kWork] = k.crank_torque_Nm * k.nominal.crank.speed_rad_s / scale.energy_J;
  // Damping dissipation (F_n − K·δⁿ)·δ̇ ≥ 0 and friction dissipation −F_t·v_t ≥ 0.
  const double elastic = elastic_force_N(law, k.penetration_m);
  dy[kContactLoss] = k.penetration_m > 0
                         ? (k.normal_force_N - elastic) * k.bearing.normal_speed_m_s / scale.energy_J
                         : 0.0;
  dy[kFrictionLoss] = -k.friction_force_N * k.bearing.tangential_speed_m_s / scale.energy_J;
  dy[kImpulseN] = k.normal_force_N * w / scale.force_N;
  dy[kImpulseT] = k.friction_force_N * w / scale.force_N;
  dy[kFilmLoss] = -(k.film.radial_N * k.bearing.normal_speed_m_s + k.film.tangential_N * k.bearing.tangential_speed_m_s) /
                  scale.energy_J;
}

double CompliantSimulator::Impl::witness(double time, const StiffState& y) {
  const NominalMotion& nm = nominal_at(time);
  const LinkMotion m = deviation_links(nm, scale.deviation, y.data());
  return -model.bearing(nm.crank, nm.pose.u2, m).gap_m / model.clearance_m();
}

StiffState CompliantSimulator::Impl::state_of(double time, const LinkMotion& m, const StiffState& q) const {
  StiffState y = q;
  deviation_state(nominal_at(time), scale.deviation, m, y.data());
  return y;
}

StiffState CompliantSimulator::Impl::state_at(double time) {
  StiffState y;
  integ.interpolate(time, y);
  return y;
}

double CompliantSimulator::Impl::mechanical_energy_J(double time, const LinkMotion& m) const {
  const CrankState c = crank_at(time);
  return model.kinetic_energy_J(c, m) + model.potential_energy_J(c, m);
}

double CompliantSimulator::Impl::total_energy_J(const ContactState& k, double time) const {
  return mechanical_energy_J(time, k.links) + elastic_energy_J(law, k.penetration_m);
}

}  // namespace fourbar
