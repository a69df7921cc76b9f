#pragma once
// The links' bending vibration that the rigid clearance model lacks: each
// link mode is a damped modal oscillator
//
//   m·q̈ + 2ζω·m·q̇ + ω²·m·q = φ_b·F⊥(t),
//
// driven by the bearing's contact impulses (each impact, plus the plastic
// impulse that stops a slow rebound, changes q̇ by φ_b·P⊥/m, where P⊥ is the
// impulse's component across the link: P·sin(η − θ_link)). A tangential
// accelerometer on that link then also sees φ_s·q̈ (the mode's transverse
// acceleration at the sensor); a normal-axis sensor sees none (the bending
// is across the link). The smooth following-mode force is left out: it
// changes slowly against the modes (hundreds of Hz), so it only bends the
// link quasi-statically by a negligible amount.
//
// Between impulses the oscillator is advanced exactly (closed-form free
// response), so the result does not depend on the sample rate. Times must
// come in increasing order (advance_to).
//
// Scene keys ([[recording.link_mode]], docs/virtual-rig.md): link,
// frequency_hz, damping_ratio, modal_mass_kg, shape_at_bearing,
// shape_at_sensor.

#include <string>
#include <vector>

#include "acquire/manifest.hpp"
#include "sim/record/run_records.hpp"

namespace fourbar {

enum class RingingLink { coupler, rocker };

struct LinkMode {
  RingingLink link = RingingLink::coupler;
  double frequency_hz = 600;    ///< undamped natural frequency
  double damping_ratio = 0.02;  ///< ζ
  double modal_mass_kg = 1;     ///< m, for the mode shape normalised as below
  double shape_at_bearing = 1;  ///< φ_b: mode shape at the coupler–rocker bearing
  double shape_at_sensor = 1;   ///< φ_s: mode shape at the link's tangential sensors
};

/// One impulse on the bearing: when, how large, and its part across each link.
struct BearingImpulse {
  double time_s = 0;
  double across_coupler_Ns = 0, across_rocker_Ns = 0;
};

/// The bearing impulses of a clearance run (three-mode: impact plus settle impulse).
std::vector<BearingImpulse> bearing_impulses(const std::vector<ImpactRecord>& impacts);

class LinkRinging {
 public:
  LinkRinging(std::vector<LinkMode> modes, std::vector<BearingImpulse> impulses);
  /// Moves every mode to `time_s` (not before the last time asked for),
  /// applying the impulses on the way.
  void advance_to(double time_s);
  /// The transverse acceleration the modes give a sensor of `role` now (m/s²).
  double sensor_acceleration(ChannelRole role) const;
  /// The same at any time, in any order (a multiplexed channel's skewed
  /// sample, an analog filter's sub-steps): from the modes' state just after
  /// the last impulse at or before `time_s`, kept when the rig was built.
  double sensor_acceleration_at(double time_s, ChannelRole role) const;
  bool empty() const { return modes_.empty(); }

 private:
  struct State {
    double q = 0, v = 0;
  };
  void propagate(double dt_s);
  static void propagate(const std::vector<LinkMode>& modes, std::vector<State>& state, double dt_s);
  static double acceleration(const std::vector<LinkMode>& modes, const std::vector<State>& state, ChannelRole role);

  std::vector<LinkMode> modes_;
  std::vector<BearingImpulse> impulses_;
  std::vector<State> state_;
  std::vector<std::vector<State>> after_impulse_;  ///< each mode's state just after impulse i
  std::size_t next_ = 0;  ///< first impulse not yet applied
  double time_s_ = 0;
  bool started_ = false;
};

}  // namespace fourbar
