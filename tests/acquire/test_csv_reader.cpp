// The delimited-text reader: delimiters, comments, blank lines, time column,
// decimal comma, and errors that name file:line:column.

#include <gtest/gtest.h>

#include <cmath>

#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "support/temp_dir.hpp"
#include "read_recording.hpp"

namespace fourbar {
namespace {

using testing::read_all;
using testing::read_error_of;
using testing::TempDir;

TEST(CsvReader, CommaWithCommentsBlankLinesAndTimeColumn) {
  TempDir dir;
  const auto f = dir.write("r.csv",
                           "# exported by the DAQ\n\n"
                           "time_s,acc,pulse\n"
                           "0.5,1.25,0\n"
                           "# a comment between rows\n"
                           "\n"
                           "0.501,-2e-3,5\r\n"
                           "0.502,3,0\n"
                           "0.503,4,0\n");
  auto r = open_recording(f);
  EXPECT_EQ(r->info().format, "CSV");
  EXPECT_EQ(r->info().channels, 2);
  EXPECT_EQ(r->info().frames, 4u);
  EXPECT_NEAR(r->info().sample_rate_hz, 1000.0, 1e-9);
  EXPECT_DOUBLE_EQ(r->info().start_time_s, 0.5);
  EXPECT_EQ(r->info().channel_names, (std::vector<std::string>{"acc", "pulse"}));
  const auto v = read_all(*r, 3);
  EXPECT_EQ(v, (std::vector<double>{1.25, 0, -2e-3, 5, 3, 0, 4, 0}));
  r->rewind();
  EXPECT_EQ(read_all(*r, 3), v);
}

TEST(CsvReader, SemicolonWithDecimalCommaAndTab) {
  TempDir dir;
  const auto semi = dir.write("s.csv", "t;a;b\n0;1,5;-2\n0,001;2,25;3\n");
  auto r = open_recording(semi);
  EXPECT_EQ(read_all(*r, 3), (std::vector<double>{1.5, -2, 2.25, 3}));
  EXPECT_NEAR(r->info().sample_rate_hz, 1000.0, 1e-9);
  const auto tab = dir.write("t.tsv", "time [ms]\ta\tb\n0\t1\t2\n0.5\t3\t4\n1.0\t5\t6\n");
  auto t = open_recording(tab);
  EXPECT_NEAR(t->info().sample_rate_hz, 2000.0, 1e-9);
  EXPECT_EQ(read_all(*t, 3), (std::vector<double>{1, 2, 3, 4, 5, 6}));
}

TEST(CsvReader, NoTimeColumnTakesTheManifestRate) {
  TempDir dir;
  const auto f = dir.write("n.csv", "a,b\n1,2\n3,4\n");
  EXPECT_NE(read_error_of(f, {}, 3).find("no time column"), std::string::npos) << read_error_of(f, {}, 3);
  ReaderOptions o;
  o.sample_rate_hz = 100;
  auto r = open_recording(f, o);
  EXPECT_EQ(r->info().sample_rate_hz, 100);
  EXPECT_EQ(r->info().channels, 2);
  o.sample_rate_hz = 0;
  EXPECT_NE(read_error_of(f, o, 3).find("must be positive"), std::string::npos);
}

TEST(CsvReader, NamedTimeColumn) {
  TempDir dir;
  const auto f = dir.write("n.csv", "a,clock\n1,0\n3,0.01\n");
  ReaderOptions o;
  o.time_column = "clock";
  auto r = open_recording(f, o);
  EXPECT_NEAR(r->info().sample_rate_hz, 100, 1e-9);
  EXPECT_EQ(r->info().channel_names, std::vector<std::string>{"a"});
  o.time_column = "clok";
  EXPECT_NE(read_error_of(f, o, 3).find("did you mean 'clock'"), std::string::npos) << read_error_of(f, o, 3);
}

TEST(CsvReader, BadCellsNameFileLineAndColumn) {
  TempDir dir;
  const auto nan = dir.write("nan.csv", "time_s,a,b\n0,1,2\n0.1,NaN,2\n0.2,1,2\n");
  EXPECT_NE(read_error_of(nan, {}, 3).find("nan.csv:3:2 (column 'a'): 'NaN' is not a finite number"), std::string::npos)
      << read_error_of(nan, {}, 3);
  const auto garbage = dir.write("g.csv", "# c\ntime_s,a\n0,1\n0.1,1.2.3\n");
  EXPECT_NE(read_error_of(garbage, {}, 3).find("g.csv:4:2"), std::string::npos) << read_error_of(garbage, {}, 3);
  const auto empty_cell = dir.write("e.csv", "time_s,a\n0,1\n0.1,\n0.2,1\n");
  EXPECT_NE(read_error_of(empty_cell, {}, 3).find("e.csv:3:2"), std::string::npos) << read_error_of(empty_cell, {}, 3);
  const auto short_row = dir.write("short.csv", "time_s,a,b\n0,1,2\n0.1,1\n");
  EXPECT_NE(read_error_of(short_row, {}, 3).find("short.csv:3: 2 cells but the header has 3"), std::string::npos)
      << read_error_of(short_row, {}, 3);
  const auto gap = dir.write("gap.csv", "time_s,a\n0,1\n0.1,1\n0.3,1\n0.4,1\n0.5,1\n");
  EXPECT_NE(read_error_of(gap, {}, 3).find("gap.csv:4:1 (column 'time_s'): time 0.3 s is not uniform"), std::string::npos) << read_error_of(gap, {}, 3);
  const auto constant = dir.write("c.csv", "time_s,a\n1,1\n1,2\n");
  EXPECT_NE(read_error_of(constant, {}, 3).find("zero sample rate"), std::string::npos) << read_error_of(constant, {}, 3);
  const auto header_only = dir.write("h.csv", "# only\ntime_s,a\n");
  EXPECT_NE(read_error_of(header_only, {}, 3).find("no data rows"), std::string::npos) << read_error_of(header_only, {}, 3);
  const auto dup = dir.write("d.csv", "time_s,a,a\n0,1,2\n");
  EXPECT_NE(read_error_of(dup, {}, 3).find("appears twice"), std::string::npos) << read_error_of(dup, {}, 3);
}

TEST(ReaderRegistry, UnknownAndMissingFiles) {
  TempDir dir;
  const auto f = dir.write("r.dat", "garbage that is no recording");
  const std::string e = read_error_of(f, {}, 3);
  EXPECT_NE(e.find("unknown recording format"), std::string::npos) << e;
  EXPECT_NE(e.find("'.dat'"), std::string::npos) << e;
  EXPECT_NE(read_error_of(dir.path() / "none.wav", {}, 3).find("no such file"), std::string::npos);
  const auto empty = dir.write("e.wav", "");
  EXPECT_NE(read_error_of(empty, {}, 3).find("empty"), std::string::npos);
}

TEST(CsvReader, HeaderBelowAPreambleOrOnTheManifestsLine) {
  TempDir dir;
  // Preamble lines of other cell counts, one of as many cells as the data
  // ("Channels;…") and a units row under the header.
  const auto f = dir.write("p.csv",
                           "Exported by Recorder 7\n"
                           "Start;2026-11-27 10:15:32\n"
                           "Sample rate;2,5;kHz\n"
                           "Channels;AI0;AI1\n"
                           "\n"
                           "Time;AI0;AI1\n"
                           "s;V;[m/s^2]\n"
                           "0,0000;1,5;2\n"
                           "0,0004;2,5;3\n"
                           "0,0008;3,5;4\n");
  auto r = open_recording(f);
  EXPECT_EQ(r->info().channel_names, (std::vector<std::string>{"AI0", "AI1"}));
  EXPECT_EQ(r->info().channel_units, (std::vector<std::string>{"V", "m/s^2"}));
  EXPECT_EQ(r->info().sample_rate_hz, 2500.0);  // the preamble's, exact; the time column agrees
  EXPECT_EQ(r->info().started_at, "2026-11-27 10:15:32");
  EXPECT_EQ(read_all(*r, 3), (std::vector<double>{1.5, 2, 2.5, 3, 3.5, 4}));
  ASSERT_EQ(r->info().notes.size(), 1u);
  EXPECT_EQ(r->info().notes[0], "column names on line 6, below 4 preamble lines; sample rate 2500 Hz from line 3; start 2026-11-27 10:15:32");

  // The manifest's header_line: "Channels;AI0;AI1" is then the header (and Time a channel without a time column).
  r = open_recording(f, {.sample_rate_hz = 2500.0, .header_line = 4});
  EXPECT_EQ(r->info().channel_names, (std::vector<std::string>{"Channels", "AI0", "AI1"}));
  EXPECT_NE(read_error_of(f, {.header_line = 5}, 3).find("p.csv:5: header_line names a blank or comment line"), std::string::npos);
  EXPECT_NE(read_error_of(f, {.header_line = 99}, 3).find("header_line = 99 but the file has 10 lines"), std::string::npos);

  // A plain file is read as before: the first row is the header, and a bad first data row is an error naming it.
  const auto bad = dir.write("b.csv", "time_s,a\n0,nan\n0.001,2\n0.002,3\n");
  EXPECT_NE(read_error_of(bad, {}, 3).find("b.csv:2:2 (column 'a'): 'nan' is not a finite number"), std::string::npos) << read_error_of(bad, {}, 3);
}

}  // namespace
}  // namespace fourbar
