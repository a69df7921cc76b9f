// Picking the analysed channels from the manifest (analysis_channels.hpp).
#include "analyze/analysis_channels.hpp"

#include "common/error.hpp"

namespace fourbar {

namespace {

AccelerometerMount mount_of(const Manifest& manifest, const ChannelSpec& c) {
  AccelerometerMount m;
  m.channel = c.name;
  m.link = is_on_coupler(c.role) ? SensedLink::coupler : SensedLink::rocker;
  m.axis = is_tangential(c.role) ? SensorAxis::tangential : SensorAxis::normal;
  m.distance_m = c.position_m;
  m.from = MeasuredFrom::first_joint;
  m.offset_m = c.offset_m;
  m.axis_sign = 1;  // acquire has applied the manifest's axis_sign
  m.high_pass_corner_hz = c.ac_coupled ? c.highpass_hz : 0.0;
  m.sample_delay_s = manifest.sample_delay_s(c);
  m.known_response = daq_filter_sections(manifest.daq_filter);
  if (c.sensor_resonance_hz > 0) m.known_response.push_back({2, c.sensor_resonance_hz, c.sensor_resonance_q});
  return m;
}

}  // namespace

AnalysisChannels analysis_channels(const Manifest& manifest) {
  AnalysisChannels out;
  LinkChannels coupler{SensedLink::coupler, {}, {}}, rocker{SensedLink::rocker, {}, {}};
  std::size_t index = 0;  // among the accelerometer channels, as acquire lists them
  for (const ChannelSpec& c : manifest.channels) {
    if (!is_accelerometer(c.role)) continue;
    LinkChannels& link = is_on_coupler(c.role) ? coupler : rocker;
    std::optional<AnalysisChannel>& slot = is_tangential(c.role) ? link.tangential : link.normal;
    if (slot)
      out.warnings.push_back("channel '" + c.name + "' is a second " + to_string(c.role) + " channel: analysed is '" +
                             slot->mount.channel + "' only");
    else
      slot = AnalysisChannel{index, mount_of(manifest, c)};
    ++index;
  }
  if (!coupler.tangential)
    throw InputError(manifest.file.string() +
                     ": no coupler channel: analyze needs a [[channel]] with role = \"coupler_tangential\" (the "
                     "coupler's angular acceleration comes from it); add it, with its position_mm on the coupler");
  out.links.push_back(coupler);
  if (rocker.tangential) out.links.push_back(rocker);
  else if (rocker.normal)
    out.warnings.push_back("channel '" + rocker.normal->mount.channel +
                           "' (rocker_normal) is not analysed: there is no rocker_tangential channel to check it against");
  return out;
}

std::array<std::optional<ResolvedMount>, 2> tangential_mounts(const Rig& rig, const std::filesystem::path& manifest_file) {
  std::array<std::optional<ResolvedMount>, 2> out;
  for (const LinkChannels& l : analysis_channels(load_manifest(manifest_file)).links)
    if (l.tangential) out[l.link == SensedLink::coupler ? 0 : 1] = resolve_mount(rig, l.tangential->mount);
  return out;
}

}  // namespace fourbar
