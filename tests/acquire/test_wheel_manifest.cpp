// The manifest keys of tooth wheels and encoders: read, written back
// unchanged, and every inconsistent combination refused naming the key.

#include <gtest/gtest.h>

#include "acquire/manifest.hpp"
#include "common/error.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

using testing::TempDir;

const std::string kHead = R"(rig = "rig.toml"
clearance_mm = 0.254

[[channel]]
index = 0
role = "coupler_tangential"
volts_per_unit = 0.01
position_mm = 309
)";

class WheelManifest : public ::testing::Test {
 protected:
  TempDir dir;
  void SetUp() override { dir.write("rig.toml", testing::thesis_rig_toml()); }
  Manifest load(const std::string& channels) { return load_manifest(dir.write("m.toml", kHead + channels)); }
  std::string error_of(const std::string& channels) {
    try {
      load(channels);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(WheelManifest, ToothWheelWithIndexRoundTrips) {
  const Manifest m = load(R"(
[[channel]]
index = 1
role = "crank_pulse"
pulses_per_rev = 60
correct_tooth_spacing = true
crank_offset_deg = 30
[[channel]]
index = 2
role = "crank_index"
polarity = "falling"
)");
  EXPECT_TRUE(m.multi_edge_angle());
  EXPECT_EQ(m.pulse_channel().pulses_per_rev, 60);
  EXPECT_TRUE(m.pulse_channel().correct_tooth_spacing);
  ASSERT_NE(m.channel_with(ChannelRole::crank_index), nullptr);
  EXPECT_EQ(m.channel_with(ChannelRole::crank_index)->polarity, PulsePolarity::falling);
  const Manifest back = load_manifest(dir.write("back.toml", manifest_to_toml(m, dir.path())));
  EXPECT_EQ(manifest_to_toml(back, dir.path()), manifest_to_toml(m, dir.path()));
  EXPECT_EQ(back.pulse_channel().pulses_per_rev, 60);
}

TEST_F(WheelManifest, EncoderIsTheAngleSource) {
  const Manifest m = load(R"(
[[channel]]
index = 1
role = "encoder_a"
lines_per_rev = 1024
crank_offset_deg = 10
[[channel]]
index = 2
role = "encoder_b"
)");
  EXPECT_TRUE(m.multi_edge_angle());
  EXPECT_EQ(m.pulse_channel().role, ChannelRole::encoder_a);
  EXPECT_EQ(m.pulse_channel().lines_per_rev, 1024);
  const Manifest back = load_manifest(dir.write("back.toml", manifest_to_toml(m, dir.path())));
  EXPECT_EQ(back.pulse_channel().lines_per_rev, 1024);
}

TEST_F(WheelManifest, InconsistentSourcesNameTheKey) {
  EXPECT_NE(error_of("[[channel]]\nindex = 1\nrole = \"crank_pulse\"\npulses_per_rev = 60\n")
                .find("'pulses_per_rev' = 60 needs a way to count turns"),
            std::string::npos);
  EXPECT_NE(error_of("[[channel]]\nindex = 1\nrole = \"crank_pulse\"\npulses_per_rev = 60\nmissing_teeth = 30\n")
                .find("missing_teeth' = 30 must be less than half"),
            std::string::npos);
  EXPECT_NE(error_of("[[channel]]\nindex = 1\nrole = \"crank_pulse\"\n[[channel]]\nindex = 2\nrole = \"crank_index\"\n")
                .find("'pulses_per_rev' is 1"),
            std::string::npos);
  EXPECT_NE(error_of("[[channel]]\nindex = 1\nrole = \"encoder_a\"\nlines_per_rev = 100\n").find("encoder_b"),
            std::string::npos);
  EXPECT_NE(error_of("[[channel]]\nindex = 1\nrole = \"encoder_a\"\n[[channel]]\nindex = 2\nrole = \"encoder_b\"\n")
                .find("lines_per_rev"),
            std::string::npos);
  EXPECT_NE(error_of("[[channel]]\nindex = 1\nrole = \"crank_pulse\"\nlines_per_rev = 100\n").find("lines_per_rev"),
            std::string::npos);
  EXPECT_NE(error_of("[[channel]]\nindex = 1\nrole = \"crank_pulse\"\n[[channel]]\nindex = 2\nrole = "
                     "\"encoder_a\"\nlines_per_rev = 8\n[[channel]]\nindex = 3\nrole = \"encoder_b\"\n")
                .find("both a crank_pulse channel and an encoder"),
            std::string::npos);
}

// crank_smoothing on the main crank channel: off by default, a period of
// 10 turns when asked without one, written back; what cannot smooth refused.
TEST_F(WheelManifest, CrankSmoothingKeys) {
  const std::string pulse = "[[channel]]\nindex = 1\nrole = \"crank_pulse\"\n";
  EXPECT_EQ(load(pulse).pulse_channel().smoothing_period_turns, 0.0);
  EXPECT_EQ(load(pulse + "crank_smoothing = \"none\"\n").pulse_channel().smoothing_period_turns, 0.0);
  EXPECT_EQ(load(pulse + "crank_smoothing = \"spline\"\n").pulse_channel().smoothing_period_turns, 10.0);
  const Manifest m = load(pulse + "crank_smoothing = \"spline\"\nsmoothing_period_turns = 25\n");
  EXPECT_EQ(m.pulse_channel().smoothing_period_turns, 25.0);
  const Manifest back = load_manifest(dir.write("back.toml", manifest_to_toml(m, dir.path())));
  EXPECT_EQ(back.pulse_channel().smoothing_period_turns, 25.0);
  // A 60-tooth wheel smooths down to 0.1 turn; one pulse per turn from 6 turns.
  EXPECT_EQ(load("[[channel]]\nindex = 1\nrole = \"crank_pulse\"\npulses_per_rev = 60\nmissing_teeth = 2\n"
                 "crank_smoothing = \"spline\"\nsmoothing_period_turns = 0.5\n")
                .pulse_channel()
                .smoothing_period_turns,
            0.5);
  EXPECT_NE(error_of(pulse + "crank_smoothing = \"spline\"\nsmoothing_period_turns = 4\n")
                .find("smoothing_period_turns' = 4 is shorter than 6 turns"),
            std::string::npos)
      << error_of(pulse + "crank_smoothing = \"spline\"\nsmoothing_period_turns = 4\n");
  EXPECT_NE(error_of(pulse + "smoothing_period_turns = 20\n").find("crank_smoothing is not \"spline\""),
            std::string::npos);
  EXPECT_NE(error_of(pulse + "crank_smoothing = \"loess\"\n").find("crank_smoothing"), std::string::npos);
  EXPECT_NE(error_of(pulse + "[[channel]]\nindex = 2\nrole = \"coupler_normal\"\nvolts_per_unit = 0.01\n"
                             "position_mm = 1\ncrank_smoothing = \"spline\"\n")
                .find("crank_smoothing"),
            std::string::npos);
}

}  // namespace
}  // namespace fourbar
