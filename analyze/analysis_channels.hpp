#pragma once
// Which of the manifest's accelerometer channels analyze uses, and how each
// is mounted: the first channel of each role, coupler first, then rocker.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "acquire/manifest.hpp"
#include "analyze/sensor_mount.hpp"

namespace fourbar {

/// The manifest's accelerometer channels as analyze uses them.
struct AnalysisChannel {
  std::size_t index = 0;  ///< in acquire's channel list (SampleBlock::channels_m_s2)
  AccelerometerMount mount;
};
struct LinkChannels {
  SensedLink link = SensedLink::coupler;
  std::optional<AnalysisChannel> tangential, normal;
};
struct AnalysisChannels {
  std::vector<LinkChannels> links;  ///< coupler first, then rocker; only links with a tangential channel
  std::vector<std::string> warnings;
};

/// Picks the channels (the first of each role; InputError when the manifest
/// has no coupler_tangential channel). Mounts in SI, axis sign +1 (acquire
/// applies the manifest's sign).
AnalysisChannels analysis_channels(const Manifest& manifest);

/// The tangential accelerometers analyze uses, resolved on `rig`: the
/// coupler's [0] and the rocker's [1] (absent: no such channel), from the
/// manifest file (the report's and the fit's linkage references read them there).
std::array<std::optional<ResolvedMount>, 2> tangential_mounts(const Rig& rig, const std::filesystem::path& manifest_file);

}  // namespace fourbar
