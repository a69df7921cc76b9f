// The manifest: every key read, strict about misspelt and missing keys and
// channels the recording lacks; manifest_to_toml reads back unchanged.

#include <gtest/gtest.h>

#include "acquire/manifest.hpp"
#include "common/error.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

using testing::replace;
using testing::TempDir;

const std::string kManifest = R"(rig = "rig.toml"
clearance_mm = 0.1
full_scale_V = 10
adc_range_V = 9.5
crank_direction = "cw"
notes = "bench test"

[[channel]]
index = 0
name = "ct"
role = "coupler_tangential"
sensitivity_mV_per_m_s2 = 1.02
gain = 10
axis_sign = -1
position_mm = 309
offset_mm = 12
ac_coupled = true
highpass_hz = 0.3

[[channel]]
index = 1
role = "rocker_tangential"
volts_per_unit = 0.005
position_mm = 300

[[channel]]
index = 2
role = "crank_pulse"
polarity = "falling"
threshold_low_V = 1.0
threshold_high_V = 2.0
crank_offset_deg = 12.5
debounce_ms = 3

[[channel]]
index = 3
role = "ignore"
notes = "spare"
)";

class ManifestTest : public ::testing::Test {
 protected:
  TempDir dir;
  void SetUp() override { dir.write("rig.toml", testing::thesis_rig_toml()); }
  std::string error_of(const std::string& text) {
    try {
      load_manifest(dir.write("m.toml", text));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  RecordingInfo recording(int channels, std::vector<std::string> names = {}) {
    RecordingInfo r;
    r.file = dir.path() / "rec.wav";
    r.channels = channels;
    r.channel_names = names.empty() ? std::vector<std::string>(static_cast<std::size_t>(channels)) : names;
    return r;
  }
};

TEST_F(ManifestTest, ReadsEveryKey) {
  Manifest m = load_manifest(dir.write("m.toml", kManifest));
  EXPECT_NEAR(m.clearance_m, 0.1e-3, 1e-15);
  EXPECT_EQ(m.full_scale_V, 10);
  EXPECT_EQ(m.adc_range_V.value(), 9.5);
  EXPECT_EQ(m.crank_direction, -1);
  ASSERT_EQ(m.channels.size(), 4u);
  const ChannelSpec& ct = m.channels[0];
  EXPECT_EQ(ct.name, "ct");
  EXPECT_NEAR(ct.volts_per_m_s2, 1.02e-3 * 10, 1e-15);
  EXPECT_EQ(ct.axis_sign, -1);
  EXPECT_NEAR(ct.position_m, 0.309, 1e-15);
  EXPECT_NEAR(ct.offset_m, 0.012, 1e-15);
  EXPECT_TRUE(ct.ac_coupled);
  EXPECT_EQ(ct.highpass_hz, 0.3);
  EXPECT_EQ(m.channels[1].name, "rocker_tangential");
  EXPECT_EQ(m.channels[1].volts_per_m_s2, 0.005);
  const ChannelSpec& p = m.pulse_channel();
  EXPECT_EQ(p.polarity, PulsePolarity::falling);
  EXPECT_EQ(p.threshold_low_V.value(), 1.0);
  EXPECT_NEAR(p.crank_offset_rad, 12.5 * M_PI / 180, 1e-15);
  EXPECT_NEAR(p.debounce_s, 3e-3, 1e-15);
  EXPECT_EQ(m.rig->name, "thesis");
  bind_channels(m, recording(4));
  EXPECT_EQ(m.channels[3].index.value(), 3);
}

TEST_F(ManifestTest, WritesWhatItReads) {
  Manifest m = load_manifest(dir.write("m.toml", kManifest));
  const std::string text = manifest_to_toml(m, dir.path());
  EXPECT_NE(text.find("rig = \"rig.toml\""), std::string::npos) << text;
  Manifest back = load_manifest(dir.write("back.toml", text));
  ASSERT_EQ(back.channels.size(), m.channels.size());
  EXPECT_EQ(back.clearance_m, m.clearance_m);
  EXPECT_EQ(back.crank_direction, m.crank_direction);
  EXPECT_EQ(back.adc_range_V, m.adc_range_V);
  for (std::size_t i = 0; i < m.channels.size(); ++i) {
    EXPECT_EQ(back.channels[i].name, m.channels[i].name);
    EXPECT_EQ(back.channels[i].role, m.channels[i].role);
    EXPECT_EQ(back.channels[i].index, m.channels[i].index);
    EXPECT_DOUBLE_EQ(back.channels[i].volts_per_m_s2, m.channels[i].volts_per_m_s2);
    EXPECT_EQ(back.channels[i].axis_sign, m.channels[i].axis_sign);
    EXPECT_DOUBLE_EQ(back.channels[i].position_m, m.channels[i].position_m);
    EXPECT_DOUBLE_EQ(back.channels[i].offset_m, m.channels[i].offset_m);
    EXPECT_EQ(back.channels[i].highpass_hz, m.channels[i].highpass_hz);
    EXPECT_EQ(back.channels[i].polarity, m.channels[i].polarity);
    EXPECT_EQ(back.channels[i].threshold_high_V, m.channels[i].threshold_high_V);
    EXPECT_DOUBLE_EQ(back.channels[i].crank_offset_rad, m.channels[i].crank_offset_rad);
    EXPECT_DOUBLE_EQ(back.channels[i].debounce_s, m.channels[i].debounce_s);
  }
}

TEST_F(ManifestTest, MisspeltKeyIsAnErrorWithASuggestion) {
  const std::string e = error_of(replace(kManifest, "position_mm = 309", "positon_mm = 309"));
  EXPECT_NE(e.find("m.toml"), std::string::npos) << e;
  EXPECT_NE(e.find("position_mm"), std::string::npos) << e;
  const std::string top = error_of(replace(kManifest, "clearance_mm", "clearence_mm"));
  EXPECT_NE(top.find("unknown key 'clearence_mm' (did you mean 'clearance_mm'?)"), std::string::npos) << top;
  const std::string role = error_of(replace(kManifest, "\"rocker_tangential\"", "\"rocker_tangental\""));
  EXPECT_NE(role.find("did you mean 'rocker_tangential'"), std::string::npos) << role;
}

TEST_F(ManifestTest, MissingKeysAreErrors) {
  EXPECT_NE(error_of(replace(kManifest, "rig = \"rig.toml\"\n", "")).find("missing key 'rig'"), std::string::npos);
  EXPECT_NE(error_of(replace(kManifest, "volts_per_unit = 0.005\n", "")).find("sensitivity_mV_per_m_s2"),
            std::string::npos);
  EXPECT_NE(error_of(replace(kManifest, "position_mm = 300\n", "")).find("missing key 'channel[1].position_mm'"),
            std::string::npos)
      << error_of(replace(kManifest, "position_mm = 300\n", ""));
  EXPECT_NE(error_of(replace(kManifest, "index = 1\n", "")).find("'index'"), std::string::npos);
  EXPECT_NE(error_of(replace(kManifest, "threshold_high_V = 2.0\n", "")).find("give both"), std::string::npos);
  EXPECT_NE(error_of(replace(kManifest, "role = \"ignore\"", "role = \"crank_pulse\"")).find("exactly one"),
            std::string::npos);
}

TEST_F(ManifestTest, ChannelOutOfRangeNamesTheChannel) {
  Manifest m = load_manifest(dir.write("m.toml", replace(kManifest, "index = 3\n", "index = 7\n")));
  try {
    bind_channels(m, recording(4));
    FAIL();
  } catch (const InputError& e) {
    const std::string s = e.what();
    EXPECT_NE(s.find("channel[3] ('ignore'): index = 7 but"), std::string::npos) << s;
    EXPECT_NE(s.find("has 4 channels (indices 0..3)"), std::string::npos) << s;
  }
}

TEST_F(ManifestTest, ColumnsBindByName) {
  std::string text = replace(kManifest, "index = 0\n", "column = \"acc_ct\"\n");
  Manifest m = load_manifest(dir.write("m.toml", text));
  bind_channels(m, recording(4, {"acc_ct", "b", "c", "d"}));
  EXPECT_EQ(m.channels[0].index.value(), 0);
  Manifest bad = load_manifest(dir.write("m2.toml", text));
  try {
    bind_channels(bad, recording(4, {"acc_c", "b", "c", "d"}));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'acc_c'"), std::string::npos) << e.what();
  }
  Manifest twice = load_manifest(dir.write("m3.toml", replace(kManifest, "index = 1\n", "index = 0\n")));
  EXPECT_THROW(bind_channels(twice, recording(4)), InputError);
}

TEST(Manifest, SidecarPath) {
  EXPECT_EQ(sidecar_manifest_path("/a/b/REC.wav"), std::filesystem::path("/a/b/REC.toml"));
  EXPECT_EQ(sidecar_manifest_path("REC.flac"), std::filesystem::path("REC.toml"));
}

}  // namespace
}  // namespace fourbar
