// The linkage simulator (linkage_simulator_state.hpp lists its files): the
// start from a linkage state, samples at the requested times, the main loop
// (a step, its samples and contact books, the contact events at the
// witnesses' roots, a restart after each), and the public API.

#include "sim/linkage/linkage_simulator.hpp"

#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "common/units.hpp"
#include "sim/linkage/linkage_simulator_state.hpp"

namespace fourbar {

namespace {

double angle_between(Vec2 a, Vec2 b) { return std::atan2(cross(a, b), dot(a, b)); }
/// A segment longer than this many turns restarts at a new time origin (as the compliant model).
constexpr double kLinkageRestartTurns = 64;

}  // namespace

LinkageSimulator::Impl::Impl(const LinkageModel& m, const CrankMotion& c)
    : model(m),
      crank(c),
      n(m.coordinates()),
      dry(m.spec().film.viscosity_Pa_s <= 0),
      per_joint(dry ? 4 : 5),
      size(static_cast<std::size_t>(2 * n + 1) + m.clearance_joints().size() * static_cast<std::size_t>(per_joint) +
           (m.any_elastic() ? 1U : 0U)),
      integ(m.spec().tolerance, size, static_cast<std::size_t>(2 * n), m.clearance_joints().size(), m.spec().method) {}

void LinkageSimulator::Impl::prepare(double t0) {
  scales = linkage_scales(model, crank.at(t0));
  std::tie(w, delta, energy, force) = std::tie(scales.w, scales.delta, scales.energy, scales.force);
  std::tie(pos_scale, rate_scale) = std::tie(scales.position, scales.rate);
  diag.energy_scale_J = energy;
  clock.origin_s = t0;
  t = seg_start = 0;
}

void LinkageSimulator::Impl::begin(const LinkageStart& s) {
  std::vector<double> y(size, 0.0);
  const NominalMotion& nm = nominal_at(0.0);
  if (!model.all_ideal()) {
    y[0] = angle_between(nm.pose.u3, s.u3) / delta;
    y[1] = angle_between(nm.pose.u4, s.u4) / delta;
    y[static_cast<std::size_t>(n)] = (s.omega3_rad_s - nm.omega3_rad_s) / (delta * w);
    y[static_cast<std::size_t>(n + 1)] = (s.omega4_rad_s - nm.omega4_rad_s) / (delta * w);
  }
  scale_modal_start(model, scales, s.modal_m, s.modal_rate_m_s, y);
  for (const Placement& pl : model.placements()) {
    if (pl.offset_index < 0) continue;
    const auto k = static_cast<std::size_t>(pl.offset_index);
    const auto ju = static_cast<std::size_t>(pl.joint);
    const Vec2 d = pl.offset_sign * s.eccentricity_m[ju], dd = pl.offset_sign * s.eccentricity_rate_m_s[ju];
    y[k] = d.x / pos_scale[k];
    y[k + 1] = d.y / pos_scale[k + 1];
    y[k + static_cast<std::size_t>(n)] = dd.x / rate_scale[k];
    y[k + 1 + static_cast<std::size_t>(n)] = dd.y / rate_scale[k + 1];
  }
  integ.reset(*this, 0.0, y);
  LinkageCoordinates c;
  LinkageWorkspace ws;
  coordinates(0.0, y.data(), c);
  forward_kinematics(model, c, ws);
  bool any = false;
  for (int j : model.clearance_joints())
    if (ws.pair[static_cast<std::size_t>(j)].penetration_m > 0) {
      onset(j, 0.0, y);
      ep[static_cast<std::size_t>(j)].phase = 2;  // a start on the wall is a following phase
      ep[static_cast<std::size_t>(j)].chi = model.hysteresis() / model.spec().damping_floor_speed_m_s;
      any = true;
    }
  if (any) integ.reset(*this, 0.0, y);
  evaluate(0.0, y.data(), c, ws);
  diag.energy_start_J = total_energy(c, ws);
}

LinkageSample LinkageSimulator::Impl::sample(double abs_time) {
  const double time = local(abs_time);
  const std::vector<double> y = state_at(time);
  LinkageCoordinates c;
  LinkageWorkspace ws;
  evaluate(time, y.data(), c, ws);
  LinkageSample s = linkage_sample(model, c, ws, sensors);
  s.time_s = abs_time;
  s.crank = crank.at(abs_time);
  return s;
}

void LinkageSimulator::Impl::emit_samples(double up_to) {
  while (next_sample < sample_times.size() && local(sample_times[next_sample]) <= up_to) {
    samples.push_back(sample(sample_times[next_sample]));
    ++next_sample;
  }
}

void LinkageSimulator::Impl::restart(double time, const std::vector<double>& y) {
  const double r = clock.rebase(time);
  integ.reset(*this, r, y);
  t = seg_start = r;
}

void LinkageSimulator::Impl::advance_to(double abs_end) {
  for (;;) {
    const double t_end = local(abs_end);
    if (!(t < t_end)) break;
    if ((t - seg_start) * w > kLinkageRestartTurns * units::kTwoPi) restart(t, state_at(t));
    const LinkageIntegrator::Step st = integ.step(t_end);
    const double ta = t, tb = st.end;
    if (trace) {
      const LinkageIntegrator::StepReport r = integ.last_step_report();
      trace->push_back({absolute(tb), r.step_s, r.weighted_error, r.order, r.limiting});
    }
    emit_samples(tb);
    track(ta, tb);
    book_interval(ta, tb);
    t = tb;
    if (!st.any_root) continue;
    std::vector<double> y = state_at(tb);
    check_energy(tb, y);
    const auto& joints = model.clearance_joints();
    for (std::size_t k = 0; k < joints.size(); ++k) {
      const int j = joints[k];
      Episode& e = ep[static_cast<std::size_t>(j)];
      if (st.roots[k] > 0 && !e.active) onset(j, tb, y);
      else if (st.roots[k] < 0 && e.active) release(j, tb, y);
    }
    restart(tb, y);
  }
}

LinkageSimulator::LinkageSimulator(const LinkageModel& model, const CrankMotion& crank)
    : impl_(std::make_unique<Impl>(model, crank)) {}
LinkageSimulator::~LinkageSimulator() = default;

void LinkageSimulator::start(double t0, const LinkageStart& s) {
  impl_->prepare(t0);
  impl_->begin(s);
}

void LinkageSimulator::start_centred(double t0) {
  const NominalMotion nm = solve_motion(impl_->model.rig(), impl_->crank.at(t0));
  LinkageStart s;
  s.u3 = nm.pose.u3;
  s.u4 = nm.pose.u4;
  s.omega3_rad_s = nm.omega3_rad_s;
  s.omega4_rad_s = nm.omega4_rad_s;
  start(t0, s);
}

void LinkageSimulator::set_sample_times(std::vector<double> times) {
  impl_->sample_times = std::move(times);
  impl_->next_sample = 0;
}

void LinkageSimulator::set_sensors(std::vector<LinkSensor> sensors) { impl_->sensors = std::move(sensors); }

void LinkageSimulator::advance_to(double t_end) { impl_->advance_to(t_end); }
double LinkageSimulator::time() const { return impl_->absolute(impl_->t); }
const std::vector<LinkageSample>& LinkageSimulator::samples() const { return impl_->samples; }
const std::vector<LinkageContact>& LinkageSimulator::contacts() const { return impl_->contacts; }

std::string LinkageSimulator::integrator_counters() const {
  const LinkageIntegrator::Counters c = impl_->integ.counters();
  return "rhs " + std::to_string(c.rhs) + ", jacobians " + std::to_string(c.jacobians) + ", error-test failures " +
         std::to_string(c.error_failures) + ", Newton failures " + std::to_string(c.newton_failures);
}

void LinkageSimulator::trace_steps(std::vector<LinkageStepTrace>* out) { impl_->trace = out; }

std::string LinkageSimulator::state_component(std::size_t i) const {
  return linkage_state_component(impl_->model, i);
}

LinkageDiagnostics LinkageSimulator::diagnostics() {
  Impl& s = *impl_;
  const std::vector<double> y = s.state_at(s.t);
  s.check_energy(s.t, y);
  LinkageCoordinates c;
  LinkageWorkspace ws;
  s.evaluate(s.t, y.data(), c, ws);
  LinkageDiagnostics d = s.diag;
  d.crank_work_J = y[s.work_index()] * s.energy;
  const auto& joints = s.model.clearance_joints();
  for (std::size_t k = 0; k < joints.size(); ++k) {
    LinkageJointBooks& b = d.joint[static_cast<std::size_t>(joints[k])];
    b.contact_loss_J = y[s.quad(k)] * s.energy;
    b.friction_loss_J = y[s.quad(k) + 1] * s.energy;
    b.film_loss_J = s.dry ? 0.0 : y[s.quad(k) + 4] * s.energy;
  }
  d.dissipated_J = s.losses(y) * s.energy;
  d.modal_damping_loss_J = s.model.any_elastic() ? y[s.modal_loss_index()] * s.energy : 0.0;
  d.energy_end_J = s.total_energy(c, ws);
  d.energy_residual_J = d.energy_end_J - d.energy_start_J - d.crank_work_J + d.dissipated_J;
  d.steps = s.integ.steps();
  return d;
}

}  // namespace fourbar
