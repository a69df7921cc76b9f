#include "sim/linkage/linkage_sample.hpp"

#include <algorithm>
#include <cmath>

namespace fourbar {

LinkageSample linkage_sample(const LinkageModel& m, const LinkageCoordinates& c, const LinkageWorkspace& w,
                             const std::vector<LinkSensor>& sensors) {
  LinkageSample s;
  s.theta3_rad = std::atan2(c.u[0].y, c.u[0].x);
  s.theta4_rad = std::atan2(c.u[1].y, c.u[1].x);
  s.omega3_rad_s = c.z_rate(0);
  s.omega4_rad_s = c.z_rate(1);
  s.alpha3_rad_s2 = w.z_accel(0);
  s.alpha4_rad_s2 = w.z_accel(1);
  s.crank_torque_Nm = w.crank_torque_Nm;
  s.kinetic_energy_J = kinetic_energy_J(w, c);
  s.potential_energy_J = potential_energy_J(m, w, c);
  s.strain_energy_J = w.strain_energy_J;
  for (const LinkSensor& x : sensors) s.sensor_m_s2.push_back(sensor_reading(m, c, w, x).tangential_m_s2);
  for (int b = 1; b < kBodies; ++b) {
    const auto bu = static_cast<std::size_t>(b - 1);
    s.midspan_deflection_m[bu] = midspan_deflection_m(m, c, w, b);
    const ModalState ms = modal_state(m, c, w, b, true);  // no modes on a rigid link
    std::copy(ms.eta_m.begin(), ms.eta_m.end(), s.modal_m[bu].begin());
    std::copy(ms.eta_ddot_m_s2.begin(), ms.eta_ddot_m_s2.end(), s.modal_accel_m_s2[bu].begin());
  }
  for (int j : m.clearance_joints()) {
    const PairState& ps = w.pair[static_cast<std::size_t>(j)];
    JointSample& js = s.joint[static_cast<std::size_t>(j)];
    js.gap_m = ps.gap_m;
    js.penetration_m = std::max(0.0, ps.penetration_m);
    js.normal_force_N = ps.normal_force_N;
    js.eta_rad = std::atan2(ps.normal.y, ps.normal.x);
    js.pin_force_N = ps.pin_force_N;
    s.in_contact = s.in_contact || ps.penetration_m > 0;
  }
  return s;
}

}  // namespace fourbar
