#pragma once
// The clearance model as the virtual rig's motion: the three-mode simulator
// (sim/three_mode) driven by the rig's crank drive, run once over the whole
// recording (plus its warm-up) and tabulated every half sample period.
//
// α is reported as the mean over one sample period, (ω(t + h/2) − ω(t − h/2))/h
// with h = 1/fs: an impact's jump in ω then shows as one sample of area Δω,
// as an anti-aliased accelerometer would see it, and integrating the samples
// gives ω back with its jumps. θ and ω are the simulator's values at the
// node times; between nodes (only the noise estimate asks there) they are
// interpolated linearly.

#include <memory>
#include <vector>

#include "sim/three_mode/settings.hpp"
#include "sim/three_mode/simulator.hpp"
#include "virtual_rig/motion_source.hpp"

namespace fourbar {

class ClearanceMotionSource final : public MotionSource {
 public:
  /// Simulates from the nominal start (sec. 3.4) at `start_s` (may be
  /// negative: warm-up turns and the AC filters' run-in) to `end_s`.
  ClearanceMotionSource(std::shared_ptr<const Rig> rig, CrankDrive drive, const ClearanceSettings& settings,
                        double clearance_m, double start_s, double end_s, double sample_period_s);
  LinkState at(double time_s) const override;
  /// Impacts of the whole run (warm-up included).
  const std::vector<ImpactRecord>& impacts() const { return impacts_; }

 private:
  struct Node {
    double theta3, omega3, theta4, omega4;
  };
  Node node_at(double time_s) const;

  CrankDrive drive_;
  double first_s_, step_s_, period_s_;
  std::vector<Node> nodes_;
  std::vector<ImpactRecord> impacts_;
};

}  // namespace fourbar
