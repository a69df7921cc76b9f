// `fourbar inspect`'s statistics on every format fourbar reads: the same
// channels (a sine with a DC offset, a pulse train, a clipped sine, a dead
// channel) written by libsndfile, libmatio and as a text export; the
// statistics, the pulse rate and the clipping against their closed forms.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "acquire/inspect.hpp"
#include "acquire/reader.hpp"
#include "support/temp_dir.hpp"
#include "format_writers.hpp"

namespace fourbar {
namespace {

using testing::TempDir;

struct FormatCase {
  const char* label;
  const char* file;
  std::function<void(const std::filesystem::path&, const testing::TestSignals&)> write;
  double tolerance;  ///< the format's quantisation
  bool integer;      ///< clipping shows as samples at the digital rails
  bool named;        ///< channels carry names
};

std::vector<FormatCase> format_cases() {
  using namespace fourbar::testing;
  return {
      {"wav_pcm16", "r.wav", [](auto& f, auto& s) { write_sndfile(f, SF_FORMAT_WAV | SF_FORMAT_PCM_16, s); }, 2e-4, true, false},
      {"flac_pcm24", "r.flac", [](auto& f, auto& s) { write_sndfile(f, SF_FORMAT_FLAC | SF_FORMAT_PCM_24, s); }, 1e-6, true, false},
      {"rf64_float", "r.rf64", [](auto& f, auto& s) { write_sndfile(f, SF_FORMAT_RF64 | SF_FORMAT_FLOAT, s); }, 1e-7, false, false},
      {"mat_v5", "r.mat", [](auto& f, auto& s) { write_mat(f, MAT_FT_MAT5, s); }, 1e-12, false, true},
      {"mat_v5_compressed", "r.mat", [](auto& f, auto& s) { write_mat(f, MAT_FT_MAT5, s, "fs", MAT_COMPRESSION_ZLIB); }, 1e-12, false, true},
      {"mat_v73", "r.mat", [](auto& f, auto& s) { write_mat(f, MAT_FT_MAT73, s); }, 1e-12, false, true},
      {"csv_units_row", "r.csv", [](auto& f, auto& s) { write_csv_with_units_row(f, s); }, 1e-12, false, true},
  };
}

class InspectFormat : public ::testing::TestWithParam<FormatCase> {};

TEST_P(InspectFormat, StatisticsPulseAndClippingMatchTheWrittenSignals) {
  const FormatCase& fc = GetParam();
  TempDir dir;
  const auto signals = testing::inspection_signals();
  const auto file = dir.path() / fc.file;
  fc.write(file, signals);
  const auto reader = open_recording(file);
  const RecordingInspection r = inspect_recording(*reader);
  const double tol = fc.tolerance;

  EXPECT_DOUBLE_EQ(r.info.sample_rate_hz, 10000.0);
  EXPECT_EQ(r.info.frames, testing::kFrames);
  ASSERT_EQ(r.channels.size(), 4u);
  if (fc.named)
    for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(r.channels[c].name, signals.names[c]);

  // Sine with DC: closed forms over whole periods.
  const ChannelInspection& sine = r.channels[0];
  EXPECT_NEAR(sine.mean, 0.1, tol);
  EXPECT_NEAR(sine.ac_rms, 0.5 / std::sqrt(2.0), tol);
  EXPECT_NEAR(sine.rms, std::sqrt(0.01 + 0.125), tol);
  EXPECT_NEAR(sine.min, -0.4, tol);
  EXPECT_NEAR(sine.max, 0.6, tol);
  EXPECT_FALSE(sine.clipped());
  EXPECT_FALSE(sine.pulse);

  // The pulse train: 20 Hz → 1200 rpm, short state high, the one crank pulse.
  const ChannelInspection& pulse = r.channels[1];
  ASSERT_TRUE(pulse.pulse);
  EXPECT_EQ(r.pulse_channel, 1);
  EXPECT_EQ(pulse.role, "crank_pulse");
  EXPECT_NEAR(pulse.pulse->rate_hz, 20.0, 1e-9);
  EXPECT_NEAR(pulse.pulse->rpm, 1200.0, 1e-7);
  EXPECT_EQ(pulse.pulse->pulses, testing::kFrames / testing::kPulsePeriod);
  EXPECT_TRUE(pulse.pulse->short_state_high);
  EXPECT_NEAR(pulse.pulse->high_fraction, 0.05, 1e-9);
  EXPECT_NEAR(pulse.mean, 0.05 * testing::kPulseHigh, tol);

  // The clipped channel: at the rails (integer formats) or flat at its extremes.
  const ChannelInspection& clipped = r.channels[2];
  const auto n_clipped = testing::clipped_count(signals);
  EXPECT_TRUE(clipped.clipped());
  EXPECT_FALSE(clipped.pulse) << "a clipped sine is not a pulse train";
  if (fc.integer) EXPECT_EQ(clipped.rail_samples, n_clipped);
  else EXPECT_EQ(clipped.rail_samples, 0u);
  EXPECT_EQ(clipped.flat_extreme_samples, n_clipped);
  EXPECT_NE(clipped.reason.find("CLIPPED"), std::string::npos) << clipped.reason;

  // The dead channel.
  EXPECT_TRUE(r.channels[3].constant);
  EXPECT_EQ(r.channels[3].role, "ignore");
  // Roles from names where the format has names.
  if (fc.named) EXPECT_EQ(r.channels[0].role, "coupler_tangential") << r.channels[0].reason;
  else EXPECT_EQ(r.channels[0].role, "") << "no name, no data clue: the role is left to the technician";
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, InspectFormat, ::testing::ValuesIn(format_cases()),
                         [](const auto& info) { return std::string(info.param.label); });

TEST(Inspect, LowGoingPulseTrainLeadsWithItsFallingEdge) {
  TempDir dir;
  auto s = testing::inspection_signals();
  for (double& v : s.columns[1]) v = testing::kPulseHigh - v;  // high, with short low pulses
  testing::write_sndfile(dir.path() / "r.wav", SF_FORMAT_WAV | SF_FORMAT_FLOAT, s);
  const auto r = inspect_recording(*open_recording(dir.path() / "r.wav"));
  ASSERT_TRUE(r.channels[1].pulse);
  EXPECT_FALSE(r.channels[1].pulse->short_state_high);
  EXPECT_NEAR(r.channels[1].pulse->rate_hz, 20.0, 1e-9);
}

TEST(Inspect, NoisePureSineAndSquareWaveOfHalfDuty) {
  // A sine spends 59 % of the time near its extremes: not a pulse train; a
  // 50 % square wave is one (either state may mark the crank).
  TempDir dir;
  auto s = testing::inspection_signals();
  std::uint64_t state = 12345;
  for (std::size_t i = 0; i < testing::kFrames; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    s.columns[2][i] = static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5;  // uniform noise
    s.columns[3][i] = (i / 250) % 2 ? 1.0 : -1.0;                                  // 20 Hz square wave
  }
  testing::write_sndfile(dir.path() / "r.wav", SF_FORMAT_WAV | SF_FORMAT_DOUBLE, s);
  const auto r = inspect_recording(*open_recording(dir.path() / "r.wav"));
  EXPECT_FALSE(r.channels[0].pulse);
  EXPECT_FALSE(r.channels[2].pulse);
  ASSERT_TRUE(r.channels[3].pulse);
  EXPECT_NEAR(r.channels[3].pulse->rate_hz, 20.0, 1e-9);
  EXPECT_EQ(r.pulse_channel, 1) << "the 5 % pulse and the square wave are both perfectly regular: the first wins";
  EXPECT_EQ(r.channels[3].role, "") << "only one channel gets the crank_pulse role";
}

TEST(Inspect, RoleFromName) {
  EXPECT_EQ(role_from_name("coupler_t"), "coupler_tangential");
  EXPECT_EQ(role_from_name("Coupler_Tangential"), "coupler_tangential");
  EXPECT_EQ(role_from_name("rocker_n"), "rocker_normal");
  EXPECT_EQ(role_from_name("rocker normal [V]"), "rocker_normal");
  EXPECT_EQ(role_from_name("crank pulse"), "crank_pulse");
  EXPECT_EQ(role_from_name("coupler"), "") << "no axis in the name";
  EXPECT_EQ(role_from_name("coupler_rocker_t"), "") << "two links";
  EXPECT_EQ(role_from_name("ai0"), "");
}

}  // namespace
}  // namespace fourbar
