// analyze_recording with the crank angle integrated from a speed channel
// (role = "crank_speed", acquire/speed_angle.hpp) against the virtual rig's
// truth: the virtual rig's recording rewritten with the crank speed of its
// own drive as an extra channel (a tacho voltage, 100 rpm per V), at a
// constant 350 rpm and in a run-up from 250 to 350 rpm; with the once-per-turn
// pulse for the angle's zero, and without it (the pulse channel ignored).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "acquire/wheel_setup.hpp"
#include "virtual_rig/recording_writer.hpp"
#include "virtual_session.hpp"

namespace fourbar {
namespace {

using testing::rel_rms_error;
using testing::row_mean;
using testing::VirtualSetup;

constexpr double kRpmPerV = 100;

/// The recording `written` with the drive's speed appended as a channel
/// ('tacho', in volts), and its manifest: crank_speed, the pulse kept for the
/// zero or ignored.
std::filesystem::path with_speed_channel(const VirtualSetup& v, const VirtualRigResult& written, bool keep_pulse,
                                         const std::string& name, double stall_from_s = -1, double stall_to_s = -1,
                                         bool known_offset = false) {
  const auto reader = open_recording(written.recording, {});
  const RecordingInfo& info = reader->info();
  const auto C = static_cast<std::size_t>(info.channels);
  std::vector<double> all(static_cast<std::size_t>(info.frames) * C);
  EXPECT_EQ(reader->read(all), info.frames);
  Manifest m = load_manifest(written.manifest);
  const CrankDrive drive = v.drive();
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(info.frames) * (C + 1));
  for (std::size_t f = 0; f < info.frames; ++f) {
    for (std::size_t c = 0; c < C; ++c) out.push_back(all[f * C + c]);
    const double t = static_cast<double>(f) / info.sample_rate_hz;
    const double rpm = t >= stall_from_s && t <= stall_to_s ? 0.0 : units::rad_s_to_rpm(std::abs(drive.at(t).speed_rad_s));
    out.push_back(rpm / kRpmPerV / m.full_scale_V);
  }
  const std::filesystem::path file = v.dir.path() / (name + ".wav");
  std::vector<std::string> names(C + 1, "x");
  auto w = open_recording_writer(file, static_cast<int>(C + 1), info.sample_rate_hz, names, "float", {});
  w->write(out);
  w->commit();
  ChannelSpec tacho;
  tacho.name = "tacho";
  tacho.role = ChannelRole::crank_speed;
  tacho.index = static_cast<int>(C);
  tacho.rpm_per_V = kRpmPerV;
  if (known_offset) tacho.crank_offset_given = true, tacho.crank_offset_rad = drive.at(0).angle_rad;
  if (!keep_pulse)
    for (ChannelSpec& c : m.channels)
      if (c.role == ChannelRole::crank_pulse) c.role = ChannelRole::ignore;
  m.channels.push_back(tacho);
  std::ofstream(sidecar_manifest_path(file)) << manifest_to_toml(m, v.dir.path());
  return file;
}

struct Outcome {
  double alpha3 = 0, omega3 = 0;  ///< averaged, relative RMS error (without a zero: at the best shift)
  std::size_t turns = 0, expected_turns = 0, revolutions = 0;
  double first_turn_offset_s = 0;  ///< first turn's start − first pulse written
  bool zero_warning = false;
};

/// The best circular shift's relative RMS error (the phase is arbitrary without a zero).
double best_shift_error(const std::vector<double>& est, const std::vector<double>& truth) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<double> shifted(est.size());
  for (std::size_t s = 0; s < est.size(); ++s) {
    for (std::size_t k = 0; k < est.size(); ++k) shifted[k] = est[(k + s) % est.size()];
    best = std::min(best, rel_rms_error(shifted, truth));
  }
  return best;
}

Outcome run(VirtualSetup& v, bool keep_pulse, const std::string& name, bool known_offset = false) {
  const VirtualRigResult written = v.write(name + "_src.wav", false);
  const std::filesystem::path file = with_speed_channel(v, written, keep_pulse, name, -1, -1, known_offset);
  AnalyzeOptions o;
  o.keep_revolutions = true;
  o.progress = false;
  const RecordingAnalysis a = analyze_recording(file, {}, o);
  Outcome r;
  for (const auto& seg : a.acquisition.pulses.segments) r.turns += seg.size() - 1;
  r.revolutions = a.revolutions;
  for (const auto& w : a.acquisition.warnings)
    if (w.find("zero is unknown") != std::string::npos) r.zero_warning = true;
  const CrankDrive drive = v.drive();
  const double end_s = static_cast<double>(written.frames - 1) / written.sample_rate_hz;
  const std::size_t N = a.grid_points_per_rev;
  if (keep_pulse) {
    r.expected_turns = written.pulse_times_s.size() - 1;
    r.first_turn_offset_s = a.acquisition.pulses.segments.front().front().time_s - written.pulse_times_s.front();
    const testing::GridTruth t = testing::grid_truth(v, written, a, a.revolution_numbers);
    r.alpha3 = rel_rms_error(a.coupler->alpha_rad_s2.mean, row_mean(t.alpha3, N));
    r.omega3 = rel_rms_error(a.coupler->omega_rad_s.mean, row_mean(t.omega3, N));
  } else {
    const double turned = std::abs(drive.at(end_s).angle_rad - drive.at(0).angle_rad);
    r.expected_turns = static_cast<std::size_t>(std::floor(turned / units::kTwoPi));
    // The turns start where the recording starts: truth from the drive's angle at t = 0.
    const NominalMotionSource motion(v.scene.rig, drive);
    std::vector<double> a3, w3;
    for (std::size_t rev : a.revolution_numbers)
      for (std::size_t k = 0; k < N; ++k) {
        const double th = units::kTwoPi * (static_cast<double>(rev) + static_cast<double>(k) / N);
        const LinkState s = motion.at(drive.time_at_turned(th));
        a3.push_back(s.alpha3_rad_s2), w3.push_back(s.omega3_rad_s);
      }
    r.alpha3 = rel_rms_error(a.coupler->alpha_rad_s2.mean, row_mean(a3, N));
    r.omega3 = rel_rms_error(a.coupler->omega_rad_s.mean, row_mean(w3, N));
    // Even at the best shift of the crank angle the averages stay wrong: the
    // conversion used the wrong crank angle (gravity, the sensor's offset).
    std::printf("    at the best shift: a3 %.4f %%  w3 %.4f %%\n", 100 * best_shift_error(a.coupler->alpha_rad_s2.mean, row_mean(a3, N)),
                100 * best_shift_error(a.coupler->omega_rad_s.mean, row_mean(w3, N)));
  }
  std::printf("  %-28s %3zu turns (expected %3zu), %3zu revs  a3 %.4f %%  w3 %.4f %%  first turn - first pulse %.2e s%s\n",
              name.c_str(), r.turns, r.expected_turns, r.revolutions, 100 * r.alpha3, 100 * r.omega3,
              r.first_turn_offset_s, r.zero_warning ? "  [zero unknown warning]" : "");
  return r;
}

VirtualSetup lab(double rpm) {
  VirtualSetup v(rpm);
  testing::housing_sensors(v);
  v.spec.revolutions = 30;
  v.spec.seed = 77;
  v.spec.noise_snr_db = 30;
  v.spec.pulse.noise_V = 2.5 / 31.62;
  return v;
}

/// 250 → 350 rpm: ω = 250 rpm·(1 + 0.4·sin(2πt/T)) with T four times the recording.
VirtualSetup run_up() {
  VirtualSetup v = lab(250);
  const double duration_s = v.spec.revolutions.value_or(30) * 60.0 / 300;  // about: the mean is near 300 rpm
  v.spec.speed_fluctuation = 0.4;
  v.spec.speed_fluctuation_period_s = 4 * duration_s;
  return v;
}

TEST(AnalyzeSpeedChannel, ConstantSpeedWithPulseForTheZero) {
  VirtualSetup v = lab(350);
  const Outcome r = run(v, true, "constant_pulse");
  EXPECT_EQ(r.turns, r.expected_turns);
  EXPECT_EQ(r.revolutions, r.turns);
  EXPECT_LT(std::abs(r.first_turn_offset_s), 2e-5);  // half a sample at 25.6 kHz
  EXPECT_LE(r.alpha3, 0.005);
  EXPECT_LE(r.omega3, 0.001);
  EXPECT_FALSE(r.zero_warning);
}

TEST(AnalyzeSpeedChannel, RunUpWithPulseForTheZero) {
  VirtualSetup v = run_up();
  const Outcome r = run(v, true, "runup_pulse");
  EXPECT_EQ(r.turns, r.expected_turns);
  EXPECT_EQ(r.revolutions, r.turns);
  EXPECT_LT(std::abs(r.first_turn_offset_s), 2e-5);
  EXPECT_LE(r.alpha3, 0.005);
  EXPECT_LE(r.omega3, 0.001);
}

// Without a pulse the zero is unknown: the turns are counted right and the
// warning says what it means; α and ω are then wrong (measured and printed:
// the conversion needs the crank angle), and right again when
// crank_offset_deg gives the crank angle at the first sample.
TEST(AnalyzeSpeedChannel, WithoutPulseTheZeroIsUnknownAndSaid) {
  for (bool runup : {false, true}) {
    VirtualSetup v = runup ? run_up() : lab(350);
    const Outcome r = run(v, false, runup ? "runup_alone" : "constant_alone");
    EXPECT_TRUE(r.zero_warning);
    EXPECT_EQ(r.turns, r.expected_turns);
    EXPECT_EQ(r.revolutions, r.turns);
    VirtualSetup k = runup ? run_up() : lab(350);
    const Outcome known = run(k, false, runup ? "runup_offset_given" : "constant_offset_given", true);
    EXPECT_FALSE(known.zero_warning);
    EXPECT_EQ(known.turns, known.expected_turns);
    EXPECT_LE(known.alpha3, 0.005);
    EXPECT_LE(known.omega3, 0.001);
  }
}

// A stop in the speed track (0 rpm from 2.0 to 2.5 s) cannot be integrated to
// a turn count: refused naming the channel, the span and the fix.
TEST(AnalyzeSpeedChannel, AStopInTheTrackIsRefusedNamingTheSpan) {
  VirtualSetup v = lab(350);
  v.spec.revolutions = 20;
  const VirtualRigResult written = v.write("stall_src.wav", false);
  const std::filesystem::path file = with_speed_channel(v, written, false, "stall", 2.0, 2.5);
  AnalyzeOptions o;
  o.progress = false;
  std::string what;
  try {
    analyze_recording(file, {}, o);
  } catch (const InputError& e) {
    what = e.what();
  }
  std::printf("  %s\n", what.c_str());
  EXPECT_NE(what.find("'tacho'"), std::string::npos) << what;
  EXPECT_NE(what.find("from 2 s"), std::string::npos) << what;
  EXPECT_NE(what.find("start_s/end_s"), std::string::npos) << what;
  // The running part before the stop reads.
  AnalyzeOptions before = o;
  before.range.end_s = 1.9;
  const RecordingAnalysis a = analyze_recording(file, {}, before);
  EXPECT_GE(a.revolutions, 9u);
}

}  // namespace
}  // namespace fourbar
