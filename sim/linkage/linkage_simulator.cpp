// The linkage simulator: state conversion, the ODE with its quadratures and witnesses, the main
// loop with per-joint contact onset and release, and the books (samples, contacts, times, energies).

#include "sim/linkage/linkage_simulator.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "common/units.hpp"
#include "mechanism/kinematics.hpp"
#include "sim/integrate/event_root.hpp"
#include "sim/linkage/linkage_dynamics.hpp"
#include "sim/integrate/linkage_integrator.hpp"
#include "sim/linkage/linkage_scales.hpp"

namespace fourbar {

namespace {

Vec2 rotated(Vec2 u, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * u.x - s * u.y, s * u.x + c * u.y};
}
double angle_between(Vec2 a, Vec2 b) { return std::atan2(cross(a, b), dot(a, b)); }
/// A segment longer than this many turns restarts at a new time origin (as the compliant model).
constexpr double kLinkageRestartTurns = 64;

}  // namespace

struct LinkageSimulator::Impl final : LinkageOde {
  Impl(const LinkageModel& m, const CrankMotion& c)
      : model(m),
        crank(c),
        n(m.coordinates()),
        dry(m.spec().film.viscosity_Pa_s <= 0),
        per_joint(dry ? 4 : 5),
        size(static_cast<std::size_t>(2 * n + 1) +
             m.clearance_joints().size() * static_cast<std::size_t>(per_joint) + (m.any_elastic() ? 1U : 0U)),
        integ(m.spec().tolerance, size, static_cast<std::size_t>(2 * n), m.clearance_joints().size(), m.spec().method) {}

  const LinkageModel& model;
  const CrankMotion& crank;
  int n;
  bool dry;
  int per_joint;
  std::size_t size;
  LinkageIntegrator integ;
  LinkageWorkspace rhs_ws;  ///< rhs()'s, kept: the mass matrix's block profile (block_cholesky.hpp) carries over
  // scales
  double w = 1, delta = 1, energy = 1, force = 1;
  LinkageScales scales;  // and its parts below (linkage_scales.hpp)
  std::array<double, kMaxFull> pos_scale{}, rate_scale{};
  // clock
  double origin_s = 0, t = 0, seg_start = 0, start_abs = 0;
  double absolute(double time) const { return origin_s + time; }
  double local(double abs_time) const { return abs_time - origin_s; }
  double rebase(double time) {
    const double o = origin_s + time;
    const double r = std::abs(origin_s) >= std::abs(time) ? (origin_s - o) + time : (time - o) + origin_s;
    origin_s = o;
    return r;
  }
  // nominal cache
  struct Entry {
    double origin = 0, time = 0;
    bool valid = false;
    NominalMotion motion;
  };
  mutable std::array<Entry, 4> cache{};
  mutable std::size_t next_entry = 0;
  const NominalMotion& nominal_at(double time) const {
    for (const Entry& e : cache)
      if (e.valid && e.time == time && e.origin == origin_s) return e.motion;
    Entry& e = cache[next_entry];
    next_entry = (next_entry + 1) % cache.size();
    e = {origin_s, time, true, solve_motion(model.rig(), crank.at_local(origin_s, time))};
    return e.motion;
  }

  // per-joint open contact
  struct Episode {
    bool active = false;
    int phase = 0;
    double chi = 0, onset_abs = 0, loss_at_onset = 0;
    LinkageContact rec;
  };
  std::array<Episode, kJoints> ep{};
  std::vector<double> sample_times;
  std::vector<LinkSensor> sensors;
  std::size_t next_sample = 0;
  std::vector<LinkageSample> samples;
  std::vector<LinkageContact> contacts;
  LinkageDiagnostics diag;
  std::vector<LinkageStepTrace>* trace = nullptr;

  std::size_t work_index() const { return static_cast<std::size_t>(2 * n); }
  /// Quadrature base of the k-th clearance joint: contact loss, friction loss, impulse n, impulse t, (film).
  std::size_t quad(std::size_t k) const { return work_index() + 1 + k * static_cast<std::size_t>(per_joint); }
  /// The modal damping's dissipation (elastic links only), after the joints' quadratures.
  std::size_t modal_loss_index() const { return quad(model.clearance_joints().size()); }

  // ---- state conversion ----
  void coordinates(double time, const double* y, LinkageCoordinates& c) const {
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

  std::array<double, kJoints> chis(const LinkageWorkspace& ws) const {
    std::array<double, kJoints> chi{};
    for (int j : model.clearance_joints()) {
      const auto ju = static_cast<std::size_t>(j);
      chi[ju] = ep[ju].active ? ep[ju].chi
                              : model.hysteresis() / std::max(ws.pair[ju].normal_speed_m_s,
                                                              model.spec().damping_floor_speed_m_s);
    }
    return chi;
  }

  void evaluate(double time, const double* y, LinkageCoordinates& c, LinkageWorkspace& ws) const {
    coordinates(time, y, c);
    forward_kinematics(model, c, ws);
    pair_forces(model, chis(ws), ws);
    solve_accelerations(model, c, ws);
  }

  void rhs(double time, const double* y, double* dy) override {
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

  /// The penetration over the clearance, (|e| − ξ)/ξ, per clearance joint,
  /// from the bodies' positions only (CVODE calls this after every step).
  void witnesses(double time, const double* y, double* g) override {
    LinkageCoordinates c;
    coordinates(time, y, c);
    const std::array<double, kJoints> pen = pair_penetrations(model, c);
    const auto& joints = model.clearance_joints();
    for (std::size_t k = 0; k < joints.size(); ++k)
      g[k] = pen[static_cast<std::size_t>(joints[k])] / model.joint(joints[k]).clearance_m;
  }

  std::vector<double> state_at(double time) {
    std::vector<double> y;
    integ.interpolate(time, y);
    return y;
  }

  double total_energy(const LinkageCoordinates& c, const LinkageWorkspace& ws) const {
    double e = kinetic_energy_J(ws, c) + potential_energy_J(model, ws, c) + ws.strain_energy_J;
    for (int j : model.clearance_joints()) e += ws.pair[static_cast<std::size_t>(j)].elastic_energy_J;
    return e;
  }

  double losses(const std::vector<double>& y) const {
    double d = 0;
    for (std::size_t k = 0; k < model.clearance_joints().size(); ++k) {
      d += y[quad(k)] + y[quad(k) + 1];
      if (!dry) d += y[quad(k) + 4];
    }
    if (model.any_elastic()) d += y[modal_loss_index()];
    return d;
  }

  void check_energy(double time, const std::vector<double>& y) {
    LinkageCoordinates c;
    LinkageWorkspace ws;
    evaluate(time, y.data(), c, ws);
    const double r = total_energy(c, ws) - diag.energy_start_J - (y[work_index()] - losses(y)) * energy;
    diag.max_energy_residual_J = std::max(diag.max_energy_residual_J, std::abs(r));
  }

  // ---- starts ----
  void prepare(double t0) {
    scales = linkage_scales(model, crank.at(t0));
    std::tie(w, delta, energy, force) = std::tie(scales.w, scales.delta, scales.energy, scales.force);
    std::tie(pos_scale, rate_scale) = std::tie(scales.position, scales.rate);
    diag.energy_scale_J = energy;
    origin_s = start_abs = t0;
    t = seg_start = 0;
  }

  void begin(const LinkageStart& s) {
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

  // ---- contacts ----
  std::size_t slot(int joint) const {
    const auto& js = model.clearance_joints();
    return static_cast<std::size_t>(std::find(js.begin(), js.end(), joint) - js.begin());
  }

  void onset(int j, double time, std::vector<double>& y) {
    LinkageCoordinates c;
    LinkageWorkspace ws;
    coordinates(time, y.data(), c);
    forward_kinematics(model, c, ws);
    const PairState& ps = ws.pair[static_cast<std::size_t>(j)];
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

  void release(int j, double time, const std::vector<double>& y) {
    LinkageCoordinates c;
    LinkageWorkspace ws;
    coordinates(time, y.data(), c);
    forward_kinematics(model, c, ws);
    const PairState& ps = ws.pair[static_cast<std::size_t>(j)];
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

  /// The clearance pairs (geometry, relative velocity, forces) at `time`.
  const std::array<PairState, kJoints>& pairs_at(double time, LinkageWorkspace& ws) {
    LinkageCoordinates c;
    integ.interpolate(time, track_state);
    coordinates(time, track_state.data(), c);
    pair_kinematics(model, c, ws);
    pair_forces(model, chis(ws), ws);
    return ws.pair;
  }
  std::vector<double> track_state;

  /// Peak force, penetration and the end of the first compression–restitution
  /// cycle of each open contact, from the pairs at the step's end and, while an
  /// impact's first cycle is open, at mid-step too (each evaluated once). A
  /// sustained contact (phase 2) is smooth on the step's scale: step ends only.
  void track(double ta, double tb) {
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

  void book_interval(double ta, double tb) {
    for (int j : model.clearance_joints()) {
      LinkageJointBooks& b = diag.joint[static_cast<std::size_t>(j)];
      (ep[static_cast<std::size_t>(j)].active ? b.contact_time_s : b.free_time_s) += tb - ta;
    }
  }

  LinkageSample sample(double abs_time) {
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

  void emit_samples(double up_to) {
    while (next_sample < sample_times.size() && local(sample_times[next_sample]) <= up_to) {
      samples.push_back(sample(sample_times[next_sample]));
      ++next_sample;
    }
  }

  void restart(double time, const std::vector<double>& y) {
    const double r = rebase(time);
    integ.reset(*this, r, y);
    t = seg_start = r;
  }

  void advance_to(double abs_end) {
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
};

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
