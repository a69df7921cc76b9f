#include "sim/nominal/run.hpp"

#include <cmath>

#include "common/angle_unwrap.hpp"
#include "common/units.hpp"
#include "mechanism/kinetostatics.hpp"
#include "sim/outputs.hpp"

namespace fourbar {

SeriesTable run_nominal(const Scene& scene, NominalRunStats* stats) {
  const Rig& rig = *scene.rig;
  const std::size_t n = static_cast<std::size_t>(scene.revolutions) * scene.samples_per_revolution + 1;
  const double w2 = scene.crank_speed_rad_s;
  const double step = units::kTwoPi / scene.samples_per_revolution * (w2 > 0 ? 1.0 : -1.0);

  // Decide once what the requested columns need.
  bool need_kin = false, need_loads = false, need_energy = false;
  std::vector<const OutputSpec*> specs;
  for (const auto& name : scene.outputs) {
    const OutputSpec* s = find_output(name);
    specs.push_back(s);
    need_kin |= s->needs != Needs::crank;
    need_loads |= s->needs == Needs::loads;
    need_energy |= s->needs == Needs::energy;
  }

  SeriesTable table;
  table.names.push_back("crank_deg");
  for (const auto& name : scene.outputs) table.names.push_back(name);
  table.columns.assign(table.names.size(), std::vector<double>(n));

  NominalRunStats counts;
  double theta3_prev = 0, theta4_prev = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double theta2 = scene.start_angle_rad + step * static_cast<double>(i);
    const CrankState crank{theta2, w2, 0.0};
    NominalMotion m;
    m.crank = crank;
    JointLoads loads;
    double theta3 = 0, theta4 = 0;
    if (need_kin) {
      m.pose = solve_pose(rig, theta2);
      solve_rates(rig, m);
      theta3 = m.pose.theta3_rad();
      theta4 = m.pose.theta4_rad();
      if (i > 0) {
        theta3 = units::unwrap_rad(theta3, theta3_prev);
        theta4 = units::unwrap_rad(theta4, theta4_prev);
      }
      theta3_prev = theta3;
      theta4_prev = theta4;
      ++counts.kinematics_evaluations;
    }
    if (need_loads) {
      loads = solve_loads(rig, m);
      ++counts.load_evaluations;
    }
    double ke = 0, pe = 0;
    if (need_energy) {
      ke = kinetic_energy_J(rig, m);
      pe = potential_energy_J(rig, m.pose);
      ++counts.energy_evaluations;
    }

    table.columns[0][i] = units::rad_to_deg(theta2);
    for (std::size_t c = 0; c < specs.size(); ++c) {
      double v = 0;
      switch (specs[c]->quantity) {
        case Quantity::time: v = (theta2 - scene.start_angle_rad) / w2; break;
        case Quantity::theta2: v = theta2; break;
        case Quantity::omega2: v = w2; break;
        case Quantity::theta3: v = theta3; break;
        case Quantity::theta4: v = theta4; break;
        case Quantity::omega3: v = m.omega3_rad_s; break;
        case Quantity::omega4: v = m.omega4_rad_s; break;
        case Quantity::alpha3: v = m.alpha3_rad_s2; break;
        case Quantity::alpha4: v = m.alpha4_rad_s2; break;
        case Quantity::transmission: v = units::rad_to_deg(transmission_angle_rad(m.pose)); break;
        case Quantity::crank_torque: v = loads.crank_torque_Nm; break;
        case Quantity::bearing_fx: v = loads.bearing_N.x; break;
        case Quantity::bearing_fy: v = loads.bearing_N.y; break;
        case Quantity::crankpin_fx: v = loads.crank_pin_N.x; break;
        case Quantity::crankpin_fy: v = loads.crank_pin_N.y; break;
        case Quantity::crank_pivot_fx: v = loads.crank_pivot_N.x; break;
        case Quantity::crank_pivot_fy: v = loads.crank_pivot_N.y; break;
        case Quantity::rocker_pivot_fx: v = loads.rocker_pivot_N.x; break;
        case Quantity::rocker_pivot_fy: v = loads.rocker_pivot_N.y; break;
        case Quantity::kinetic_energy: v = ke; break;
        case Quantity::potential_energy: v = pe; break;
      }
      table.columns[c + 1][i] = v;
    }
  }
  if (stats) *stats = counts;
  return table;
}

}  // namespace fourbar
