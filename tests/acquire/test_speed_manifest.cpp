// The manifest of a speed channel as crank source (role = "crank_speed",
// acquire/speed_angle.hpp): read and written back, with or without a pulse for
// the zero; two speed channels, or one beside an encoder, an index or a
// tooth wheel, refused naming the channel and the fix.

#include <gtest/gtest.h>

#include "acquire/manifest.hpp"
#include "common/error.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

using testing::TempDir;

const std::string kHead = R"(rig = "rig.toml"

[[channel]]
index = 0
role = "coupler_tangential"
volts_per_unit = 0.01
position_mm = 309
)";

const std::string kSpeed = R"(
[[channel]]
index = 1
name = "tacho"
role = "crank_speed"
rpm_per_V = 100
)";

class SpeedManifest : public ::testing::Test {
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

TEST_F(SpeedManifest, SpeedAloneRoundTrips) {
  const Manifest m = load(kSpeed);
  ASSERT_NE(m.speed_channel(), nullptr);
  EXPECT_EQ(m.speed_channel()->name, "tacho");
  EXPECT_EQ(m.speed_channel()->rpm_per_V.value_or(0), 100);
  EXPECT_EQ(&m.pulse_channel(), m.speed_channel());  // no pulse: the speed channel is the source
  EXPECT_FALSE(is_accelerometer(ChannelRole::crank_speed));
  const Manifest back = load_manifest(dir.write("back.toml", manifest_to_toml(m, dir.path())));
  EXPECT_EQ(manifest_to_toml(back, dir.path()), manifest_to_toml(m, dir.path()));
  EXPECT_EQ(back.speed_channel()->rpm_per_V.value_or(0), 100);
  EXPECT_FALSE(back.speed_channel()->crank_offset_given);
  const Manifest given = load(kSpeed + "crank_offset_deg = 40\n");
  EXPECT_TRUE(given.speed_channel()->crank_offset_given);
  const Manifest given_back = load_manifest(dir.write("given.toml", manifest_to_toml(given, dir.path())));
  EXPECT_NEAR(given_back.pulse_channel().crank_offset_rad, 40 * 3.14159265358979 / 180, 1e-9);
}

TEST_F(SpeedManifest, RpmWithoutScaleAndAPulseForTheZero) {
  const Manifest m = load(R"(
[[channel]]
index = 1
role = "crank_speed"
[[channel]]
index = 2
role = "crank_pulse"
crank_offset_deg = 30
)");
  ASSERT_NE(m.speed_channel(), nullptr);
  EXPECT_FALSE(m.speed_channel()->rpm_per_V.has_value());
  EXPECT_EQ(m.pulse_channel().role, ChannelRole::crank_pulse);  // its offset applies
  EXPECT_NEAR(m.pulse_channel().crank_offset_rad, 30 * 3.14159265358979 / 180, 1e-12);
}

TEST_F(SpeedManifest, ConflictingSourcesAreRefused) {
  const std::string two = error_of(kSpeed + R"(
[[channel]]
index = 2
role = "crank_speed"
)");
  EXPECT_NE(two.find("2 channels have role = \"crank_speed\""), std::string::npos) << two;
  EXPECT_NE(two.find("ignore"), std::string::npos) << two;
  const std::string enc = error_of(kSpeed + R"(
[[channel]]
index = 2
role = "encoder_a"
lines_per_rev = 100
[[channel]]
index = 3
role = "encoder_b"
)");
  EXPECT_NE(enc.find("'tacho'"), std::string::npos) << enc;
  EXPECT_NE(enc.find("one source"), std::string::npos) << enc;
  const std::string wheel = error_of(kSpeed + R"(
[[channel]]
index = 2
role = "crank_pulse"
pulses_per_rev = 60
missing_teeth = 2
)");
  EXPECT_NE(wheel.find("pulses_per_rev"), std::string::npos) << wheel;
  const std::string offset = error_of(kSpeed + R"(crank_offset_deg = 12
[[channel]]
index = 2
role = "crank_pulse"
)");
  EXPECT_NE(offset.find("crank_offset_deg"), std::string::npos) << offset;
  const std::string scale = error_of(R"(
[[channel]]
index = 1
role = "crank_speed"
rpm_per_V = -3
)");
  EXPECT_NE(scale.find("rpm_per_V"), std::string::npos) << scale;
  const std::string stray = error_of(R"(
[[channel]]
index = 1
role = "crank_speed"
pulses_per_rev = 60
)");
  EXPECT_NE(stray.find("pulses_per_rev"), std::string::npos) << stray;
}

}  // namespace
}  // namespace fourbar
