#include "virtual_rig/wheel_signal.hpp"

#include <cmath>
#include <random>

#include "common/units.hpp"

namespace fourbar {

std::vector<double> wheel_tooth_errors_rad(const WheelSpec& w, std::uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  std::vector<double> err(static_cast<std::size_t>(w.encoder_lines > 0 ? w.encoder_lines : w.teeth), 0.0);
  for (auto& e : err) e = w.tooth_error_rad * uni(rng);
  err[0] = 0;  // position 0 is where angle_deg says
  return err;
}

std::vector<EdgeChannel> wheel_channels(const WheelSpec& w, const CrankDrive& drive, double angle_rad,
                                        double duration_s, double margin_s, const std::string& main_name,
                                        std::uint64_t seed) {
  const bool encoder = w.encoder_lines > 0;
  const int P = encoder ? w.encoder_lines : w.teeth;
  const double pitch = units::kTwoPi / P;
  const double direction = drive.mean_speed_rad_s > 0 ? 1.0 : -1.0;
  // Tooth errors: one draw per position, from their own generator.
  const std::vector<double> err = wheel_tooth_errors_rad(w, seed);
  // Turned angle (from the drive's start) of position 0 in the first turn.
  const double base = std::fmod(std::fmod(direction * (angle_rad - drive.start_angle_rad), units::kTwoPi) + units::kTwoPi,
                                units::kTwoPi);
  auto time_at = [&](double turned) { return drive.time_at_turned(direction * turned); };

  std::vector<EdgeChannel> out;
  out.push_back({main_name, encoder ? ChannelRole::encoder_a : ChannelRole::crank_pulse, {}});
  if (encoder) out.push_back({"encoder_b", ChannelRole::encoder_b, {}});
  if (w.index) out.push_back({"crank_index", ChannelRole::crank_index, {}});
  for (long long turn = -1;; ++turn) {
    const double t0 = base + units::kTwoPi * static_cast<double>(turn);
    if (time_at(t0) - margin_s > duration_s) break;
    for (int k = 0; k < P; ++k) {
      if (!encoder && k >= P - w.missing_teeth) break;
      const double a = t0 + pitch * k + err[static_cast<std::size_t>(k)];
      const double lead = time_at(a), trail = time_at(a + 0.5 * pitch);
      if (trail < -margin_s || lead - margin_s > duration_s) continue;
      out[0].pulses.push_back({lead, trail});
      if (encoder) out[1].pulses.push_back({time_at(a + 0.25 * pitch), time_at(a + 0.75 * pitch)});
    }
    if (w.index) {
      // At offset 0 the leading edge is position 0's own edge time (the
      // same number, as a gate driven by that edge gives).
      const double offset = w.index_offset_pitch.value_or(encoder ? -0.125 : -0.25);
      const double lead = t0 + offset * pitch;
      out.back().pulses.push_back({time_at(lead), time_at(lead + 0.25 * pitch)});
    }
  }
  return out;
}

ChannelSpec wheel_manifest_channel(const WheelSpec& w, const EdgeChannel& ch, double angle_rad) {
  ChannelSpec c;
  c.name = ch.name;
  c.role = ch.role;
  if (ch.role == ChannelRole::crank_pulse) {
    c.pulses_per_rev = w.teeth;
    c.missing_teeth = w.missing_teeth;
  }
  if (ch.role == ChannelRole::encoder_a) c.lines_per_rev = w.encoder_lines;
  if (ch.role == ChannelRole::crank_pulse || ch.role == ChannelRole::encoder_a) {
    c.crank_offset_rad = angle_rad;
    c.correct_tooth_spacing = w.correct_tooth_spacing;
  }
  return c;
}

}  // namespace fourbar
