// `fourbar inspect` as a technician runs it: a virtual-rig recording →
// inspect → manifest template (refused while unfilled) → filled in with the
// rig's set-up → analyze gives exactly what the virtual rig's own manifest
// gives. And inspect on .mat and text exports, with their bad-input errors.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include <toml++/toml.h>

#include "format_writers.hpp"
#include "support/clean_failure.hpp"
#include "support/realdata.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

using testing::read_file;
using testing::run_fourbar;
using testing::TempDir;

const std::string kScene = FOURBAR_SOURCE_DIR "/data/scenes/thesis_virtual_rig_350rpm.toml";
const std::string kRig = FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml";

std::string toml_value(const toml::node& n) {
  if (const auto* s = n.as_string()) return "\"" + s->get() + "\"";
  if (const auto* b = n.as_boolean()) return b->get() ? "true" : "false";
  if (const auto* i = n.as_integer()) return std::to_string(i->get());
  std::ostringstream os;
  os.precision(17);
  os << n.as_floating_point()->get();
  return os.str();
}

/// What the technician does with the template: every "FILL IN", every
/// commented-out key and the sensor offsets get the set-up's values (here:
/// the virtual rig's manifest, channel by channel through `index`). The
/// guesses inspect made (crank-pulse channel, polarity) are left alone.
std::string fill_in_from(const std::string& tmpl, const toml::table& truth) {
  const toml::table* context = &truth;
  const std::regex kv(R"(^(# )?(\w+) = (.*)$)");
  std::istringstream in(tmpl);
  std::ostringstream out;
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (line == "[[channel]]") {
      context = nullptr;
    } else if (std::regex_match(line, m, kv)) {
      const std::string key = m[2], value = m[3];
      if (!context && key == "index") {
        for (const auto& c : *truth["channel"].as_array())
          if (c.as_table()->get("index")->value<int>() == std::stoi(value)) context = c.as_table();
      } else if (context && context->contains(key) &&
                 (m[1].matched || value.starts_with("\"FILL IN\"") || key == "offset_mm")) {
        line = key + " = " + toml_value(*context->get(key));
      }
    }
    out << line << "\n";
  }
  return out.str();
}

std::string data_rows(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::string rows;
  for (std::string line; std::getline(in, line);)
    if (!line.starts_with("#")) rows += line + "\n";
  return rows;
}

TEST(InspectCommand, TemplateFilledInAnalysesLikeTheVirtualRigsOwnManifest) {
  TempDir dir;
  const auto rec = dir.path() / "REC.wav";
  ASSERT_EQ(run_fourbar("virtual-rig " + kScene + " --no-truth --out " + rec.string()).status, 0);
  std::filesystem::rename(dir.path() / "REC.toml", dir.path() / "truth.toml");
  const toml::table truth = toml::parse_file((dir.path() / "truth.toml").string());

  const auto summary = run_fourbar("inspect " + rec.string());
  ASSERT_EQ(summary.status, 0) << summary.err;
  EXPECT_NE(summary.out.find("crank pulses on channel 3: 350"), std::string::npos) << summary.out;

  const auto t = run_fourbar("inspect " + rec.string() + " --manifest-template");
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_TRUE(t.err.empty()) << t.err;
  // The pulse channel and its polarity are the virtual rig's.
  int pulse_index = -1;
  for (const auto& c : *truth["channel"].as_array())
    if (c.as_table()->get("role")->value<std::string>() == "crank_pulse") pulse_index = c.as_table()->get("index")->value<int>().value();
  EXPECT_NE(t.out.find("index = " + std::to_string(pulse_index) + "\nrole = \"crank_pulse\""), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("polarity = \"rising\""), std::string::npos) << t.out;

  // Unfilled: refused by acquire, analyze and report, naming the first key; nothing written.
  const auto manifest = dir.write("REC.toml", t.out);
  for (const std::string& cmd : {"acquire " + rec.string(), "analyze " + rec.string() + " --out " + (dir.path() / "a").string()}) {
    const auto r = run_fourbar(cmd);
    testing::expect_clean_failure(r, manifest.string() + ":6: rig is still \"FILL IN\"", dir.path() / "a");
  }

  dir.write("REC.toml", fill_in_from(t.out, truth));
  const auto check = run_fourbar("acquire " + rec.string());
  ASSERT_EQ(check.status, 0) << check.err << read_file(manifest);
  EXPECT_NE(check.out.find("complete revolutions, 350"), std::string::npos) << check.out;

  const auto a = run_fourbar("analyze " + rec.string() + " --out " + (dir.path() / "from_template").string());
  const auto b = run_fourbar("analyze " + rec.string() + " --manifest " + (dir.path() / "truth.toml").string() + " --out " +
                             (dir.path() / "from_truth").string());
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  for (const char* f : {"averaged.csv", "spectra.csv"}) {
    const std::string rows = data_rows(dir.path() / "from_template" / f);
    EXPECT_GT(rows.size(), 1000u);
    EXPECT_EQ(rows, data_rows(dir.path() / "from_truth" / f)) << f;
  }
}

TEST(AcquireCommand, WithoutOutChecksOnlyAndDefaultOutputFolders) {
  TempDir dir;
  const auto rec = dir.path() / "REC.wav";
  ASSERT_EQ(run_fourbar("virtual-rig " + kScene + " --no-truth --out " + rec.string()).status, 0);
  const auto before = std::distance(std::filesystem::directory_iterator(dir.path()), {});
  const auto previous = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());  // the default folders are relative to where fourbar runs
  const auto check = run_fourbar("acquire REC.wav");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), before) << "a check writes nothing";
  const auto acquired = run_fourbar("acquire REC.wav --out");
  const auto analysed = run_fourbar("analyze REC.wav");
  std::filesystem::current_path(previous);
  ASSERT_EQ(check.status, 0) << check.err;
  EXPECT_NE(check.out.find("19 complete revolutions"), std::string::npos) << check.out;
  EXPECT_NE(check.out.find("checked: "), std::string::npos) << check.out;
  ASSERT_EQ(acquired.status, 0) << acquired.err;
  ASSERT_EQ(analysed.status, 0) << analysed.err;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / "REC" / "acquire" / "revolutions.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / "REC" / "analyze" / "averaged.csv"));
}

TEST(InspectCommand, MatlabAndTextExports) {
  TempDir dir;
  const auto s = testing::inspection_signals();
  for (auto [name, version] : {std::pair{"v5.mat", MAT_FT_MAT5}, std::pair{"v73.mat", MAT_FT_MAT73}}) {
    testing::write_mat(dir.path() / name, version, s);
    const auto r = run_fourbar("inspect " + (dir.path() / name).string());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find(version == MAT_FT_MAT73 ? "MAT v7.3 DOUBLE, 4 channels, 10000 Hz (from the variable 'fs')"
                                                 : "MAT v5 DOUBLE, 4 channels, 10000 Hz (from the variable 'fs')"),
              std::string::npos) << r.out;
    EXPECT_NE(r.out.find("crank pulses on channel 1: 1200 rpm"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("coupler_t"), std::string::npos) << r.out;
  }
  testing::write_csv_with_units_row(dir.path() / "export.csv", s);
  const auto c = run_fourbar("inspect " + (dir.path() / "export.csv").string());
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.out.find("coupler_t [V]"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("crank pulses on channel 1: 1200 rpm"), std::string::npos) << c.out;
}

TEST(InspectCommand, BadInput) {
  TempDir dir;
  const auto s = testing::inspection_signals();
  const auto mat = dir.path() / "r.mat";
  testing::write_mat(mat, MAT_FT_MAT5, s, "");
  // A .mat without the named rate variable: the error names it and lists the variables.
  auto r = run_fourbar("inspect " + mat.string() + " --rate-variable fs");
  testing::expect_clean_failure(r, "rate_variable 'fs' is not a numeric variable in this file (variables found: coupler_t 20000x1",
                                dir.path() / "none");
  // The same through a manifest's rate_variable.
  dir.write("r.toml", "rig = \"" + kRig + "\"\nclearance_mm = 0.254\nrate_variable = \"fs\"\n[[channel]]\ncolumn = \"pulse\"\nrole = \"crank_pulse\"\n");
  r = run_fourbar("acquire " + mat.string());
  testing::expect_clean_failure(r, "rate_variable 'fs' is not a numeric variable", dir.path() / "none");

  // A text export whose manifest names a column it lacks: the columns found are listed.
  const auto csv = dir.path() / "e.csv";
  testing::write_csv_with_units_row(csv, s);
  dir.write("e.toml", "rig = \"" + kRig + "\"\nclearance_mm = 0.254\n[[channel]]\ncolumn = \"crank\"\nrole = \"crank_pulse\"\n");
  r = run_fourbar("acquire " + csv.string());
  testing::expect_clean_failure(r, "its channels are 'coupler_t', 'pulse', 'rocker_t', 'spare'", dir.path() / "none");

  // A damaged v7.3 (HDF5) file: one line on stderr, no HDF5 error stack.
  testing::write_mat(dir.path() / "full.mat", MAT_FT_MAT73, s);
  {
    std::ifstream in(dir.path() / "full.mat", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto cut = dir.write("cut.mat", bytes.substr(0, bytes.size() / 2));
    testing::expect_clean_failure(run_fourbar("inspect " + cut.string()), cut.string() + ": ", dir.path() / "none");
  }

  // inspect needs no manifest, but a text file without a time column needs a rate.
  const auto bare = dir.write("bare.csv", "a,b\n1,2\n3,4\n");
  testing::expect_clean_failure(run_fourbar("inspect " + bare.string()), "sample_rate_hz", dir.path() / "none");
  EXPECT_EQ(run_fourbar("inspect " + bare.string() + " --sample-rate-hz 100").status, 0);
}

/// A DAQ export as such software writes it: a preamble (who, start, rate)
/// above `Time [s];coupler_t [V];…`, semicolons and decimal commas.
void write_preamble_export(const std::filesystem::path& file, const testing::TestSignals& s, const std::string& rate_line,
                           bool time_column) {
  std::ofstream out(file);
  out << "Exported by LabDAQ 4.2 (demo)\nStart;27.11.2026 10:15:32\n" << rate_line << "\n";
  out << (time_column ? "Time [s]" : "");
  for (std::size_t c = 0; c < s.names.size(); ++c) out << (c > 0 || time_column ? ";" : "") << s.names[c] << " [V]";
  out << "\n";
  char cell[32];
  for (std::size_t i = 0; i < s.columns[0].size(); ++i) {
    std::string row;
    if (time_column) std::snprintf(cell, sizeof cell, "%.6f", static_cast<double>(i) / s.rate_hz), row = cell;
    for (const auto& c : s.columns) std::snprintf(cell, sizeof cell, "%.9g", c[i]), row += (row.empty() && !time_column ? "" : ";") + std::string(cell);
    std::replace(row.begin(), row.end(), '.', ',');
    out << row << "\n";
  }
}

TEST(InspectCommand, DaqExportWithAPreambleAboveTheHeader) {
  TempDir dir;
  const auto s = testing::inspection_signals();
  const auto rec = dir.path() / "daq.csv";
  write_preamble_export(rec, s, "Sample rate;10000;Hz", true);
  auto r = run_fourbar("inspect " + rec.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("CSV TEXT, 4 channels, 10000 Hz, 20000 samples = 2 s, started 27.11.2026 10:15:32"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("coupler_t [V]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("crank pulses on channel 1: 1200 rpm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("note: column names on line 4, below 3 preamble lines; sample rate 10000 Hz from line 3; start "
                       "27.11.2026 10:15:32"), std::string::npos) << r.out;
  // acquire reads it with a manifest that names columns only.
  dir.write("daq.toml", "rig = \"" + kRig + "\"\nclearance_mm = 0.254\n[[channel]]\ncolumn = \"pulse\"\nrole = \"crank_pulse\"\n");
  r = run_fourbar("acquire " + rec.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("10000 Hz"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("complete revolutions, 1200"), std::string::npos) << r.out;

  // Without a time column the preamble's rate is the rate.
  write_preamble_export(rec, s, "Sample rate: 10 kHz", false);
  r = run_fourbar("inspect " + rec.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("CSV TEXT, 4 channels, 10000 Hz, 20000 samples = 2 s"), std::string::npos) << r.out;

  // A preamble rate the time column contradicts: an error naming the line.
  write_preamble_export(rec, s, "Sample rate;12800;Hz", true);
  testing::expect_clean_failure(run_fourbar("inspect " + rec.string()),
                                rec.string() + ":3: the preamble states 12800 Hz but the time column 'Time [s]' spans 1.9999 s",
                                dir.path() / "none");
}

TEST(InspectCommand, RecordingsWrittenByOtherSoftware) {
  FOURBAR_REALDATA_FILE(tdms, "tdms/Digital_Input.tdms");
  // README of realdata: SignalExpress 2011, NI-DAQ digital line Dev1/port3/line7, 2 kHz for 10 s, two decimated groups.
  auto r = run_fourbar("inspect " + tdms.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Digital_Input.tdms: TDMS U8, 1 channel, 2000 Hz, 20000 samples = 10 s, started 2012-07-09T23:58:24"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Dev1_port3_line7 - line 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Decimated Data_Level1/Dev1_port3_line7 - line 0': 400 values at 40 Hz"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Decimated Data_Level2/Dev1_port3_line7 - line 0': 8 values at 0.8 Hz"), std::string::npos) << r.out;
  auto t = run_fourbar("inspect " + tdms.string() + " --manifest-template");
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_NE(t.out.find("column = \"Dev1_port3_line7 - line 0\""), std::string::npos) << t.out;

  // README: one microphone record (ordinate type 21, Pa), 65 536 Hz, 79 292 samples (1.21 s), dated 18-Apr-16.
  for (const char* name : {"uff58/Sample_UFF58_ascii.uff", "uff58/Sample_UFF58b_bin.uff"}) {
    const auto f = testing::realdata_dir() / name;
    r = run_fourbar("inspect " + f.string());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find(": UFF58 FLOAT, 1 channel, 65536 Hz, 79292 samples = 1.2099 s, started 18-Apr-16 13:49:58"),
              std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Mic 01.0Scalar [Pa]"), std::string::npos) << r.out;
    t = run_fourbar("inspect " + f.string() + " --manifest-template");
    ASSERT_EQ(t.status, 0) << t.err;
    EXPECT_NE(t.out.find("column = \"Mic 01.0Scalar\""), std::string::npos) << t.out;
    EXPECT_NE(t.out.find("its channels are in Pa"), std::string::npos) << t.out;
  }
}

}  // namespace
}  // namespace fourbar
