#pragma once
// Test and bench support for the set-up check: a virtual-rig recording of
// the thesis rig (nominal or clearance motion, any speed, SNR, AC- or
// DC-coupled sensors) and its manifest with one of the common mistakes
// written into it, as a technician would make it.

#include <cmath>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "acquire/virtual_recording.hpp"
#include "analyze/pipeline.hpp"
#include "virtual_rig/clearance_motion_source.hpp"

namespace fourbar::testing {

enum class Mistake {
  none,
  coupler_sign,      ///< coupler_t axis_sign flipped
  coupler_scale,     ///< coupler_t volts_per_unit × 10
  crank_offset,      ///< crank_offset_deg = 90 (the truth: 0)
  crank_direction,   ///< crank_direction = "cw" on a ccw rig
  coupler_position,  ///< coupler_t position_mm 50 mm off (towards the link's middle)
  swapped,           ///< coupler_t and rocker_t channel indices exchanged
  rocker_sign,       ///< rocker_t axis_sign flipped
  pulse_polarity,    ///< the pulse's other edge ("falling"; the mark starts rising, 10° wide)
  full_scale,        ///< full_scale_V × 1.1 (every channel 10 % high)
  coupler_highpass,  ///< coupler_t ac_coupled with highpass_hz = 5 (the truth: 0.5 Hz, or DC)
  coupler_gain,      ///< coupler_t volts_per_unit × 1.2 (a calibration 20 % off)
};
/// The mistakes a manifest with only the coupler's tangential channel can make.
inline const std::vector<Mistake>& coupler_only_mistakes() {
  static const std::vector<Mistake> m{Mistake::coupler_sign, Mistake::coupler_scale, Mistake::crank_offset,
                                      Mistake::crank_direction, Mistake::coupler_position, Mistake::pulse_polarity,
                                      Mistake::coupler_highpass, Mistake::coupler_gain};
  return m;
}
inline const std::vector<Mistake>& all_mistakes() {
  static const std::vector<Mistake> m{Mistake::coupler_sign,     Mistake::coupler_scale, Mistake::crank_offset,
                                      Mistake::crank_direction,  Mistake::coupler_position, Mistake::swapped,
                                      Mistake::rocker_sign,      Mistake::pulse_polarity, Mistake::full_scale,
                                      Mistake::coupler_highpass, Mistake::coupler_gain};
  return m;
}
inline const char* to_string(Mistake m) {
  switch (m) {
    case Mistake::none: return "none (correct)";
    case Mistake::coupler_sign: return "coupler axis_sign flipped";
    case Mistake::coupler_scale: return "coupler volts_per_unit x10";
    case Mistake::crank_offset: return "crank_offset_deg = 90";
    case Mistake::crank_direction: return "crank_direction cw on ccw";
    case Mistake::coupler_position: return "coupler position 50 mm off";
    case Mistake::swapped: return "coupler/rocker swapped";
    case Mistake::rocker_sign: return "rocker axis_sign flipped";
    case Mistake::pulse_polarity: return "pulse polarity: other edge";
    case Mistake::full_scale: return "full_scale_V x1.1";
    case Mistake::coupler_highpass: return "coupler highpass_hz 5";
    case Mistake::coupler_gain: return "coupler volts_per_unit x1.2";
  }
  return "?";
}
/// The finding's item that names the mistake.
inline const char* expected_item(Mistake m) {
  switch (m) {
    case Mistake::none: return "";
    case Mistake::coupler_sign: return "axis_sign";
    case Mistake::coupler_scale: return "volts_per_unit";
    case Mistake::crank_offset: return "crank_offset_deg";
    case Mistake::crank_direction: return "crank_direction";
    case Mistake::coupler_position: return "position_mm";
    case Mistake::swapped: return "channels_swapped";
    case Mistake::rocker_sign: return "axis_sign";
    case Mistake::pulse_polarity: return "polarity";
    case Mistake::full_scale: return "common_scale";
    case Mistake::coupler_highpass: return "highpass_hz";
    case Mistake::coupler_gain: return "volts_per_unit";
  }
  return "";
}

struct SetupCase {
  double rpm = 350;
  bool clearance = false;  ///< clearance model (0.254 mm, e = 0.5) instead of the nominal motion
  double snr_db = 30;
  bool ac_coupled = false; ///< every accelerometer AC-coupled (0.5 Hz)
  double revolutions = 8;
  double sample_rate_hz = 10240;
  std::uint64_t seed = 1;
  bool coupler_only = false;  ///< only the coupler's tangential sensor (no normal, no rocker channel)
};

/// For test names and failure messages.
inline void PrintTo(const SetupCase& c, std::ostream* os) {
  *os << (c.clearance ? "clearance " : "nominal ") << c.rpm << " rpm " << c.snr_db << " dB "
      << (c.ac_coupled ? "AC" : "DC") << (c.coupler_only ? " coupler only" : "") << " seed " << c.seed;
}

/// Writes the recording of `c` into `v`'s folder; returns the recording path.
inline std::filesystem::path write_setup_case(VirtualSetup& v, const SetupCase& c, const std::string& name) {
  v.scene.crank_speed_rad_s = units::rpm_to_rad_s(c.rpm);
  v.spec.sample_rate_hz = c.sample_rate_hz;
  v.spec.pulse.rise_s = 4.0 / c.sample_rate_hz;
  v.spec.revolutions = c.revolutions;
  v.spec.noise_snr_db = c.snr_db;
  v.spec.seed = c.seed;
  v.spec.speed_fluctuation = 0.005;
  v.spec.sensors.clear();
  ChannelSpec& ct = v.add_sensor("coupler_t", ChannelRole::coupler_tangential, 289, 1);
  ct.offset_m = 0.012;
  if (!c.coupler_only) {
    ChannelSpec& cn = v.add_sensor("coupler_n", ChannelRole::coupler_normal, 289, -1);
    cn.offset_m = 0.012;
    ChannelSpec& rt = v.add_sensor("rocker_t", ChannelRole::rocker_tangential, 292, 1);
    rt.offset_m = 0.010;
  }
  for (ChannelSpec& s : v.spec.sensors) {
    s.volts_per_m_s2 = 0.002;  // ±5000 m/s² at ±10 V: the impacts at 600 rpm fit
    if (c.ac_coupled) s.ac_coupled = true, s.highpass_hz = 0.5;
  }
  const CrankDrive drive = v.drive();
  VirtualRigOptions o;
  o.write_truth = false;
  o.progress = false;
  const auto out = v.dir.path() / name;
  if (!c.clearance) {
    const NominalMotionSource motion(v.scene.rig, drive);
    make_virtual_recording(v.scene, v.spec, drive, motion, out, Provenance{"test", {}}, o);
    return out;
  }
  ClearanceSettings cs;
  cs.restitution = 0.5;
  const double period_s = units::kTwoPi / std::abs(drive.mean_speed_rad_s);
  const double run_in_s = c.ac_coupled ? 12.0 / (units::kTwoPi * 0.5) : 0.0;
  const int warmup = 5;
  v.spec.warmup_revolutions = warmup;
  const ClearanceMotionSource motion(v.scene.rig, drive, cs, v.scene.rig->radial_clearance_m,
                                     -run_in_s - (warmup + 1) * period_s, (c.revolutions + 1) * period_s,
                                     1.0 / c.sample_rate_hz);
  make_virtual_recording(v.scene, v.spec, drive, motion, out, Provenance{"test", {}}, o);
  return out;
}

/// The recording's manifest with `m` written into it, saved beside it; its path.
inline std::filesystem::path manifest_with(const std::filesystem::path& recording, Mistake m) {
  Manifest man = load_manifest(sidecar_manifest_path(recording));
  auto channel = [&](const std::string& name) -> ChannelSpec& {
    for (ChannelSpec& c : man.channels)
      if (c.name == name) return c;
    throw std::runtime_error("no channel " + name);
  };
  switch (m) {
    case Mistake::none: break;
    case Mistake::coupler_sign: channel("coupler_t").axis_sign *= -1; break;
    case Mistake::coupler_scale: channel("coupler_t").volts_per_m_s2 *= 10; break;
    case Mistake::crank_offset: channel("crank_pulse").crank_offset_rad = units::deg_to_rad(90); break;
    case Mistake::crank_direction: man.crank_direction = -1; break;
    case Mistake::coupler_position: channel("coupler_t").position_m -= 0.050; break;
    case Mistake::swapped: std::swap(channel("coupler_t").index, channel("rocker_t").index); break;
    case Mistake::rocker_sign: channel("rocker_t").axis_sign *= -1; break;
    case Mistake::pulse_polarity: channel("crank_pulse").polarity = PulsePolarity::falling; break;
    case Mistake::full_scale: man.full_scale_V *= 1.1; break;
    case Mistake::coupler_highpass: channel("coupler_t").ac_coupled = true, channel("coupler_t").highpass_hz = 5; break;
    case Mistake::coupler_gain: channel("coupler_t").volts_per_m_s2 *= 1.2; break;
  }
  const auto out = recording.parent_path() / (recording.stem().string() + "." + std::to_string(static_cast<int>(m)) + ".toml");
  std::ofstream(out) << manifest_to_toml(man, recording.parent_path());
  return out;
}

/// True when `check` names the mistake (for `none`: when it finds nothing).
inline bool flags(const SetupCheck& check, Mistake m) {
  if (m == Mistake::none) return !check.findings.empty();
  for (const SetupFinding& f : check.findings)
    if (f.item == expected_item(m)) {
      if (m == Mistake::coupler_sign || m == Mistake::coupler_scale || m == Mistake::coupler_position ||
          m == Mistake::coupler_highpass || m == Mistake::coupler_gain)
        return f.channel == "coupler_t";
      if (m == Mistake::rocker_sign) return f.channel == "rocker_t";
      return true;
    }
  return false;
}

}  // namespace fourbar::testing
