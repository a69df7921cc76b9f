// Units in text exports: in the header (`coupler_t [V]`) or in a row under
// it; the channel keeps its bare name, and a manifest column that matches
// none is an error listing the columns found.

#include <gtest/gtest.h>

#include "acquire/csv_units.hpp"
#include "acquire/manifest.hpp"
#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "support/temp_dir.hpp"
#include "read_recording.hpp"

namespace fourbar {
namespace {

using testing::read_all;
using testing::TempDir;

TEST(CsvUnits, SplitUnit) {
  EXPECT_EQ(split_unit("coupler_t [V]").name, "coupler_t");
  EXPECT_EQ(split_unit("coupler_t [V]").unit, "V");
  EXPECT_EQ(split_unit("  acc[m/s^2] ").unit, "m/s^2");
  EXPECT_EQ(split_unit("acc (mV)").unit, "mV");
  EXPECT_EQ(split_unit("data(:,1)").name, "data(:,1)") << "MATLAB-style names keep their brackets";
  EXPECT_EQ(split_unit("data(:,1)").unit, "");
  EXPECT_EQ(split_unit("[V]").name, "[V]") << "no name left: the cell is the name";
  EXPECT_EQ(split_unit("a [b [c]]").unit, "") << "nested brackets: not a unit";
}

TEST(CsvUnits, Latin1HeadersBecomeUtf8) {
  EXPECT_EQ(as_utf8("acc [m/s\xB2]"), "acc [m/s\xC2\xB2]") << "Latin-1 superscript two";
  EXPECT_EQ(as_utf8("acc [m/s\xC2\xB2]"), "acc [m/s\xC2\xB2]") << "already UTF-8: unchanged";
  EXPECT_EQ(as_utf8("\xE2\x82"), "\xC3\xA2\xC2\x82") << "a cut UTF-8 sequence is not UTF-8";
  EXPECT_EQ(as_utf8("\xC0\xAF"), "\xC3\x80\xC2\xAF") << "an overlong form is not UTF-8";
  TempDir dir;
  const auto f = dir.write("r.csv", "time_s;Beschleunigung [m/s\xB2];Impuls\n0;1;0\n0,1;2;5\n");
  auto r = open_recording(f);
  EXPECT_EQ(r->info().channel_units[0], "m/s\xC2\xB2");
}

TEST(CsvUnits, UnitsRowDetection) {
  EXPECT_TRUE(is_units_row({"s", "V", "[V]"}));
  EXPECT_TRUE(is_units_row({"s", "", "V"}));
  EXPECT_FALSE(is_units_row({"", ""}));
  EXPECT_FALSE(is_units_row({"0,001", "V"})) << "a number (decimal comma) makes it a data row";
  EXPECT_FALSE(is_units_row({"1e-3", "2"}));
}

TEST(CsvUnits, HeaderUnitsGiveBareNames) {
  TempDir dir;
  const auto f = dir.write("r.csv", "time [ms];coupler_t [V];pulse (V)\n0;1,5;0\n1;2,5;5\n2;3,5;0\n");
  auto r = open_recording(f);
  EXPECT_EQ(r->info().channel_names, (std::vector<std::string>{"coupler_t", "pulse"}));
  EXPECT_EQ(r->info().channel_units, (std::vector<std::string>{"V", "V"}));
  EXPECT_NEAR(r->info().sample_rate_hz, 1000.0, 1e-9);
  EXPECT_EQ(read_all(*r, 2), (std::vector<double>{1.5, 0, 2.5, 5, 3.5, 0}));
}

TEST(CsvUnits, UnitsRowUnderTheHeaderIsReadAndSkipped) {
  TempDir dir;
  const auto f = dir.write("r.csv", "# LabVIEW export\ntime,coupler_t,rocker_t\n# units:\nms,[V],mV\n0,1,2\n0.5,3,4\n1,5,6\n");
  auto r = open_recording(f);
  EXPECT_EQ(r->info().frames, 3u);
  EXPECT_EQ(r->info().channel_names, (std::vector<std::string>{"coupler_t", "rocker_t"}));
  EXPECT_EQ(r->info().channel_units, (std::vector<std::string>{"V", "mV"}));
  EXPECT_NEAR(r->info().sample_rate_hz, 2000.0, 1e-9) << "the units row says the time is in ms";
  EXPECT_EQ(read_all(*r, 2), (std::vector<double>{1, 2, 3, 4, 5, 6}));
  r->rewind();
  EXPECT_EQ(read_all(*r, 2), (std::vector<double>{1, 2, 3, 4, 5, 6}));
}

TEST(CsvUnits, AFirstRowWithSomeNumbersIsDataAndItsTextAnError) {
  TempDir dir;
  const auto f = dir.write("r.csv", "time_s,a,b\n0,x,2\n0.1,1,2\n");
  try {
    auto r = open_recording(f);
    read_all(*r, 2);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(f.string() + ":2:2 (column 'a'): 'x' is not a finite number"), std::string::npos)
        << e.what();
  }
}

TEST(CsvUnits, ManifestColumnMatchesWithOrWithoutItsUnitAndAMismatchListsTheColumns) {
  TempDir dir;
  const auto f = dir.write("r.csv", "time_s,coupler_t [V],crank_pulse [V]\n0,1,0\n0.1,2,5\n");
  auto r = open_recording(f);
  Manifest m;
  m.file = dir.path() / "r.toml";
  ChannelSpec a, b;
  a.name = "a", a.column = "coupler_t";
  b.name = "b", b.column = "crank_pulse [V]";
  m.channels = {a, b};
  bind_channels(m, r->info());
  EXPECT_EQ(m.channels[0].index, 0);
  EXPECT_EQ(m.channels[1].index, 1);

  m.channels = {a};
  m.channels[0].column = "coupler_tan";
  try {
    bind_channels(m, r->info());
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("column 'coupler_tan' is not in " + f.string() + " (did you mean 'coupler_t'?)"), std::string::npos) << what;
    EXPECT_NE(what.find("its channels are 'coupler_t', 'crank_pulse'"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace fourbar
