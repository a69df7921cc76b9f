#pragma once
// Where an accelerometer sits on a link and which way it points.
//
// Link frame: u = unit vector along the link from its first joint to its far
// joint (coupler: crank pin A → pin B; rocker: pivot O4 → bushing centre C),
// n = u turned +90° (counter-clockwise), the direction a point moves when the
// link turns counter-clockwise. A sensor at distance r along the link from
// the first joint and offset h along n sits at P = J + r·u + h·n.
//
// A `tangential` channel senses along ±n (thesis "tangential" accelerometer,
// Fig. 7.5/7.7), a `normal` channel along ±u (towards the far joint for
// sign +1). Accelerometers measure specific force (a_P − g_vec), not a_P.

#include <string>
#include <vector>

#include "acquire/analog_response.hpp"

#include "mechanism/rig.hpp"

namespace fourbar {

enum class SensedLink { coupler, rocker };
enum class SensorAxis { tangential, normal };
/// The joint the distance is measured from: the link's first joint (coupler:
/// crank pin A, rocker: pivot O4) or its far joint (the coupler–rocker joint).
enum class MeasuredFrom { first_joint, far_joint };

const char* to_string(SensedLink l);
const char* to_string(SensorAxis a);

/// An accelerometer as the manifest describes it (SI units).
struct AccelerometerMount {
  std::string channel;              ///< channel name, for error messages
  SensedLink link = SensedLink::coupler;
  SensorAxis axis = SensorAxis::tangential;
  double distance_m = 0;            ///< along the link, from `from`
  MeasuredFrom from = MeasuredFrom::first_joint;
  double offset_m = 0;              ///< perpendicular offset h along +n (0: on the link line)
  int axis_sign = 1;                ///< +1: a positive reading is specific force along +n (+u); −1: opposite
  double high_pass_corner_hz = 0;   ///< AC-coupled (piezo) sensor: first-order high-pass corner; 0: DC-coupled
  /// Known sample-time offset of this channel after the crank channel (a
  /// multiplexed ADC's skew, a linear-phase filter's delay); removed before
  /// conversion with `known_response` (known_response.hpp).
  double sample_delay_s = 0;
  /// The analog path's known sections (the DAQ's filter, the sensor's
  /// mounted resonance) on this channel; divided out in band.
  std::vector<AnalogSection> known_response;
};

/// The mount reduced to the link frame, validated.
struct ResolvedMount {
  SensedLink link = SensedLink::coupler;
  SensorAxis axis = SensorAxis::tangential;
  double r_m = 0;     ///< distance from the first joint along u, in (0, l]
  double h_m = 0;     ///< offset along n
  double sign = 1;    ///< ±1
  double high_pass_corner_hz = 0;
};

/// Resolves `mount` against `rig`. Throws InputError naming the channel when
/// the sensor lies outside the link (r < 0 or r > l), at the first joint
/// (r = 0: its tangential reading holds no angular acceleration), the sign is
/// not ±1, or a value is not finite / the corner is negative.
ResolvedMount resolve_mount(const Rig& rig, const AccelerometerMount& mount);

/// Length of the sensed link.
double link_length_m(const Rig& rig, SensedLink link);

}  // namespace fourbar
