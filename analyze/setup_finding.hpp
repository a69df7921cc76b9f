#pragma once
// A set-up check's finding as the technician reads it: which item, the
// manifest's value, the data's value, how sure, and the key to change.

#include <string>
#include <utility>
#include <vector>

#include "analyze/setup_check.hpp"

namespace fourbar {

/// `[[channel]] name="NAME" KEY`: how a finding names a channel's key.
std::string channel_key(const std::string& name, const std::string& key);
/// What a finding is called to the user: the manifest's own key for a
/// channel's key (a manifest with sensitivity_mV_per_g is told about
/// sensitivity_mV_per_g, not volts_per_unit), else the finding's item.
std::string finding_label(const std::string& item, const std::string& key);

/// Appends the finding with its message ("channel 'X': item: the manifest
/// says …, the data say … (confidence N %); change KEY").
void add_finding(SetupCheck& out, std::string item, std::string channel, std::string key, std::string manifest,
                 std::string data, double confidence);

/// The channel's high-pass corner (sensor_corner.hpp): the manifest's
/// `ac_coupled`/`highpass_hz` against the data's corner (0: DC-coupled).
void add_corner_finding(SetupCheck& out, const ChannelSpec& channel, double data_corner_hz, double crank_hz,
                        double confidence);

/// Every judged accelerometer (at least two) reads the rig's nominal motion
/// at a common factor beyond `tolerance` (same side, e.g. 0.05: 5 %): one
/// sensor's calibration rarely errs like all the others', so the cause is
/// common to all — the rig file's link lengths, the recording's
/// full_scale_V, or its sample rate: a file that says fs while the DAQ
/// sampled at fs·q reads every speed 1/q and every nominal acceleration 1/q²
/// of the truth, so the sensors read q² × the nominal motion (the finding
/// names the q that its factor gives). The finding's confidence is
/// 1 − (the factors' spread / their mean distance from 1): how well the
/// channels agree on one factor. `scales`: |A| of each judged channel (1: as
/// the manifest says); `sample_rate_hz`: the file's.
void add_common_scale_finding(SetupCheck& out, const std::vector<double>& scales, double tolerance,
                              const std::string& rig_file, double sample_rate_hz, double min_confidence);

/// A channel whose scale (|A| with the manifest's position, 1: as the
/// manifest says) lies beyond 1 ± `tolerance` while the scale factor 1.5
/// that the misfit test judges is not reached: a calibration 10–50 % off
/// (a sensitivity from another sensor's sheet, a gain misread). Not when a
/// common_scale finding already names a cause common to every channel. The
/// confidence is 1 − kChannelScaleSpread / |scale − 1|: the spread of the
/// scale on correct manifests against the deviation.
void add_channel_scale_findings(SetupCheck& out, const std::vector<std::pair<const ChannelSpec*, double>>& scales,
                                double tolerance);

/// A channel's calibration off by `ratio` (data/manifest of volts per m/s²):
/// a "volts_per_unit" finding that names the key the manifest used
/// (volts_per_unit, sensitivity_mV_per_m_s2 or sensitivity_mV_per_g) with
/// its values in that key's unit, and says when the ratio is a unit mix-up
/// (unit_mixup()).
void add_calibration_finding(SetupCheck& out, const ChannelSpec& channel, double ratio, double confidence);

/// "" or the unit mix-up a calibration off by `ratio` is (within 3 %):
/// g = 9.81 (mV/g given as mV per m/s², or back), 1000 (mV given as V, or
/// back), 1000 g; and a gain step of 10, which lies within 2 % of g (both
/// named when both fit).
std::string unit_mixup(double ratio);

/// Two or more channels (`scales`: every accelerometer judged on its own
/// link, 1: as the manifest says) read the rig's nominal motion off by more
/// than `tolerance` and by different factors: each sensor then sees the
/// wrong rig's kinematics differently (its link, its distance), the
/// signature of a rig file that is not this rig's. A "rig_file" finding
/// placed first, naming the manifest's `rig` key before the channels'
/// calibration findings (which stand only once the rig file is right), with
/// the highest confidence among them. Not when a common_scale finding
/// names one common factor already.
void add_rig_file_finding(SetupCheck& out, const std::vector<std::pair<const ChannelSpec*, double>>& scales,
                          double tolerance, const std::string& rig_file, const std::string& rig_name);

/// The largest |scale − 1| of a channel on a correct manifest in the
/// set-up check matrix (bench/setup_check_matrix: 0.0225 with three channels,
/// 0.0243 with the coupler's alone), rounded up.
inline constexpr double kChannelScaleSpread = 0.025;

}  // namespace fourbar
