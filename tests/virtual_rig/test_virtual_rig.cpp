// The virtual rig's recording: noise at the asked SNR, mains hum, float
// quantisation, pulse width, the truth file, and the [recording] table's
// validation.

#include <gtest/gtest.h>

#include <cmath>

#include "acquire/reader.hpp"
#include "acquire/virtual_recording.hpp"
#include "common/error.hpp"

namespace fourbar {
namespace {

using testing::VirtualSetup;

std::vector<double> read_all(const std::filesystem::path& f) {
  auto r = open_recording(f);
  std::vector<double> all(r->info().frames * static_cast<std::size_t>(r->info().channels));
  r->read(all);
  return all;
}

TEST(VirtualRig, NoiseAtTheAskedSnrAndHumAtMainsFrequency) {
  VirtualSetup v;
  v.spec.revolutions = 6;
  v.spec.sample_format = "double";
  const auto clean = read_all(v.write("clean.wav", false).recording);
  v.spec.noise_snr_db = 30;
  const VirtualRigResult noisy_r = v.write("noisy.wav", false);
  const auto noisy = read_all(noisy_r.recording);
  v.spec.noise_snr_db.reset();
  v.spec.hum_V = 0.02;
  v.spec.hum_harmonics = {1.0, 0.5};
  v.spec.hum_frequency_hz = 60;
  const auto hum = read_all(v.write("hum.wav", false).recording);
  const std::size_t nch = 4, frames = clean.size() / nch;
  for (std::size_t c = 0; c < 3; ++c) {
    double sig = 0, sig_sq = 0, noise_sq = 0;
    for (std::size_t i = 0; i < frames; ++i) {
      sig += clean[i * nch + c], sig_sq += clean[i * nch + c] * clean[i * nch + c];
      const double e = noisy[i * nch + c] - clean[i * nch + c];
      noise_sq += e * e;
    }
    const double n = static_cast<double>(frames);
    const double snr = 10 * std::log10((sig_sq / n - (sig / n) * (sig / n)) / (noise_sq / n));
    EXPECT_NEAR(snr, 30.0, 0.5) << c;
    EXPECT_NEAR(std::sqrt(noise_sq / n), noisy_r.noise_V[c], 0.03 * noisy_r.noise_V[c]);
    // Hum: amplitudes at 60 and 120 Hz by projection on sine and cosine.
    for (int h : {1, 2, 3}) {
      double sc = 0, cc = 0;
      for (std::size_t i = 0; i < frames; ++i) {
        const double t = static_cast<double>(i) / v.spec.sample_rate_hz, e = hum[i * nch + c] - clean[i * nch + c];
        sc += e * std::sin(2 * M_PI * 60 * h * t), cc += e * std::cos(2 * M_PI * 60 * h * t);
      }
      const double amplitude = 2 * std::hypot(sc, cc) / n;
      EXPECT_NEAR(amplitude, h == 1 ? 0.02 : h == 2 ? 0.01 : 0.0, 2e-4) << c << " harmonic " << h;
    }
  }
  // The pulse channel carries neither.
  for (std::size_t i = 0; i < frames; ++i) ASSERT_EQ(hum[i * nch + 3], clean[i * nch + 3]);
}

TEST(VirtualRig, FloatOutputQuantisedToAskedBits) {
  VirtualSetup v;
  v.spec.revolutions = 2;
  v.spec.sample_format = "double";
  v.spec.quantisation_bits = 12;
  const auto x = read_all(v.write("q.caf", false).recording);
  const double step = v.spec.full_scale_V / 2048;
  for (std::size_t i = 0; i < x.size(); i += 4) ASSERT_NEAR(std::remainder(x[i], step), 0.0, 1e-12) << i;
}

TEST(VirtualRig, PulseWidthLevelsAndTruthFile) {
  VirtualSetup v;
  v.spec.revolutions = 5;
  v.spec.pulse.low_V = 0.5;
  v.spec.pulse.high_V = 4.5;
  const VirtualRigResult r = v.write("p.wav");
  const auto x = read_all(r.recording);
  const std::size_t frames = x.size() / 4;
  std::size_t high = 0;
  double lo = 1e9, hi = -1e9;
  for (std::size_t i = 0; i < frames; ++i) {
    const double volts = x[i * 4 + 3] * v.spec.full_scale_V;
    high += volts > 2.5;
    lo = std::min(lo, volts), hi = std::max(hi, volts);
  }
  EXPECT_NEAR(lo, 0.5, 1e-5);
  EXPECT_NEAR(hi, 4.5, 1e-5);
  // 10° of each of the pulses inside the recording.
  const double per_pulse = 10.0 / 360 * 60 / 350 * v.spec.sample_rate_hz;
  EXPECT_NEAR(static_cast<double>(high), per_pulse * static_cast<double>(r.pulse_times_s.size()), 2.0 * r.pulse_times_s.size());
  // Pulses where θ2 passes the pulse angle (0).
  const CrankDrive d = v.drive();
  for (double t : r.pulse_times_s) EXPECT_NEAR(std::remainder(d.at(t).angle_rad, 2 * M_PI), 0.0, 1e-9);
  // Truth file: one row per sample, crank angle first, consistent with the drive.
  const auto truth = testing::read_csv_table(r.truth);
  ASSERT_EQ(truth.rows(), frames);
  EXPECT_EQ(truth.header.front(), "crank_deg");
  for (std::size_t i = 0; i < frames; i += 997) {
    EXPECT_NEAR(truth["theta2_rad"][i], d.at(truth["time_s"][i]).angle_rad, 1e-12);
    EXPECT_NEAR(truth["crank_deg"][i], truth["theta2_rad"][i] * 180 / M_PI, 1e-9);
  }
  // The manifest beside it names the channels in order.
  const Manifest m = load_manifest(r.manifest);
  ASSERT_EQ(m.channels.size(), 4u);
  EXPECT_EQ(m.channels[3].role, ChannelRole::crank_pulse);
  EXPECT_EQ(m.channels[1].axis_sign, -1);
  EXPECT_EQ(m.full_scale_V, 10);
}

class RecordingSpecErrors : public ::testing::Test {
 protected:
  testing::TempDir dir;
  std::string error_of(const std::string& recording) {
    dir.write("rig.toml", testing::thesis_rig_toml());
    const auto f = dir.write("s.toml", "rig = \"rig.toml\"\ncrank_speed_rpm = 300\noutputs = [\"time_s\"]\n" + recording);
    try {
      read_recording_spec(load_scene(f));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(RecordingSpecErrors, NameTheKey) {
  const std::string ok = "[recording]\nsample_rate_hz = 1000\nduration_s = 1\n[recording.pulse]\n";
  EXPECT_EQ(error_of(ok), "");
  EXPECT_NE(error_of("").find("no [recording] table"), std::string::npos);
  EXPECT_NE(error_of("[recording]\nduration_s = 1\n[recording.pulse]\n").find("missing key 'recording.sample_rate_hz'"),
            std::string::npos);
  EXPECT_NE(error_of("[recording]\nsample_rate_hz = 1000\nduration_s = 1\nrevolutions = 3\n[recording.pulse]\n")
                .find("give exactly one"),
            std::string::npos);
  EXPECT_NE(error_of(ok + "jitter_ms = 3\n").find("unknown key 'recording.pulse.jitter_ms'"), std::string::npos)
      << error_of(ok + "jitter_ms = 3\n");
  EXPECT_NE(error_of(ok + "missing = [1, -2]\n").find("s.toml:8: key 'recording.pulse.missing' must hold only"),
            std::string::npos)
      << error_of(ok + "missing = [1, -2]\n");
  EXPECT_NE(error_of(ok + "[[recording.sensor]]\nrole = \"crank_pulse\"\n").find("is not one of"), std::string::npos);
  EXPECT_NE(error_of(ok + "[[recording.sensor]]\nrole = \"rocker_normal\"\nvolts_per_unit = 0.01\n")
                .find("missing key 'recording.sensor[0].position_mm'"),
            std::string::npos);
  EXPECT_NE(error_of("[recording]\nsample_rate_hz = 1000\nduration_s = 1\nsample_format = \"pcm16\"\n"
                     "quantisation_bits = 12\n[recording.pulse]\n")
                .find("is for float or text outputs"),
            std::string::npos);
  EXPECT_NE(error_of("[recording]\nsample_rate_hz = 1000\nduration_s = 1\nhum_harmonics = [\"a\"]\n[recording.pulse]\n")
                .find("recording.hum_harmonics"),
            std::string::npos);
}

// [recording.wheel] index_offset_pitch: read within one pitch (an encoder's:
// one quadrature edge) so that tooth 0 is the edge the index names; an index
// is needed.
TEST_F(RecordingSpecErrors, IndexOffsetPitch) {
  const std::string head = "[recording]\nsample_rate_hz = 1000\nduration_s = 1\n[recording.pulse]\n[recording.wheel]\n";
  dir.write("rig.toml", testing::thesis_rig_toml());
  const auto f = dir.write("ok.toml", "rig = \"rig.toml\"\ncrank_speed_rpm = 300\noutputs = [\"time_s\"]\n" + head +
                                          "teeth = 60\nindex = true\nindex_offset_pitch = 0\n");
  const RecordingSpec spec = read_recording_spec(load_scene(f));
  ASSERT_TRUE(spec.wheel.index_offset_pitch.has_value());
  EXPECT_EQ(*spec.wheel.index_offset_pitch, 0.0);
  EXPECT_EQ(error_of(head + "encoder_lines = 256\nindex = true\nindex_offset_pitch = 0\n"), "");
  EXPECT_NE(error_of(head + "teeth = 60\nindex = true\nindex_offset_pitch = 0.5\n").find("index_offset_pitch"),
            std::string::npos);
  EXPECT_NE(error_of(head + "encoder_lines = 256\nindex = true\nindex_offset_pitch = 0.2\n").find("index_offset_pitch"),
            std::string::npos);
  EXPECT_NE(error_of(head + "teeth = 60\nmissing_teeth = 2\nindex_offset_pitch = 0\n").find("set index = true"),
            std::string::npos)
      << error_of(head + "teeth = 60\nmissing_teeth = 2\nindex_offset_pitch = 0\n");
}

}  // namespace
}  // namespace fourbar
