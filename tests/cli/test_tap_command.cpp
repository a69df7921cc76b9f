// `fourbar tap REC` on virtual tap recordings (CSV with a time column): the
// rig-file lines it prints hold the known frequencies and damping ratios; a
// recording without a decay, and a rig file whose elastic table is bad, fail
// cleanly with exit 2 naming the file or key.

#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <string>

#include "analyze/tap_recording.hpp"
#include "support/clean_failure.hpp"
#include "support/realdata.hpp"
#include "support/run_command.hpp"

namespace fourbar {
namespace {

using testing::run_fourbar;
using testing::TempDir;

std::vector<double> numbers_after(const std::string& text, const std::string& key) {
  std::smatch m;
  std::vector<double> out;
  if (!std::regex_search(text, m, std::regex(key + " = \\[([^\\]]*)\\]"))) return out;
  std::string list = m[1];
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(std::stod(item));
  return out;
}

TEST(TapCommand, PrintsTheRigFileLines) {
  TempDir dir;
  const auto rec = testing::virtual_tap({{600.0, 0.01, 1.0, 0.0}, {625.0, 0.015, 0.7, 2.0}}, 30, 4);
  const auto file = dir.write("tap.csv", testing::tap_csv(rec));
  const auto r = run_fourbar("tap " + file.string() + " --link rocker");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("[rocker.elastic]"), std::string::npos) << r.out;
  const auto f = numbers_after(r.out, "mode_frequencies_Hz");
  const auto z = numbers_after(r.out, "damping_ratios");
  ASSERT_EQ(f.size(), 2u) << r.out;
  ASSERT_EQ(z.size(), 2u) << r.out;
  EXPECT_NEAR(f[0] / 600.0, 1.0, 0.005) << r.out;
  EXPECT_NEAR(f[1] / 625.0, 1.0, 0.005) << r.out;
  EXPECT_NEAR(z[0] / 0.01, 1.0, 0.10) << r.out;
  EXPECT_NEAR(z[1] / 0.015, 1.0, 0.10) << r.out;
  // The lines paste into a rig file that loads.
  const std::string rig = std::regex_replace(testing::thesis_rig_toml(), std::regex("\\[clearance\\]"),
                                             r.out.substr(r.out.find("[rocker.elastic]")) + "\n[clearance]");
  const auto checked = run_fourbar("rig " + dir.write("rig.toml", rig).string());
  EXPECT_EQ(checked.status, 0) << checked.err << rig;
  EXPECT_NE(checked.out.find("rocker  modes: 600"), std::string::npos) << checked.out;
}

// The rig file's entries are the link's modes in order: a gap (the second
// mode at its node) or two modes too close for one link's bending get a
// '#' note, which keeps the pasted lines valid TOML; with --modes the lowest
// are printed and the higher ones named.
TEST(TapCommand, NotesAModeRatioThatIsNotALinksAndNamesTheHigherModesFitted) {
  TempDir dir;
  const auto gap = dir.write("gap.csv", testing::tap_csv(testing::virtual_tap(
                                            {{600.0, 0.01, 1.0, 0.0}, {5400.0, 0.02, 1.0, 1.0}}, 30, 2)));
  const auto r = run_fourbar("tap " + gap.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("# note: mode 2 is 9"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("may be missing"), std::string::npos) << r.out;
  const auto one = run_fourbar("tap " + gap.string() + " --modes 1");
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_NE(one.out.find("also fitted, not reported (only the 1 lowest were asked for): 540"), std::string::npos)
      << one.out;
  EXPECT_EQ(numbers_after(one.out, "mode_frequencies_Hz").size(), 1u) << one.out;
  const auto close = dir.write("close.csv", testing::tap_csv(testing::virtual_tap(
                                                {{600.0, 0.01, 1.0, 0.0}, {625.0, 0.015, 0.7, 2.0}}, 30, 4)));
  const auto c = run_fourbar("tap " + close.string());
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.out.find("# note: mode 2 is only 1.04 times mode 1"), std::string::npos) << c.out;
  const auto plain = dir.write("plain.csv", testing::tap_csv(testing::virtual_tap(
                                                {{614.1, 0.02, 1.0, 0.5}, {2456.3, 0.015, 0.5, 1.0}}, 30, 1)));
  const auto p = run_fourbar("tap " + plain.string());
  ASSERT_EQ(p.status, 0) << p.err;
  EXPECT_EQ(p.out.find("# note"), std::string::npos) << p.out;
}

/// The pasted lines hold the thesis coupler's first two modes (614.1 and
/// 2456.3 Hz) within 0.5 %.
void expect_thesis_coupler_modes(const std::string& out) {
  const auto f = numbers_after(out, "mode_frequencies_Hz");
  ASSERT_EQ(f.size(), 2u) << out;
  EXPECT_NEAR(f[0] / 614.1, 1.0, 0.005) << out;
  EXPECT_NEAR(f[1] / 2456.3, 1.0, 0.005) << out;
}

// A bounce of the hammer is named on its own line, with the time the fit
// starts from, and the pasted lines hold the true modes.
TEST(TapCommand, NamesABounceOfTheHammer) {
  TempDir dir;
  auto rec = testing::virtual_tap({{614.1, 0.02, 1.0, 0.5}, {2456.3, 0.015, 0.5, 1.0}}, 30, 2);
  testing::add_strike(rec, {{614.1, 0.02, 0.4, 0.5}, {2456.3, 0.015, 0.2, 1.0}}, 0.105);
  const auto r = run_fourbar("tap " + dir.write("bounce.csv", testing::tap_csv(rec)).string() + " --modes 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::regex_search(r.out, std::regex("struck again \\(a bounce\\) at 0\\.105 s \\(\\+4\\.[0-9]+ ms\\)")))
      << r.out;
  expect_thesis_coupler_modes(r.out);
}

// Several taps in one record (a technician's habit): the later ones are
// named as taps, not bounces, and the last one's decay is fitted.
TEST(TapCommand, NamesFurtherTapsInTheRecord) {
  TempDir dir;
  const std::vector<testing::TapModeTruth> truth = {{614.1, 0.02, 1.0, 0.5}, {2456.3, 0.015, 0.5, 1.0}};
  auto rec = testing::virtual_tap(truth, 40, 3, 25600, 1.6, 0.1);
  testing::add_strike(rec, {{614.1, 0.02, 0.7, 1.5}, {2456.3, 0.015, 0.35, 0.2}}, 0.9);
  const auto r = run_fourbar("tap " + dir.write("two_taps.csv", testing::tap_csv(rec)).string() + " --modes 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("the record holds 1 more tap(s), at 0.9"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("bounce"), std::string::npos) << r.out;
  expect_thesis_coupler_modes(r.out);
}

TEST(TapCommand, ARecordingWithoutADecayIsExit2) {
  TempDir dir;
  auto rec = testing::virtual_tap({{600.0, 0.01, 1.0, 0.0}}, 30, 1);
  for (std::size_t i = 0; i < rec.samples.size(); ++i)
    rec.samples[i] = 0.5 * std::sin(2 * 3.14159265 * 50 * static_cast<double>(i) / rec.sample_rate_hz);
  const auto file = dir.write("hum.csv", testing::tap_csv(rec));
  const auto r = run_fourbar("tap " + file.string());
  testing::expect_clean_failure(r, "hum.csv", dir.path() / "none");
  EXPECT_NE(r.err.find("no free decay"), std::string::npos) << r.err;
}

// Files other software wrote (../shared/realdata): a LabVIEW digital line
// (0/1) and a microphone record of a steady sound. Neither is a tap; both
// are refused with a message that says what they are, and the digital line
// is not called a clipped tap.
TEST(TapCommand, OtherSoftwaresRecordsThatAreNoTapAreExit2) {
  FOURBAR_REALDATA_FILE(tdms, "tdms/Digital_Input.tdms");
  TempDir dir;
  const auto digital = run_fourbar("tap " + tdms.string());
  testing::expect_clean_failure(digital, "a digital line or a saturated channel", dir.path() / "none");
  EXPECT_EQ(digital.err.find("clipped"), std::string::npos) << digital.err;
  for (const char* uff : {"uff58/Sample_UFF58_ascii.uff", "uff58/Sample_UFF58b_bin.uff"}) {
    const auto r = run_fourbar("tap " + (testing::realdata_dir() / uff).string());
    testing::expect_clean_failure(r, "no free decay", dir.path() / "none");
  }
}

TEST(TapCommand, BadElasticRigKeysAreExit2) {
  TempDir dir;
  const struct {
    std::string table, key;
  } cases[] = {
      {"mode_frequencies_Hz = [0, 2400]\n", "coupler.elastic.mode_frequencies_Hz"},
      {"mode_frequencies_Hz = [600]\ndamping_ratios = [1.5]\n", "coupler.elastic.damping_ratios"},
      {"E_GPa = 210\nwidth_mm = 25\nthickness_mm = 0\n", "coupler.elastic.thickness_mm"},
  };
  for (const auto& c : cases) {
    const auto file = dir.write("bad.toml", testing::thesis_rig_toml() + "\n[coupler.elastic]\n" + c.table);
    const auto r = run_fourbar("rig " + file.string());
    SCOPED_TRACE(c.table);
    testing::expect_clean_failure(r, c.key, dir.path() / "none");
  }
}

}  // namespace
}  // namespace fourbar
