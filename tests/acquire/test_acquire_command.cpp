// `fourbar virtual-rig` and `fourbar acquire` as a user runs them: the example
// scene end to end, and bad input failing with one line, exit status 2 and
// nothing written.

#include <gtest/gtest.h>

#include <regex>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "support/clean_failure.hpp"
#include "tacho_signal.hpp"
#include "support/run_command.hpp"

namespace fourbar {
namespace {

using testing::count_lines;
using testing::read_file;
using testing::replace;
using testing::run_fourbar;
using testing::TempDir;

const std::string kExample = FOURBAR_SOURCE_DIR "/data/scenes/thesis_virtual_rig_350rpm.toml";

std::size_t data_rows(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) n += !line.empty() && line[0] != '#';
  return n - 1;  // header
}

std::string header(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') return line;
  return "";
}

TEST(VirtualRigCommand, ExampleSceneThenAcquire) {
  TempDir dir;
  const auto rec = dir.path() / "session" / "REC.wav";
  const auto vr = run_fourbar("virtual-rig " + kExample + " --out " + rec.string());
  ASSERT_EQ(vr.status, 0) << vr.err;
  EXPECT_TRUE(vr.err.empty()) << vr.err;
  for (const char* f : {"REC.wav", "REC.toml", "REC.truth.csv", "REC.truth.csv.json"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "session" / f)) << f;
  EXPECT_EQ(header(dir.path() / "session" / "REC.truth.csv").rfind("crank_deg,time_s,theta2_rad", 0), 0u);
  std::ifstream truth(dir.path() / "session" / "REC.truth.csv");
  std::string first_line;
  std::getline(truth, first_line);
  EXPECT_EQ(first_line.rfind("crank_deg,", 0), 0u) << "no '#' lines: the truth's provenance is in REC.truth.csv.json";

  const auto out = dir.path() / "acq";
  const auto r = run_fourbar("acquire " + rec.string() + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("acquired 19 revolutions"), std::string::npos) << r.out;
  for (const char* f : {"samples.csv", "revolutions.csv", "revolution_list.csv", "pulses.csv", "summary.json"})
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  const std::string summary = read_file(out / "summary.json");
  EXPECT_NE(summary.find("\"kept\": 19"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"samples_per_revolution\": 4680"), std::string::npos);
  EXPECT_EQ(header(out / "revolutions.csv"),
            "crank_deg,revolution,time_s,omega2_rad_s,alpha2_rad_s2,coupler_t_m_s2,coupler_n_m_s2,rocker_t_m_s2");
  EXPECT_EQ(header(out / "samples.csv"),
            "crank_deg,time_s,revolution,omega2_rad_s,alpha2_rad_s2,coupler_t_m_s2,coupler_n_m_s2,rocker_t_m_s2");
  EXPECT_EQ(data_rows(out / "revolutions.csv"), 19u * 4680u);
  EXPECT_EQ(data_rows(out / "revolution_list.csv"), 19u);
  EXPECT_EQ(data_rows(out / "pulses.csv"), 20u);

  // --no-samples and a chosen grid.
  const auto out2 = dir.path() / "acq2";
  const auto r2 = run_fourbar("acquire " + rec.string() + " --manifest " + (dir.path() / "session" / "REC.toml").string() +
                              " -n 360 --no-samples --out " + out2.string());
  ASSERT_EQ(r2.status, 0) << r2.err;
  EXPECT_FALSE(std::filesystem::exists(out2 / "samples.csv"));
  EXPECT_EQ(data_rows(out2 / "revolutions.csv"), 19u * 360u);

  // --binary: the same numbers as float64 rows.
  const auto out3 = dir.path() / "acq3";
  ASSERT_EQ(run_fourbar("acquire " + rec.string() + " -n 360 --binary --out " + out3.string()).status, 0);
  EXPECT_FALSE(std::filesystem::exists(out3 / "revolutions.csv"));
  const std::string bin = read_file(out3 / "revolutions.f64");
  ASSERT_EQ(bin.size(), 19u * 360u * 8u * sizeof(double));
  // Its first row equals the first CSV row of the same run, value for value.
  std::ifstream csv(out2 / "revolutions.csv");
  std::string line;
  while (std::getline(csv, line) && (line.empty() || line[0] == '#' || line[0] == 'c')) {}
  double first[8];
  std::memcpy(first, bin.data(), sizeof first);
  std::stringstream cells(line);
  std::string cell;
  for (int c = 0; std::getline(cells, cell, ','); ++c) EXPECT_EQ(first[c], std::strtod(cell.c_str(), nullptr)) << c;
  EXPECT_NE(read_file(out3 / "summary.json").find("\"rows\": 6840"), std::string::npos);
  EXPECT_EQ(std::filesystem::file_size(out3 / "samples.f64") % (8 * sizeof(double)), 0u);
}

TEST(VirtualRigCommand, SameSeedSameBytes) {
  TempDir dir;
  ASSERT_EQ(run_fourbar("virtual-rig " + kExample + " --no-truth --out " + (dir.path() / "a.flac").string()).status, 0);
  ASSERT_EQ(run_fourbar("virtual-rig " + kExample + " --no-truth --out " + (dir.path() / "b.flac").string()).status, 0);
  EXPECT_EQ(read_file(dir.path() / "a.flac"), read_file(dir.path() / "b.flac"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "a.truth.csv"));
}

class BadInput : public ::testing::Test {
 protected:
  TempDir dir;
  std::filesystem::path out() const { return dir.path() / "out"; }
  void expect_clean_failure(const testing::CommandResult& r, const std::string& needle) {
    testing::expect_clean_failure(r, needle, out());
  }
  /// A 4-revolution virtual recording; returns its path.
  std::filesystem::path recording(const std::string& name, const std::string& scene_edit_from = "",
                                  const std::string& scene_edit_to = "") {
    std::string scene = read_file(kExample);
    scene = replace(scene, "rig = \"../rigs/thesis.toml\"", "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml\"");
    scene = replace(scene, "revolutions = 20", "revolutions = 4");
    if (!scene_edit_from.empty()) scene = replace(scene, scene_edit_from, scene_edit_to);
    const auto s = dir.write("scene.toml", scene);
    const auto rec = dir.path() / name;
    const auto r = run_fourbar("virtual-rig " + s.string() + " --no-truth --out " + rec.string());
    EXPECT_EQ(r.status, 0) << r.err;
    return rec;
  }
  testing::CommandResult acquire(const std::filesystem::path& rec, const std::string& extra = "") {
    return run_fourbar("acquire " + rec.string() + " " + extra + " --out " + out().string());
  }
  void edit_manifest(const std::filesystem::path& rec, const std::string& from, const std::string& to) {
    const auto m = std::filesystem::path(rec).replace_extension(".toml");
    const std::string text = read_file(m);
    ASSERT_NE(text.find(from), std::string::npos) << text;
    std::ofstream(m) << replace(text, from, to);
  }
};

TEST_F(BadInput, UnknownFormat) {
  const auto rec = dir.write("REC.xyz", "not a recording at all");
  dir.write("REC.toml", "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml\"\nclearance_mm = 0.254\n"
                       "[[channel]]\nindex = 0\nrole = \"crank_pulse\"\n");
  expect_clean_failure(acquire(rec), "unknown recording format");
}

TEST_F(BadInput, TruncatedFile) {
  const auto rec = recording("REC.wav");
  std::filesystem::resize_file(rec, std::filesystem::file_size(rec) * 2 / 3);
  expect_clean_failure(acquire(rec), "truncated");
}

// Cut just after the header: a FLAC decoder then fails when acquire seeks
// back for its next pass, which is still a truncated file, not a run failure.
TEST_F(BadInput, FlacCutAfterHeader) {
  const auto rec = recording("REC.flac");
  std::filesystem::resize_file(rec, 3000);
  expect_clean_failure(acquire(rec), "truncated");
}

TEST_F(BadInput, ChannelIndexOutOfRange) {
  const auto rec = recording("REC.wav");
  edit_manifest(rec, "index = 2", "index = 9");
  expect_clean_failure(acquire(rec), "channel[2] ('rocker_t'): index = 9 but");
}

TEST_F(BadInput, ManifestKeyMissing) {
  const auto rec = recording("REC.wav");
  edit_manifest(rec, "position_mm = 312\n", "");
  expect_clean_failure(acquire(rec), "missing key 'channel[2].position_mm'");
}

TEST_F(BadInput, ManifestKeyMisspelt) {
  const auto rec = recording("REC.wav");
  edit_manifest(rec, "axis_sign = -1", "axis_sing = -1");
  expect_clean_failure(acquire(rec), "unknown key 'channel[1].axis_sing' (did you mean 'axis_sign'?)");
}

TEST_F(BadInput, MissingManifest) {
  const auto rec = recording("REC.wav");
  std::filesystem::remove(std::filesystem::path(rec).replace_extension(".toml"));
  expect_clean_failure(acquire(rec), "no manifest");
}

TEST_F(BadInput, NoPulses) {
  const auto rec = dir.write("flat.csv", "time_s,acc,pulse\n0,1,0\n0.001,2,0\n0.002,1,0\n0.003,2,0\n");
  dir.write("flat.toml", "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml\"\nclearance_mm = 0.254\n"
                         "[[channel]]\ncolumn = \"acc\"\nrole = \"rocker_tangential\"\nvolts_per_unit = 0.01\n"
                         "position_mm = 312\n[[channel]]\ncolumn = \"pulse\"\nrole = \"crank_pulse\"\n");
  expect_clean_failure(acquire(rec), "no crank pulses");
}

TEST_F(BadInput, FewerThanTwoRevolutions) {
  const auto rec = recording("REC.wav", "revolutions = 4", "revolutions = 1.5");
  expect_clean_failure(acquire(rec), "need at least 2");
}

TEST_F(BadInput, NanInCsv) {
  const auto rec = recording("REC.csv", "sample_format = \"pcm24\"\n", "");
  std::string text = read_file(rec);
  const auto row = text.find("\n0.01,");  // the row at t = 0.01 s
  ASSERT_NE(row, std::string::npos);
  text.replace(text.find(',', row + 1) + 1, 0, "NaN");  // "NaN<number>" in the first channel
  std::ofstream(rec) << text;
  expect_clean_failure(acquire(rec), "is not a finite number");
}

TEST_F(BadInput, ZeroSampleRate) {
  const auto rec = dir.write("z.csv", "acc,pulse\n1,0\n2,5\n");
  dir.write("z.toml", "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml\"\nclearance_mm = 0.254\nsample_rate_hz = 0\n"
                      "[[channel]]\ncolumn = \"pulse\"\nrole = \"crank_pulse\"\n");
  expect_clean_failure(acquire(rec), "'sample_rate_hz' = 0 must be positive");
}

TEST_F(BadInput, VirtualRigMisspeltRecordingKey) {
  std::string scene = replace(read_file(kExample), "rig = \"../rigs/thesis.toml\"",
                              "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml\"");
  const auto s = dir.write("s.toml", replace(scene, "hum_mV", "hum_mv"));
  const auto r = run_fourbar("virtual-rig " + s.string() + " --out " + (out() / "R.wav").string());
  expect_clean_failure(r, "unknown key 'recording.hum_mv' (did you mean 'hum_mV'?)");
}

/// Tachometer recordings through `fourbar acquire`, good and ambiguous.
using TachoCommand = BadInput;

/// A 1 kHz CSV of a tachometer (one pulse per turn) and an idle accelerometer,
/// with its sidecar manifest; returns the recording's path.
std::filesystem::path tacho_csv(const TempDir& dir, const std::string& name, const testing::TachoSignal& s) {
  std::ostringstream csv;
  csv << "time_s,coupler_t,crank_pulse\n";
  for (std::size_t i = 0; i < s.volts.size(); ++i) csv << static_cast<double>(i) / 1000 << ",0," << s.volts[i] << "\n";
  dir.write(name + ".toml", "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml\"\nclearance_mm = 0.0254\n"
            "[[channel]]\nindex = 0\nname = \"coupler_t\"\nrole = \"coupler_tangential\"\nvolts_per_unit = 0.002\n"
            "axis_sign = 1\nposition_mm = 289\n[[channel]]\nindex = 1\nname = \"crank_pulse\"\nrole = \"crank_pulse\"\n");
  return dir.write(name + ".csv", csv.str());
}

// The tachometer run-up that used to come out at half speed with exit 0:
// 600 → 3000 rpm in 10 s, 0/1 pulses at 1 kHz. Every pulse is kept, no warning
// about spurious edges, the top speed is 3000 rpm.
TEST_F(TachoCommand, RunUpKeepsEveryPulse) {
  const auto s = testing::tacho_signal({{0, 10}, {10, 50}}, 1000, 0.1, 0.3);
  const auto rec = tacho_csv(dir, "runup", s);
  const auto r = acquire(rec, "--no-samples");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("spurious"), std::string::npos) << r.err;
  const std::string summary = read_file(out() / "summary.json");
  EXPECT_NE(summary.find("\"pulses\": " + std::to_string(s.pulse_times.size())), std::string::npos) << summary;
  EXPECT_EQ(data_rows(out() / "revolution_list.csv"), s.pulse_times.size() - 1);
}

// The speed doubles within a turn but the tacho's pulses are 12 ms long
// whatever the speed: the same edges as an echo half a period after each
// pulse. Refused, naming what was seen and the key.
TEST_F(TachoCommand, AmbiguousPeriodHalvingIsRefused) {
  const auto s = testing::tacho_signal({{0, 3, 3.02, 6}, {10, 10, 20, 20}}, 1000, 0, 0.3, 0.012);
  const auto rec = tacho_csv(dir, "step", s);
  const auto r = acquire(rec);
  expect_clean_failure(r, "period halves abruptly after");
  EXPECT_NE(r.err.find("set debounce_ms = "), std::string::npos) << r.err;
}

// crank_smoothing on a 0/1 tachometer at 1 kHz (edges quantised to the
// sample: ±0.5 ms). A steady run (600 → 606 rpm in 30 s) is smoothed and
// summary.json says how; a 30 % speed step at 15 s is refused with exit
// status 2, naming the key and the fix, and nothing is written.
TEST_F(TachoCommand, CrankSmoothingSteadyRunAndSpeedStep) {
  const std::string keys = "crank_smoothing = \"spline\"\nsmoothing_period_turns = 10\n";
  const auto steady = tacho_csv(dir, "steady", testing::tacho_signal({{0, 30}, {10, 10.1}}, 1000, 0.1, 0.3));
  std::ofstream(std::filesystem::path(steady).replace_extension(".toml"), std::ios::app) << keys;
  const auto ok = acquire(steady, "--no-samples");
  ASSERT_EQ(ok.status, 0) << ok.err;
  const std::string summary = read_file(out() / "summary.json");
  EXPECT_NE(summary.find("\"crank_smoothing\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"period_turns\": 10"), std::string::npos) << summary;
  std::filesystem::remove_all(out());

  const auto step = tacho_csv(dir, "step", testing::tacho_signal({{0, 15, 15.02, 30}, {10, 10, 13, 13}}, 1000, 0.1, 0.3));
  std::ofstream(std::filesystem::path(step).replace_extension(".toml"), std::ios::app) << keys;
  const auto r = acquire(step);
  expect_clean_failure(r, "crank_smoothing = \"spline\" with smoothing_period_turns = 10");
  EXPECT_NE(r.err.find("Lower smoothing_period_turns"), std::string::npos) << r.err;
}

/// The range a warning tells the user to type: "--start-s A --end-s B".
std::pair<std::string, std::string> suggested_range(const std::string& err) {
  static const std::regex re(R"(--start-s ([0-9.]+) --end-s ([0-9.]+))");
  std::smatch m;
  if (!std::regex_search(err, m, re)) return {};
  return {m[1].str(), m[2].str()};
}

// A run at 352 rpm that coasts down to 156 rpm in its last second
// (acquire/time_range.hpp). The user is told the speed changed, by how much,
// and the exact range to type; with it, the coast-down's turns are left out
// and nothing is warned about. The manifest's keys do the same.
TEST_F(TachoCommand, CoastDownIsWarnedWithTheRangeToCut) {
  const double steady = 352.0 / 60, low = 156.0 / 60;
  const auto s = testing::tacho_signal({{0, 10, 11}, {steady, steady, low}}, 1000, 0.1, 0.3);
  const auto rec = tacho_csv(dir, "coast", s);
  const auto r = acquire(rec, "--no-samples");
  ASSERT_EQ(r.status, 0) << r.err;
  std::printf("%s", r.err.c_str());
  EXPECT_NE(r.err.find("fourbar: warning: the crank speed changes by"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("a coast-down, a stall or a run-up"), std::string::npos) << r.err;
  const auto [from, to] = suggested_range(r.err);
  ASSERT_FALSE(from.empty()) << r.err;
  EXPECT_NE(r.err.find("set start_s = " + from + " and end_s = " + to), std::string::npos) << r.err;
  EXPECT_LE(std::stod(to), 10.05);  // the coast-down starts at 10 s
  EXPECT_LE(std::stod(from), 0.3);  // nothing steady is cut
  std::filesystem::remove_all(out());

  const auto clean = acquire(rec, "--no-samples --start-s " + from + " --end-s " + to);
  ASSERT_EQ(clean.status, 0) << clean.err;
  EXPECT_EQ(clean.err.find("warning"), std::string::npos) << clean.err;
  const std::string summary = read_file(out() / "summary.json");
  EXPECT_NE(summary.find("\"start_s\": " + from), std::string::npos) << summary;
  // Every steady turn kept: 58 turns at 352 rpm in 10 s, less a partial one at each end.
  const std::size_t rows = data_rows(out() / "revolution_list.csv");
  EXPECT_GE(rows, 56u);
  EXPECT_LE(rows, 58u);
  std::filesystem::remove_all(out());

  edit_manifest(rec, "clearance_mm = 0.0254\n", "clearance_mm = 0.0254\nstart_s = " + from + "\nend_s = " + to + "\n");
  const auto keyed = acquire(rec, "--no-samples");
  ASSERT_EQ(keyed.status, 0) << keyed.err;
  EXPECT_EQ(keyed.err.find("warning"), std::string::npos) << keyed.err;
  EXPECT_EQ(data_rows(out() / "revolution_list.csv"), rows);
}

// A run at 352 rpm that stalls at 8 s and stands still for 3 s: over a
// tenth of the file lies outside the turns. Told so, with the range; with
// it, clean.
TEST_F(TachoCommand, StallIsWarnedWithTheRangeToCut) {
  const double steady = 352.0 / 60;
  const auto s = testing::tacho_signal({{0, 8, 8.3, 11.3}, {steady, steady, 0, 0}}, 1000, 0.1, 0.3);
  const auto rec = tacho_csv(dir, "stall", s);
  const auto r = acquire(rec, "--no-samples");
  ASSERT_EQ(r.status, 0) << r.err;
  std::printf("%s", r.err.c_str());
  EXPECT_NE(r.err.find("of the recording lie outside the crank's turns"), std::string::npos) << r.err;
  const auto [from, to] = suggested_range(r.err);
  ASSERT_FALSE(from.empty()) << r.err;
  EXPECT_LE(std::stod(to), 8.05);
  std::filesystem::remove_all(out());
  const auto clean = acquire(rec, "--no-samples --start-s " + from + " --end-s " + to);
  ASSERT_EQ(clean.status, 0) << clean.err;
  EXPECT_EQ(clean.err.find("warning"), std::string::npos) << clean.err;
}

TEST_F(BadInput, VirtualRigUnknownExtension) {
  const auto r = run_fourbar("virtual-rig " + kExample + " --out " + (out() / "R.mp3").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("unknown output format '.mp3'"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out() / "R.mp3"));
  EXPECT_FALSE(std::filesystem::exists(out() / "R.toml"));
}

}  // namespace
}  // namespace fourbar
