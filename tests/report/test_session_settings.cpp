// session.toml values the analysis or the simulators would refuse later are
// refused when the session is read, naming the session.toml key (found by
// the session fuzz target's invariants, tests/fuzz/fuzz_session.cpp).
#include <gtest/gtest.h>

#include <string>

#include "common/error.hpp"
#include "report/session_settings.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

/// The InputError text of reading a session holding run1.flac and this
/// session.toml ("" when it loads).
std::string error_of(const std::string& session_toml) {
  testing::TempDir d;
  d.write("run1.flac", "");
  d.write("rig.toml", "");
  d.write("session.toml", session_toml);
  try {
    (void)load_session_settings(d.path());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_refused(const std::string& session_toml, const std::string& key) {
  const std::string err = error_of(session_toml);
  EXPECT_NE(err.find("session.toml"), std::string::npos) << session_toml << "\n" << err;
  EXPECT_NE(err.find(key), std::string::npos) << session_toml << "\n" << err;
}

TEST(SessionSettings, RecordingTableNamesOnlyARecordingOfTheFolder) {
  EXPECT_EQ(error_of("[[recording]]\nfile = \"run1.flac\"\nrestitution = 0.2\n"), "");
  for (const char* name : {"session.toml", "rig.toml", ".", "", "..", "run2.flac", "run1.FLAC"}) {
    const std::string err = error_of(std::string("[[recording]]\nfile = \"") + name + "\"\nrestitution = 0.2\n");
    EXPECT_NE(err.find("is not a recording in the session folder"), std::string::npos) << name << ": " << err;
  }
}

TEST(SessionSettings, ThreeModeFrictionHasTheScenesBounds) {
  EXPECT_EQ(error_of("[theory]\ncontact = \"stick-slip\"\nfriction_coefficient = 100\n"), "");
  expect_refused("[theory]\ncontact = \"stick-slip\"\nfriction_coefficient = 1e6\n", "friction_coefficient");
  expect_refused("[[recording]]\nfile = \"run1.flac\"\ncontact = \"stick-slip\"\nfriction_coefficient = 101\n",
                 "friction_coefficient");
}

TEST(SessionSettings, StickSlipWithoutFrictionIsRefusedNotSmooth) {
  // Before: μ = 0, which is smooth contact under another name.
  expect_refused("[theory]\ncontact = \"stick-slip\"\n", "contact");
  expect_refused("[[recording]]\nfile = \"run1.flac\"\ncontact = \"stick-slip\"\n", "contact");
  // μ from the session's [theory] carries over to a recording's override.
  EXPECT_EQ(error_of("[theory]\ncontact = \"stick-slip\"\nfriction_coefficient = 0.2\n[[recording]]\nfile = "
                     "\"run1.flac\"\ncontact = \"stick-slip\"\n"),
            "");
}

TEST(SessionSettings, AnalysisValuesTheAnalysisRefusesAreRefusedByKey) {
  EXPECT_EQ(error_of("[analysis]\npoints_per_rev = 4\n"), "");
  EXPECT_EQ(error_of("[analysis]\npoints_per_rev = 0\n"), "");
  expect_refused("[analysis]\npoints_per_rev = 3\n", "points_per_rev");
  EXPECT_EQ(error_of("[analysis]\nwindow = \"rectangular\"\ntransition_hz = 0\n"), "");
  expect_refused("[analysis]\nwindow = \"kaiser:8\"\ntransition_hz = 0\n", "transition_hz");
}

}  // namespace
}  // namespace fourbar

namespace fourbar {
namespace {

TEST(SessionSettings, ModelFamilyBandLimitAboveNyquistNamesTheKeyAndTheFix) {
  testing::TempDir d;
  d.write("run1.flac", "");
  d.write("session.toml", "[model_family]\nband_width_hz = 40\nmax_frequency_hz = 7000\n");
  const SessionSettings s = load_session_settings(d.path());
  EXPECT_DOUBLE_EQ(s.model_family.band_width_hz, 40);
  EXPECT_DOUBLE_EQ(s.model_family.max_frequency_hz, 7000);
  EXPECT_NO_THROW(check_band_limit(s, "run1.flac", 16000));  // Nyquist 8000 Hz
  try {
    check_band_limit(s, "run1.flac", 12800);  // Nyquist 6400 Hz
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("model_family.max_frequency_hz"), std::string::npos) << m;
    EXPECT_NE(m.find("6400"), std::string::npos) << m;
    EXPECT_NE(m.find("run1.flac"), std::string::npos) << m;
    EXPECT_NE(m.find("give at most"), std::string::npos) << m;
  }
  expect_refused("[model_family]\nband_width_hz = 0\n", "model_family.band_width_hz");
  expect_refused("[model_family]\nbands = 3\n", "bands");
}

}  // namespace
}  // namespace fourbar
