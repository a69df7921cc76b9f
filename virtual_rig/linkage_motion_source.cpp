#include "virtual_rig/linkage_motion_source.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "common/units.hpp"
#include "virtual_rig/drive_crank.hpp"

namespace fourbar {

LinkageMotionSource::LinkageMotionSource(const Scene& scene, CrankDrive drive, const std::vector<ChannelSpec>& channels,
                                         double start_s, double first_node_s, double end_s, double sample_period_s)
    : drive_(std::move(drive)), step_s_(sample_period_s / 2) {
  const LinkageModel model = build_linkage(*scene.rig, scene.linkage.spec);
  elastic_ = model.any_elastic();
  std::vector<LinkSensor> sensors;
  for (const ChannelSpec& c : channels) {
    const bool read = is_accelerometer(c.role) && is_tangential(c.role);
    sensor_of_.push_back(read ? static_cast<int>(sensors.size()) : -1);
    if (read) sensors.push_back({is_on_coupler(c.role) ? 1 : 2, c.position_m, c.offset_m});
  }
  // Nodes every half sample period on the grid of the recording's sample times.
  const auto first = static_cast<long long>(std::floor(first_node_s / step_s_));
  const auto last = static_cast<long long>(std::ceil(end_s / step_s_)) + 2;
  first_s_ = static_cast<double>(first) * step_s_;
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(last - first + 1));
  for (long long j = first; j <= last; ++j) times.push_back(static_cast<double>(j) * step_s_);
  if (!(start_s <= first_s_))
    throw RunError("virtual rig: the linkage run starts at " + std::to_string(start_s) + " s, after its first node");

  const DriveCrank crank(drive_);
  LinkageSimulator sim(model, crank);
  sim.set_sample_times(times);
  sim.set_sensors(sensors);
  sim.start_centred(start_s);
  sim.advance_to(times.back());
  const std::vector<LinkageSample>& samples = sim.samples();
  if (samples.size() != times.size())
    throw RunError("virtual rig: the linkage model gave " + std::to_string(samples.size()) + " of " +
                   std::to_string(times.size()) + " samples");
  nodes_.reserve(samples.size());
  reads_.assign(sensors.size(), std::vector<double>(samples.size()));
  double th3 = 0, th4 = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const LinkageSample& s = samples[i];
    // Continuous angles: the interpolation between nodes must not cross a ±π cut.
    th3 = i == 0 ? s.theta3_rad : th3 + std::remainder(s.theta3_rad - th3, units::kTwoPi);
    th4 = i == 0 ? s.theta4_rad : th4 + std::remainder(s.theta4_rad - th4, units::kTwoPi);
    nodes_.push_back({th3, s.omega3_rad_s, s.alpha3_rad_s2, th4, s.omega4_rad_s, s.alpha4_rad_s2});
    for (std::size_t k = 0; k < sensors.size(); ++k) reads_[k][i] = s.sensor_m_s2[k];
  }
  contacts_ = sim.contacts();
}

std::pair<std::size_t, double> LinkageMotionSource::locate(double t) const {
  const double u = std::clamp((t - first_s_) / step_s_, 0.0, static_cast<double>(nodes_.size() - 1));
  const double j = std::round(u);
  if (std::abs(u - j) < 1e-6) return {static_cast<std::size_t>(j), 0.0};  // a node: the simulator's own value
  const auto i = std::min(static_cast<std::size_t>(u), nodes_.size() - 2);
  return {i, u - static_cast<double>(i)};
}

LinkState LinkageMotionSource::at(double t) const {
  const auto [i, f] = locate(t);
  const Node& a = nodes_[i];
  const Node& b = f > 0 ? nodes_[i + 1] : a;
  auto mix = [f = f](double x, double y) { return x + f * (y - x); };
  LinkState s;
  s.time_s = t;
  s.crank = drive_.at(t);
  s.theta3_rad = mix(a.theta3, b.theta3), s.omega3_rad_s = mix(a.omega3, b.omega3), s.alpha3_rad_s2 = mix(a.alpha3, b.alpha3);
  s.theta4_rad = mix(a.theta4, b.theta4), s.omega4_rad_s = mix(a.omega4, b.omega4), s.alpha4_rad_s2 = mix(a.alpha4, b.alpha4);
  return s;
}

double LinkageMotionSource::reading(std::size_t c, double t) const {
  const std::vector<double>& r = reads_.at(static_cast<std::size_t>(sensor_of_.at(c)));
  const auto [i, f] = locate(t);
  return f > 0 ? r[i] + f * (r[i + 1] - r[i]) : r[i];
}

}  // namespace fourbar
