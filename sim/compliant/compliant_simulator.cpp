// The compliant simulator's run: preparing the contact law and the scales,
// the starts, the main loop (one BDF step, its books, and at a root of the
// penetration the contact's onset or release and a restart), and the public
// CompliantSimulator API.

#include "sim/compliant/compliant_simulator.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "common/error.hpp"
#include "common/units.hpp"
#include "mechanism/kinetostatics.hpp"
#include "sim/compliant/compliant_state.hpp"

namespace fourbar {

CompliantSimulator::Impl::Impl(const ClearanceModel& m, const CrankMotion& c, const ClearanceSettings& s)
    : model(m),
      crank(c),
      settings(s),
      // A dry bearing leaves the film's quadrature out (the error norm, so the steps, as without it).
      integ(s.tolerance, kCoupled, s.compliant.film.viscosity_Pa_s > 0 ? kStiffSize : std::size_t{kFilmLoss},
            s.compliant.method) {
  const CompliantSettings& k = s.compliant;
  if (!(k.stiffness_N_per_m_n > 0))
    throw RunError("compliant clearance model: no contact stiffness (the scene resolves it; see docs/clearance-model.md)");
  law = {k.stiffness_N_per_m_n, k.exponent, k.damping, s.restitution};
  friction = {s.friction_coefficient, k.friction_stick_speed_m_s, k.friction_slip_speed_m_s};
  hysteresis = hysteresis_factor(k.damping, s.restitution, k.exponent);
  film = k.film;
  if (film.viscosity_Pa_s > 0 && !(film.radius_m > 0 && film.length_m > 0 && film.clearance_m > 0))
    throw RunError("compliant clearance model: a lubricant without the bearing's radius, length or clearance (the "
                   "scene resolves them from the rig)");
}

void CompliantSimulator::Impl::prepare(double t0) {
  const CrankState c = crank.at(t0);
  scale.deviation.speed_rad_s = std::abs(c.speed_rad_s) > 0 ? std::abs(c.speed_rad_s) : 1.0;
  scale.deviation.delta = model.clearance_m() / model.rig().coupler.length_m;
  scale.energy_J = model.energy_scale_J(c.speed_rad_s);
  if (!(scale.energy_J > 0)) scale.energy_J = 1.0;
  scale.force_N = model.force_scale_N(c.speed_rad_s);
  books.rev_dir = c.speed_rad_s < 0 ? -1 : 1;
  books.diag.energy_scale_J = scale.energy_J;
  clock.origin_s = t0;
  start_abs_s = t0;
  t = seg_start = 0;
}

void CompliantSimulator::Impl::restart(double time, const StiffState& y) {
  const double r = clock.rebase(time);
  integ.reset(*this, r, y);
  t = seg_start = r;
}

void CompliantSimulator::Impl::begin(const LinkMotion& links, double approach_speed_m_s) {
  StiffState y = state_of(0.0, links, StiffState{});
  integ.reset(*this, 0.0, y);
  const ContactState k = evaluate(0.0, y);
  if (k.penetration_m > 0) {
    onset(0.0, y);
    ep.phase = approach_speed_m_s > 0 ? 0 : 2;  // a start at rest on the wall is a following phase
    ep.chi_s_per_m = hysteresis / std::max(approach_speed_m_s, settings.compliant.damping_floor_speed_m_s);
    integ.reset(*this, 0.0, y);
  }
  books.diag.energy_start_J = total_energy_J(evaluate(0.0, y), 0.0);
  if (books.revolutions_on) record_start_state(revolution(std::max(0, revolution_of(0.0))));
}

void CompliantSimulator::Impl::advance_to(double absolute_end) {
  for (;;) {
    const double t_end = local(absolute_end);
    if (!(t < t_end)) break;
    if ((t - seg_start) * scale.deviation.speed_rad_s > kCompliantRestartTurns * units::kTwoPi)
      restart(t, state_at(t));
    const StiffIntegrator::Step st = integ.step(t_end);
    const double ta = t, tb = st.end;
    ++books.diag.steps;
    emit_samples(tb);
    emit_statistics(tb);
    track_contact(ta, tb);
    book_interval(ta, tb);
    t = tb;
    if (st.root == 0) continue;
    StiffState y = state_at(tb);
    check_energy(tb, y);
    if (st.root > 0 && !ep.active) onset(tb, y);
    else if (st.root < 0 && ep.active) release(tb, y);
    restart(tb, y);
  }
}

// ---- public API -------------------------------------------------------------

CompliantSimulator::CompliantSimulator(const ClearanceModel& model, const CrankMotion& crank,
                                       const ClearanceSettings& settings)
    : impl_(std::make_unique<Impl>(model, crank, settings)) {}

CompliantSimulator::~CompliantSimulator() = default;

void CompliantSimulator::set_sample_times(std::vector<double> times) {
  impl_->books.sample_times = std::move(times);
  impl_->books.next_sample = 0;
}

void CompliantSimulator::set_revolution_statistics(int samples_per_turn) {
  impl_->books.stats_per_turn = samples_per_turn;
  impl_->books.next_stat = 0;
}

void CompliantSimulator::set_revolution_origin(double crank_angle_rad) {
  impl_->books.revolutions_on = true;
  impl_->books.rev_origin_rad = crank_angle_rad;
}

void CompliantSimulator::start_nominal(double t0) {
  Impl& s = *impl_;
  s.prepare(t0);
  const Rig& rig = s.model.rig();
  // The pin pressed into the wall along the nominal bearing force (as the
  // three-mode start, thesis sec. 3.4), at the static penetration.
  auto force = [&](double time) { return solve_loads(rig, solve_motion(rig, s.crank_at(time))).bearing_N; };
  auto direction = [&](double time) {
    const Vec2 f = force(time);
    return std::atan2(-f.y, -f.x);
  };
  const double eta0 = direction(0.0);
  const double h = 1e-4 / s.scale.deviation.speed_rad_s;
  auto rel = [&](double time) { return eta0 + std::remainder(direction(time) - eta0, units::kTwoPi); };
  const double rate = (rel(-2 * h) - 8 * rel(-h) + 8 * rel(h) - rel(2 * h)) / (12 * h);
  const double f0 = std::sqrt(dot(force(0.0), force(0.0)));
  const double depth = std::pow(f0 / s.law.stiffness, 1.0 / s.law.exponent);
  const ClearanceModel pressed(rig, s.model.clearance_m() + depth);
  s.begin(pressed.following_links(s.crank_at(0.0), eta0, rate), 0.0);
}

void CompliantSimulator::start_free(double t0, const LinkMotion& links) {
  impl_->prepare(t0);
  impl_->begin(links, 0.0);
}

void CompliantSimulator::advance_to(double t_end) { impl_->advance_to(t_end); }

double CompliantSimulator::time() const { return impl_->absolute(impl_->t); }

ContactMode CompliantSimulator::mode() const {
  return impl_->ep.active ? ContactMode::following : ContactMode::free_flight;
}

LinkMotion CompliantSimulator::current_links() { return impl_->evaluate(impl_->t, impl_->state_at(impl_->t)).links; }

const std::vector<ClearanceSample>& CompliantSimulator::samples() const { return impl_->books.samples; }
const std::vector<ImpactRecord>& CompliantSimulator::impacts() const { return impl_->books.impacts; }
const std::vector<RevolutionRecord>& CompliantSimulator::revolutions() const { return impl_->books.revolutions; }

std::string CompliantSimulator::integrator_counters() const {
  const StiffIntegrator::Counters c = impl_->integ.counters();
  return "rhs " + std::to_string(c.rhs) + ", jacobians " + std::to_string(c.jacobians) + ", error-test failures " +
         std::to_string(c.error_failures) + ", Newton failures " + std::to_string(c.newton_failures);
}

ClearanceDiagnostics CompliantSimulator::diagnostics() {
  Impl& s = *impl_;
  const StiffState y = s.state_at(s.t);
  s.check_energy(s.t, y);
  const ContactState k = s.evaluate(s.t, y);
  ClearanceDiagnostics d = s.books.diag;
  d.crank_work_J = y[kWork] * s.scale.energy_J;
  d.impact_loss_J = y[kContactLoss] * s.scale.energy_J;
  d.friction_loss_J = y[kFrictionLoss] * s.scale.energy_J;
  d.film_loss_J = y[kFilmLoss] * s.scale.energy_J;
  d.elastic_energy_end_J = elastic_energy_J(s.law, k.penetration_m);
  d.energy_end_J = s.total_energy_J(k, s.t);
  d.energy_residual_J = d.energy_end_J - d.energy_start_J - d.crank_work_J + d.impact_loss_J + d.friction_loss_J +
                       d.film_loss_J;
  d.steps = s.integ.steps();
  return d;
}

}  // namespace fourbar
