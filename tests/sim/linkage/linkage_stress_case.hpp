#pragma once
// One stress case of the linkage model (issue 25: the stress grid of issue 7
// extended to elastic links and several clearances): the thesis_elastic rig,
// a start angle, clearance in 1–3 joints, an impact law, wall friction, a
// crank speed and 0, 2 or 4 modes on the coupler and rocker, run for whole
// turns in 1/8-turn slices. Shared by the CI subset
// (tests/sim/linkage/test_linkage_stress.cpp) and the full grid
// (bench/stress_linkage.cpp).
//
// A case passes when
//  * it reaches the end without an exception and every sample (1°: angles,
//    rates, θ̈, torque, energies, pin forces, gaps, the modal coordinates and
//    the coupler's mid-span sensor) and every diagnostic is finite,
//  * the steps per 1/8 turn stay below a bound (no hang),
//  * the largest energy residual (motor work = contact + friction + modal
//    damping + ΔE, checked at every contact event and at the end) is below
//    1e-8 of the energy scale,
//  * no pin goes deeper than the penetration that would store ten times the
//    energy scale in its contact, ((n+1)·10·E/K)^(1/(n+1)): the compliant
//    contact's penetration is physical, an unbounded drift is not.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "sim/drive/crank_motion.hpp"
#include "sim/linkage/linkage_simulator.hpp"

namespace fourbar::linkage_stress {

inline constexpr double kEnergyBound = 1e-8;  ///< max |energy residual| / energy scale
inline constexpr double kMaxStepsPerTurn = 2e6;

struct Case {
  double start_deg = 0;
  std::array<bool, kJoints> joints{false, true, false};  ///< which joints have the clearance
  double clearance_m = 0.254e-3;
  double restitution = 0.5;
  double friction = 0;
  double rpm = 350;
  int modes = 2;  ///< per elastic link; 0 = rigid links
  int turns = 1;
  double tolerance = 1e-10;
  LinkageMethod method = LinkageMethod::bdf;

  std::string label() const {
    char buf[256];
    std::snprintf(buf, sizeof buf, "start=%g° joints=%s%s%s xi=%gmm e=%g mu=%g rpm=%g modes=%d", start_deg,
                  joints[0] ? "A" : "", joints[1] ? "B" : "", joints[2] ? "O4" : "", units::m_to_mm(clearance_m),
                  restitution, friction, rpm, modes);
    return buf;
  }
};

struct Result {
  bool ok = true;
  std::string failure;         ///< first failed check
  double energy_residual = 0;  ///< max |residual| / energy scale
  double penetration_ratio = 0;  ///< deepest penetration / the bound above
  double max_steps_per_turn = 0;
  std::size_t contacts = 0;
  double wall_seconds = 0;
};

inline Result run_case(const Rig& rig, const Case& c) {
  Result r;
  const auto t0 = std::chrono::steady_clock::now();
  auto fail = [&](const std::string& why) {
    if (r.ok) r.failure = why;
    r.ok = false;
  };
  try {
    LinkageSpec s;
    for (int j = 0; j < kJoints; ++j) s.clearance_m[static_cast<std::size_t>(j)] = c.joints[static_cast<std::size_t>(j)] ? c.clearance_m : 0.0;
    s.law = {1e10, 1.5, DampingLaw::calibrated, c.restitution};
    s.friction = {c.friction, 1e-4, 1e-3};
    s.tolerance = c.tolerance;
    s.method = c.method;
    s.elastic = {false, c.modes > 0, c.modes > 0};
    s.elastic_modes = c.modes;
    const LinkageModel model = build_linkage(rig, s);
    const double w = units::rpm_to_rad_s(c.rpm), period = units::kTwoPi / w;
    const ConstantSpeedCrank crank(units::deg_to_rad(c.start_deg), w);
    LinkageSimulator sim(model, crank);
    std::vector<double> times;
    for (int i = 0; i <= 360 * c.turns; ++i) times.push_back(period * i / 360.0);
    sim.set_sample_times(times);
    sim.set_sensors({{1, 0.5 * rig.coupler.length_m, 0.0}});
    sim.start_centred(0.0);
    constexpr int kSlices = 8;
    std::size_t before = 0, turn_start = 0;
    for (int k = 1; k <= c.turns * kSlices && r.ok; ++k) {
      sim.advance_to(times[static_cast<std::size_t>(k * 360 / kSlices)]);
      const std::size_t steps = sim.diagnostics().steps;
      if (static_cast<double>(steps - before) > kMaxStepsPerTurn / kSlices) fail("steps per 1/8 turn above the bound");
      before = steps;
      if (k % kSlices == 0) {
        r.max_steps_per_turn = std::max(r.max_steps_per_turn, static_cast<double>(steps - turn_start));
        turn_start = steps;
      }
    }
    const LinkageDiagnostics d = sim.diagnostics();
    if (sim.samples().size() != times.size()) fail("missing samples");
    double deepest = 0;
    for (const LinkageSample& x : sim.samples()) {
      std::vector<double> v = {x.theta3_rad, x.theta4_rad, x.omega3_rad_s, x.omega4_rad_s, x.alpha3_rad_s2,
                               x.alpha4_rad_s2, x.crank_torque_Nm, x.kinetic_energy_J, x.potential_energy_J,
                               x.strain_energy_J, x.midspan_deflection_m[0], x.midspan_deflection_m[1]};
      for (const auto& link : x.modal_m) v.insert(v.end(), link.begin(), link.end());
      v.insert(v.end(), x.sensor_m_s2.begin(), x.sensor_m_s2.end());
      for (const JointSample& j : x.joint) {
        v.insert(v.end(), {j.gap_m, j.penetration_m, j.normal_force_N, j.pin_force_N.x, j.pin_force_N.y});
        deepest = std::max(deepest, j.penetration_m);
      }
      if (!std::all_of(v.begin(), v.end(), [](double y) { return std::isfinite(y); })) {
        fail("NaN/Inf in a sample at t = " + std::to_string(x.time_s));
        break;
      }
    }
    for (const LinkageJointBooks& b : d.joint) deepest = std::max(deepest, b.max_penetration_m);
    const double diag[] = {d.crank_work_J, d.energy_start_J, d.energy_end_J, d.dissipated_J, d.modal_damping_loss_J,
                           d.energy_residual_J, d.max_energy_residual_J};
    for (double x : diag)
      if (!std::isfinite(x)) fail("NaN/Inf in the diagnostics");
    r.energy_residual = std::max(std::abs(d.energy_residual_J), d.max_energy_residual_J) / d.energy_scale_J;
    if (!(r.energy_residual < kEnergyBound)) fail("energy residual above 1e-8 of the scale");
    const double n = s.law.exponent;
    const double bound = std::pow((n + 1) * 10 * d.energy_scale_J / s.law.stiffness, 1 / (n + 1));
    r.penetration_ratio = deepest / bound;
    if (!(r.penetration_ratio < 1)) fail("a pin went deeper than the energy bound");
    r.contacts = sim.contacts().size();
  } catch (const std::exception& e) {
    fail(std::string("exception: ") + e.what());
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace fourbar::linkage_stress
