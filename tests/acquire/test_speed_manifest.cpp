// The manifest of a speed channel as crank source (role = "crank_speed",
// acquire/speed_angle.hpp): read and written back, with or without a pulse for
// the zero; two speed channels, or one beside an encoder, an index or a
// tooth wheel, refused naming the channel and the fix.

#include <gtest/gtest.h>

#include <cmath>

#include "acquire/manifest.hpp"
#include "acquire/speed_angle.hpp"
#include "common/units.hpp"
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

// The virtual edges against the closed form of a linear run-up, 250 → 350 rpm
// in 2 s at 1 kHz (the last sample at 1.999 s) (the speed linear between samples: the trapezoid integral
// is exact): θ(t) = ω0·t + β·t²/2, so edge p at t = (√(ω0² + 2β·θp) − ω0)/β.
// With pulses where θ = 2π·k + 1 rad the turns start at the pulses.
TEST(SpeedAngle, EdgesOfALinearRunUpMatchTheClosedForm) {
  const double fs = 1000, w0 = 250 * units::kPi / 30, w1 = 350 * units::kPi / 30, beta = (w1 - w0) / 2;
  std::vector<double> rpm;
  for (int i = 0; i < 2000; ++i) rpm.push_back((w0 + beta * i / fs) * 30 / units::kPi);
  ChannelSpec speed;
  speed.name = "tacho", speed.role = ChannelRole::crank_speed, speed.index = 1;
  auto time_at = [&](double theta) { return (std::sqrt(w0 * w0 + 2 * beta * theta) - w0) / beta; };
  const SpeedAngle alone = speed_angle_edges(rpm, fs, 0, speed, nullptr, {}, {}, "m.toml");
  ASSERT_EQ(alone.edges.segments.size(), 1u);
  const NumberedSegment& seg = alone.edges.segments[0];
  EXPECT_EQ(alone.edges.positions_per_rev, kSpeedPositionsPerRev);
  EXPECT_FALSE(alone.zero_known);
  ASSERT_EQ(alone.warnings.size(), 1u);
  EXPECT_NE(alone.warnings[0].find("zero is unknown"), std::string::npos);
  const double T = 1.999, total = w0 * T + beta * T * T / 2;  // θ at the last sample
  EXPECT_EQ(seg.time_s.size(), static_cast<std::size_t>(std::floor(total / (2 * units::kPi / 360))) + 1);
  double worst = 0;
  for (std::size_t i = 0; i < seg.time_s.size(); ++i) {
    EXPECT_EQ(seg.position[i], static_cast<std::int64_t>(i));
    worst = std::max(worst, std::abs(seg.time_s[i] - time_at(2 * units::kPi * static_cast<double>(i) / 360)));
  }
  EXPECT_LT(worst, 1e-9);

  ChannelSpec pulse;
  pulse.name = "pulse", pulse.role = ChannelRole::crank_pulse, pulse.index = 2;
  std::vector<double> pulses;
  for (int k = 0; 2 * units::kPi * k + 1 < total; ++k) pulses.push_back(time_at(2 * units::kPi * k + 1));
  const SpeedAngle zeroed = speed_angle_edges(rpm, fs, 0, speed, &pulse, pulses, {}, "m.toml");
  EXPECT_TRUE(zeroed.zero_known);
  EXPECT_LT(zeroed.zero_spread_deg, 1e-6);
  EXPECT_TRUE(zeroed.warnings.empty());
  const NumberedSegment& z = zeroed.edges.segments.at(0);
  EXPECT_EQ(z.position.front(), 0);
  EXPECT_NEAR(z.time_s.front(), pulses.front(), 1e-9);
  for (std::size_t i = 0; i < z.time_s.size(); ++i)
    if (z.position[i] % 360 == 0) EXPECT_NEAR(z.time_s[i], pulses.at(static_cast<std::size_t>(z.position[i] / 360)), 1e-9);
}

}  // namespace
}  // namespace fourbar
