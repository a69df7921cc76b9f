#include "mechanism/rig_report.hpp"

#include <algorithm>
#include <cmath>

#include "common/units.hpp"
#include "mechanism/kinematics.hpp"

namespace fourbar {

RigReport report_rig(const Rig& rig) {
  RigReport r{grashof_class(rig)};
  r.transmission_min_deg = 180.0;
  double th4_min = 1e9, th4_max = -1e9, prev = 0;
  for (int i = 0; i < 3600; ++i) {
    const double crank_deg = 0.1 * i;
    const Pose p = solve_pose(rig, units::deg_to_rad(crank_deg));
    const double mu = units::rad_to_deg(transmission_angle_rad(p));
    if (mu < r.transmission_min_deg) r.transmission_min_deg = mu, r.transmission_min_at_crank_deg = crank_deg;
    if (mu > r.transmission_max_deg) r.transmission_max_deg = mu, r.transmission_max_at_crank_deg = crank_deg;
    double th4 = p.theta4_rad();
    if (i > 0) th4 -= units::kTwoPi * std::round((th4 - prev) / units::kTwoPi);
    prev = th4;
    th4_min = std::min(th4_min, th4);
    th4_max = std::max(th4_max, th4);
  }
  r.rocker_swing_deg = units::rad_to_deg(th4_max - th4_min);
  return r;
}

nlohmann::json to_json(const Rig& rig, const RigReport& r) {
  nlohmann::json j;
  j["name"] = rig.name;
  j["file"] = rig.source.string();
  j["grashof_class"] = to_string(r.grashof);
  j["assembly"] = to_string(rig.assembly);
  j["radial_clearance_mm"] = units::m_to_mm(rig.radial_clearance_m);
  j["transmission_angle_min_deg"] = r.transmission_min_deg;
  j["transmission_angle_min_at_crank_deg"] = r.transmission_min_at_crank_deg;
  j["transmission_angle_max_deg"] = r.transmission_max_deg;
  j["transmission_angle_max_at_crank_deg"] = r.transmission_max_at_crank_deg;
  j["rocker_swing_deg"] = r.rocker_swing_deg;
  return j;
}

}  // namespace fourbar
