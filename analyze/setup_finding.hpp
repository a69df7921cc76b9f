#pragma once
// A set-up check's finding as the technician reads it: which item, the
// manifest's value, the data's value, how sure, and the key to change.

#include <string>
#include <vector>

#include "analyze/setup_check.hpp"

namespace fourbar {

/// `[[channel]] name="NAME" KEY`: how a finding names a channel's key.
std::string channel_key(const std::string& name, const std::string& key);

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
/// common to all — the rig file's link lengths, or the recording's
/// full_scale_V. The finding's confidence is 1 − (the factors' spread /
/// their mean distance from 1): how well the channels agree on one factor.
/// `scales`: |A| of each judged channel (1: as the manifest says).
void add_common_scale_finding(SetupCheck& out, const std::vector<double>& scales, double tolerance,
                              const std::string& rig_file, double min_confidence);

}  // namespace fourbar
