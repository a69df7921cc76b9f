#pragma once
// The warnings acquire gives once all passes are done: clipped accelerometer
// channels, pulse-train repairs, gaps and isolated pulses, and a sample rate
// too coarse for the crank speed. (Warnings about the pulse channel's levels
// come with the thresholds: pulse_thresholds.hpp.)

#include <string>
#include <vector>

namespace fourbar {

struct AcquisitionReport;

/// Frames per revolution below which impact bursts are not resolved.
inline constexpr double kMinFramesPerRev = 64;

/// In the order they are reported.
std::vector<std::string> collect_warnings(const AcquisitionReport& report);

}  // namespace fourbar
