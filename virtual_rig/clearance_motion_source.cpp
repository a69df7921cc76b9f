#include "virtual_rig/clearance_motion_source.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "common/angle_unwrap.hpp"
#include "common/units.hpp"
#include "sim/run/clearance_simulation.hpp"
#include "virtual_rig/drive_crank.hpp"

namespace fourbar {

ClearanceMotionSource::ClearanceMotionSource(std::shared_ptr<const Rig> rig, CrankDrive drive,
                                             const ClearanceSettings& settings, double clearance_m, double start_s,
                                             double end_s, double sample_period_s)
    : drive_(drive), step_s_(sample_period_s / 2), period_s_(sample_period_s) {
  // Nodes every half sample period, on the grid of the recording's sample times.
  const auto first = static_cast<long long>(std::floor(start_s / step_s_));
  const auto last = static_cast<long long>(std::ceil(end_s / step_s_)) + 2;
  first_s_ = static_cast<double>(first) * step_s_;
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(last - first + 1));
  for (long long j = first; j <= last; ++j) times.push_back(static_cast<double>(j) * step_s_);

  const ClearanceModel model(*rig, clearance_m);
  const DriveCrank crank(drive_);
  // Either clearance model ([clearance] model).
  const std::unique_ptr<ClearanceSimulation> simulation = make_clearance_simulation(model, crank, settings);
  ClearanceSimulation& sim = *simulation;
  sim.set_revolution_origin(drive_.at(first_s_).angle_rad);
  sim.start_nominal(first_s_);
  sim.set_sample_times(times);
  sim.advance_to(times.back());
  if (sim.samples().size() != times.size())
    throw RunError("virtual rig: the clearance model gave " + std::to_string(sim.samples().size()) + " of " +
                   std::to_string(times.size()) + " samples");
  nodes_.reserve(times.size());
  double th3 = 0, th4 = 0;
  for (const ClearanceSample& s : sim.samples()) {
    const double a3 = std::atan2(s.links.u3.y, s.links.u3.x), a4 = std::atan2(s.links.u4.y, s.links.u4.x);
    th3 = nodes_.empty() ? a3 : units::unwrap_rad(a3, th3);
    th4 = nodes_.empty() ? a4 : units::unwrap_rad(a4, th4);
    nodes_.push_back({th3, s.links.omega3_rad_s, th4, s.links.omega4_rad_s});
  }
  impacts_ = sim.impacts();
}

ClearanceMotionSource::Node ClearanceMotionSource::node_at(double t) const {
  const double u = std::clamp((t - first_s_) / step_s_, 0.0, static_cast<double>(nodes_.size() - 1));
  const double j = std::round(u);
  if (std::abs(u - j) < 1e-6) return nodes_[static_cast<std::size_t>(j)];  // a node: the simulator's own value
  const auto i = std::min(static_cast<std::size_t>(u), nodes_.size() - 2);
  const double f = u - static_cast<double>(i);
  const Node &a = nodes_[i], &b = nodes_[i + 1];
  return {a.theta3 + f * (b.theta3 - a.theta3), a.omega3 + f * (b.omega3 - a.omega3),
          a.theta4 + f * (b.theta4 - a.theta4), a.omega4 + f * (b.omega4 - a.omega4)};
}

LinkState ClearanceMotionSource::at(double t) const {
  const Node n = node_at(t), lo = node_at(t - period_s_ / 2), hi = node_at(t + period_s_ / 2);
  LinkState s;
  s.time_s = t;
  s.crank = drive_.at(t);
  s.theta3_rad = n.theta3, s.omega3_rad_s = n.omega3, s.alpha3_rad_s2 = (hi.omega3 - lo.omega3) / period_s_;
  s.theta4_rad = n.theta4, s.omega4_rad_s = n.omega4, s.alpha4_rad_s2 = (hi.omega4 - lo.omega4) / period_s_;
  return s;
}

}  // namespace fourbar
