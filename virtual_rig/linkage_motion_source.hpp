#pragma once
// The linkage model (sim/linkage/, model = "linkage") as the virtual rig's
// motion: rigid or elastic coupler and rocker, clearance in any joint, run
// once over the whole recording (plus its warm-up) and tabulated every half
// sample period. With elastic links the links' vibration comes from the
// model itself (issue 28, item 2), not from the modal-oscillator stand-in of
// [[recording.link_mode]] (link_ringing.hpp).
//
// Each accelerometer on the coupler or the rocker with a tangential axis is
// one of the simulator's sensors (sim/linkage/linkage_sensor.hpp: the
// specific force at the manifest's position_m and offset_m, rigid frame plus
// the elastic deflection, read across the deformed axis); `reading` gives
// it. The links' states (`at`) are the floating frames' angles and rates:
// other sensors (normal axes, crank) see those through
// virtual_rig/sensor_signal.hpp, as on rigid links. Unlike the clearance
// source's α (a sample period's mean, for the three-mode model's jumps in
// ω), α and the readings here are point values: the compliant contact has no
// jumps (a contact lasts some 0.1–0.3 ms, two to four samples at 12.8 kHz).
// Between nodes (a multiplexed channel's skew, an analog filter's
// sub-steps) everything is interpolated linearly.

#include <memory>
#include <vector>

#include "acquire/manifest.hpp"
#include "sim/linkage/linkage_simulator.hpp"
#include "sim/scene.hpp"
#include "virtual_rig/motion_source.hpp"

namespace fourbar {

class LinkageMotionSource final : public MotionSource {
 public:
  /// Simulates the scene's linkage on `drive` from the nominal start with
  /// centred pins at `start_s` (may be negative: warm-up turns), tabulating
  /// from `first_node_s` (the AC filters' run-in) to `end_s`. `channels`: the
  /// recording's sensors; the tangential ones on the coupler or rocker become
  /// the simulator's sensors.
  LinkageMotionSource(const Scene& scene, CrankDrive drive, const std::vector<ChannelSpec>& channels, double start_s,
                      double first_node_s, double end_s, double sample_period_s);
  LinkState at(double time_s) const override;
  /// Whether the linkage reads channel `c` itself (a tangential sensor on the coupler or the rocker).
  bool reads(std::size_t c) const { return c < sensor_of_.size() && sensor_of_[c] >= 0; }
  /// That channel's reading (m/s², the sensor's own axis sign not applied).
  double reading(std::size_t c, double time_s) const;
  /// Contacts released during the run (warm-up included).
  const std::vector<LinkageContact>& contacts() const { return contacts_; }
  /// Whether any link is elastic (the readings then hold its vibration).
  bool elastic() const { return elastic_; }

 private:
  struct Node {
    double theta3, omega3, alpha3, theta4, omega4, alpha4;
  };
  /// Index and weight of the node interval holding `time_s`.
  std::pair<std::size_t, double> locate(double time_s) const;

  CrankDrive drive_;
  double first_s_ = 0, step_s_ = 0;
  std::vector<Node> nodes_;
  std::vector<int> sensor_of_;              ///< per channel: the simulator's sensor index, or −1
  std::vector<std::vector<double>> reads_;  ///< per simulator sensor: the reading at each node
  std::vector<LinkageContact> contacts_;
  bool elastic_ = false;
};

}  // namespace fourbar
