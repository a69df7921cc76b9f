// The manifest template: refused while a "FILL IN" is left (naming the first
// one by line and key), accepted once every placeholder holds a value, and
// faithful to what inspect found (channels, pulse channel and polarity,
// column names quoted through toml_quoted).

#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "acquire/inspect.hpp"
#include "acquire/manifest.hpp"
#include "acquire/manifest_template.hpp"
#include "common/error.hpp"
#include "format_writers.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

using testing::TempDir;

std::string load_error(const std::filesystem::path& f) {
  try {
    load_manifest(f);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Every `key = "FILL IN"` line with a value a technician would give.
std::string fill_in(const std::string& text) {
  static const std::map<std::string, std::string> values{
      {"rig", "\"rig.toml\""},        {"full_scale_V", "10"},    {"crank_direction", "\"ccw\""},
      {"role", "\"rocker_normal\""},  {"volts_per_unit", "0.01"}, {"axis_sign", "-1"},
      {"position_mm", "100"},         {"ac_coupled", "false"},   {"crank_offset_deg", "12.5"},
      {"clearance_mm", "0.1"}};
  std::istringstream in(text);
  std::ostringstream out;
  const std::regex placeholder(R"(^(\w+) = "FILL IN".*$)");
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_match(line, m, placeholder)) line = m[1].str() + " = " + values.at(m[1].str());
    out << line << "\n";
  }
  return out.str();
}

TEST(ManifestTemplate, RefusedUntilFilledInThenAcceptedAsInspected) {
  TempDir dir;
  dir.write("rig.toml", testing::thesis_rig_toml());
  const auto rec = dir.path() / "r.wav";
  testing::write_sndfile(rec, SF_FORMAT_WAV | SF_FORMAT_PCM_24, testing::inspection_signals());
  const RecordingInspection r = inspect_recording(*open_recording(rec));
  const std::string text = manifest_template(r, {});
  const auto manifest = dir.write("r.toml", text);

  const std::string e = load_error(manifest);
  EXPECT_EQ(e.rfind(manifest.string() + ":6: rig is still \"FILL IN\"", 0), 0u) << e << "\n" << text;
  EXPECT_NE(e.find("placeholders are left"), std::string::npos) << e;

  // One placeholder left deep in a channel table: named as channel[i].key.
  std::string almost = fill_in(text);
  almost = std::regex_replace(almost, std::regex("position_mm = 100"), "position_mm = \"FILL IN\"",
                              std::regex_constants::format_first_only);
  dir.write("r.toml", almost);
  const std::string e2 = load_error(manifest);
  EXPECT_NE(e2.find(": channel[0].position_mm is still \"FILL IN\""), std::string::npos) << e2;
  EXPECT_EQ(e2.find("placeholders are left"), std::string::npos) << e2;

  dir.write("r.toml", fill_in(text));
  Manifest m = load_manifest(manifest);
  // Channels 0 and 2 (continuous signals) and the pulse on 1; the dead channel 3 is left out.
  ASSERT_EQ(m.channels.size(), 3u);
  EXPECT_EQ(m.channels[0].index, 0);
  EXPECT_EQ(m.channels[1].index, 1);
  EXPECT_EQ(m.channels[1].role, ChannelRole::crank_pulse);
  EXPECT_EQ(m.channels[1].polarity, PulsePolarity::rising);
  EXPECT_DOUBLE_EQ(m.channels[1].crank_offset_rad, 12.5 * std::numbers::pi / 180);
  EXPECT_EQ(m.channels[2].index, 2);
  EXPECT_DOUBLE_EQ(m.channels[2].volts_per_m_s2, 0.01);
  EXPECT_DOUBLE_EQ(m.full_scale_V, 10);
  EXPECT_NE(text.find("CLIPPED"), std::string::npos) << "the clipped channel is flagged in its comment";

  // The smoothing keys offered as comments on the pulse channel load as written once uncommented.
  std::string smoothed = fill_in(text);
  smoothed = std::regex_replace(smoothed, std::regex("# (crank_smoothing = |smoothing_period_turns = )"), "$1");
  dir.write("r.toml", smoothed);
  const Manifest ms = load_manifest(manifest);
  EXPECT_DOUBLE_EQ(ms.channels[1].smoothing_period_turns, 10) << smoothed;
}

TEST(ManifestTemplate, NamedChannelsByColumnRateVariableAndVoltUnits) {
  TempDir dir;
  dir.write("rig.toml", testing::thesis_rig_toml());
  auto s = testing::inspection_signals();
  s.names[2] = "odd \"name\"\tx\ny\x01";  // quoted and escaped in the template, and in its comments
  const auto rec = dir.path() / "r.mat";
  testing::write_mat(rec, MAT_FT_MAT5, s, "Fs");
  const auto r = inspect_recording(*open_recording(rec));
  const std::string text = manifest_template(r, {});
  EXPECT_NE(text.find("rate_variable = \"Fs\""), std::string::npos) << text;
  EXPECT_NE(text.find("column = \"odd \\\"name\\\"\\tx\\ny\\u0001\""), std::string::npos) << text;
  EXPECT_NE(text.find("# channel 2 'odd \"name\"\tx\\x0Ay\\x01'"), std::string::npos) << text;
  EXPECT_NE(text.find("role = \"coupler_tangential\"  # from its name"), std::string::npos) << text;
  const auto manifest = dir.write("r.toml", fill_in(text));
  Manifest m = load_manifest(manifest);
  bind_channels(m, open_recording(rec, m.reader_options())->info());
  EXPECT_EQ(m.channels[2].index, 2);
  EXPECT_EQ(*m.channels[2].column, s.names[2]);

  // A text export in V: full_scale_V = 1 comes from the units row.
  const auto csv = dir.path() / "e.csv";
  testing::write_csv_with_units_row(csv, testing::inspection_signals());
  const std::string csv_text = manifest_template(inspect_recording(*open_recording(csv)), {});
  EXPECT_NE(csv_text.find("full_scale_V = 1  # the export states every channel in V"), std::string::npos) << csv_text;
}

}  // namespace
}  // namespace fourbar
