// Rig loading and validation: the thesis rig file, and errors that name file,
// key and value.

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "mechanism/rig.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

using testing::replace;
using testing::TempDir;
using testing::thesis_rig_toml;

std::string load_error(const std::string& text) {
  TempDir dir;
  const auto file = dir.write("rig.toml", text);
  try {
    load_rig(file);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return {};
}

TEST(Rig, DataFileEqualsThesisTable) {
  const Rig file = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml");
  const Rig code = thesis_rig();
  EXPECT_DOUBLE_EQ(file.ground_length_m, code.ground_length_m);
  EXPECT_DOUBLE_EQ(file.coupler.inertia_cg_kg_m2, code.coupler.inertia_cg_kg_m2);
  EXPECT_DOUBLE_EQ(file.rocker.mass_centre_m, code.rocker.mass_centre_m);
  EXPECT_DOUBLE_EQ(file.radial_clearance_m, code.radial_clearance_m);
  EXPECT_DOUBLE_EQ(file.gravity_m_s2, code.gravity_m_s2);
  EXPECT_EQ(grashof_class(file), GrashofClass::crank_rocker);
}

TEST(Rig, GrashofClasses) {
  Rig r = thesis_rig();
  EXPECT_EQ(grashof_class(r), GrashofClass::crank_rocker);
  r.ground_length_m = 0.05;  // ground shortest
  EXPECT_EQ(grashof_class(r), GrashofClass::double_crank);
  r = thesis_rig();
  r.crank.length_m = 0.3;  // s + l > p + q
  r.ground_length_m = 0.6;
  EXPECT_EQ(grashof_class(r), GrashofClass::non_grashof);
}

TEST(Rig, RejectsMissingKey) {
  const auto msg = load_error(replace(thesis_rig_toml(), "mass_kg = 0.2439\n", ""));
  EXPECT_NE(msg.find("coupler.mass_kg"), std::string::npos) << msg;
}

TEST(Rig, RejectsNegativeMass) {
  const auto msg = load_error(replace(thesis_rig_toml(), "mass_kg = 0.2334", "mass_kg = -0.2334"));
  EXPECT_NE(msg.find("rocker.mass_kg"), std::string::npos) << msg;
  EXPECT_NE(msg.find("-0.2334"), std::string::npos) << msg;
  EXPECT_NE(msg.find("positive"), std::string::npos) << msg;
}

TEST(Rig, RejectsMisspeltKeyWithSuggestion) {
  const auto msg = load_error(replace(thesis_rig_toml(), "mass_centre_mm = 9.0", "mass_center_mm = 9.0"));
  EXPECT_NE(msg.find("crank.mass_centre_mm"), std::string::npos) << msg;
  EXPECT_NE(msg.find("mass_center_mm"), std::string::npos) << msg;
}

TEST(Rig, RejectsUnknownKey) {
  const auto msg = load_error(replace(thesis_rig_toml(), "[ground]\n", "[ground]\nwidth_mm = 3\n"));
  EXPECT_NE(msg.find("unknown key 'ground.width_mm'"), std::string::npos) << msg;
}

TEST(Rig, RejectsLinksThatCannotClose) {
  const auto msg = load_error(replace(thesis_rig_toml(), "length_mm = 387.0", "length_mm = 800.0"));
  EXPECT_NE(msg.find("cannot close"), std::string::npos) << msg;
}

TEST(Rig, RejectsCrankThatCannotTurnFully) {
  // A 250 mm crank reaches 637 mm from O4, beyond coupler + rocker (621 mm).
  const auto msg = load_error(replace(thesis_rig_toml(), "length_mm = 64.0", "length_mm = 250.0"));
  EXPECT_NE(msg.find("full crank turn"), std::string::npos) << msg;
}

TEST(Rig, RejectsBadAssemblyAndSyntax) {
  auto msg = load_error(replace(thesis_rig_toml(), "assembly = \"open\"", "assembly = \"opne\""));
  EXPECT_NE(msg.find("did you mean 'open'"), std::string::npos) << msg;
  msg = load_error(replace(thesis_rig_toml(), "length_mm = 387.0", "length_mm = 387.0.0"));
  EXPECT_NE(msg.find("not valid TOML"), std::string::npos) << msg;
  msg = load_error(replace(thesis_rig_toml(), "length_mm = 387.0", "length_mm = \"387\""));
  EXPECT_NE(msg.find("must be a number"), std::string::npos) << msg;
  msg = load_error(replace(thesis_rig_toml(), "mass_centre_mm = 185.0", "mass_centre_mm = 400.0"));
  EXPECT_NE(msg.find("beyond the link"), std::string::npos) << msg;
}

TEST(Rig, MissingFileIsInputError) {
  try {
    load_rig("/nonexistent/rig.toml");
    ADD_FAILURE() << "a missing rig file loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/rig.toml"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fourbar

namespace fourbar {
namespace {

using testing::thesis_rig_toml;

std::string with_elastic(const std::string& table) { return thesis_rig_toml() + "\n[coupler.elastic]\n" + table; }

std::string elastic_error(const std::string& table) {
  TempDir dir;
  const auto file = dir.write("rig.toml", with_elastic(table));
  try {
    load_rig(file);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error for:\n" << table;
  return {};
}

TEST(RigElastic, DataFileHasElasticCouplerAndRocker) {
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  ASSERT_TRUE(rig.coupler_elastic && rig.rocker_elastic);
  EXPECT_EQ(rig.coupler_elastic->modes, 4);
  EXPECT_DOUBLE_EQ(*rig.coupler_elastic->area_m2, 25e-3 * 4e-3);
  EXPECT_NEAR(*rig.coupler_elastic->second_moment_m4, 4e-3 * 25e-3 * 25e-3 * 25e-3 / 12, 1e-24);
  EXPECT_EQ(rig.coupler_elastic->damping_ratios.size(), 4u);
  EXPECT_FALSE(load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml").coupler_elastic);
}

TEST(RigElastic, ReadsMeasuredModes) {
  TempDir dir;
  const Rig rig = load_rig(
      dir.write("rig.toml", with_elastic("mode_frequencies_Hz = [598.5, 2391]\ndamping_ratios = [0.012, 0.02]\n")));
  ASSERT_TRUE(rig.coupler_elastic);
  EXPECT_EQ(rig.coupler_elastic->modes, 2);
  EXPECT_EQ(rig.coupler_elastic->frequencies_Hz, (std::vector<double>{598.5, 2391}));
  EXPECT_FALSE(rig.rocker_elastic);
}

TEST(RigElastic, RejectsBadModes) {
  std::string msg = elastic_error("mode_frequencies_Hz = [598.5, -3]\n");
  EXPECT_NE(msg.find("coupler.elastic.mode_frequencies_Hz"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must be > 0 Hz"), std::string::npos) << msg;
  msg = elastic_error("mode_frequencies_Hz = [0]\n");
  EXPECT_NE(msg.find("[0] = 0 must be > 0 Hz"), std::string::npos) << msg;
  msg = elastic_error("mode_frequencies_Hz = [600, 1e300]\n");
  EXPECT_NE(msg.find("< 1 MHz"), std::string::npos) << msg;
  msg = elastic_error("mode_frequencies_Hz = [900, 600]\n");
  EXPECT_NE(msg.find("must increase"), std::string::npos) << msg;
  msg = elastic_error("mode_frequencies_Hz = [600]\ndamping_ratios = [1.0]\n");
  EXPECT_NE(msg.find("coupler.elastic.damping_ratios"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must lie in [0, 1)"), std::string::npos) << msg;
  msg = elastic_error("mode_frequencies_Hz = [600]\ndamping_ratios = [-0.01]\n");
  EXPECT_NE(msg.find("must lie in [0, 1)"), std::string::npos) << msg;
  msg = elastic_error("mode_frequencies_Hz = [600, 2400]\nmodes = 3\n");
  EXPECT_NE(msg.find("one frequency per mode"), std::string::npos) << msg;
  msg = elastic_error("mode_frequencies_Hz = [600]\ndamping_ratios = [0.01, 0.02]\n");
  EXPECT_NE(msg.find("at most one per mode"), std::string::npos) << msg;
}

TEST(RigElastic, RejectsASectionWithoutStiffness) {
  std::string msg = elastic_error("E_GPa = 0\nwidth_mm = 25\nthickness_mm = 4\n");
  EXPECT_NE(msg.find("coupler.elastic.E_GPa"), std::string::npos) << msg;
  EXPECT_NE(msg.find("no bending stiffness"), std::string::npos) << msg;
  msg = elastic_error("E_GPa = 210\nwidth_mm = 0\nthickness_mm = 4\n");
  EXPECT_NE(msg.find("coupler.elastic.width_mm"), std::string::npos) << msg;
  msg = elastic_error("E_GPa = 210\narea_mm2 = 100\nsecond_moment_mm4 = -5\n");
  EXPECT_NE(msg.find("coupler.elastic.second_moment_mm4"), std::string::npos) << msg;
  msg = elastic_error("E_GPa = 210\narea_mm2 = 100\n");
  EXPECT_NE(msg.find("second_moment_mm4' is missing"), std::string::npos) << msg;
  msg = elastic_error("density_kg_m3 = 7850\nwidth_mm = 25\nthickness_mm = 4\n");
  EXPECT_NE(msg.find("coupler.elastic.E_GPa' is missing"), std::string::npos) << msg;
  msg = elastic_error("E_GPa = 210\nwidth_mm = 25\n");
  EXPECT_NE(msg.find("needs its partner"), std::string::npos) << msg;
  msg = elastic_error("E_GPa = 210\nwidth_mm = 25\nthickness_mm = 4\nmodulus = 3\n");
  EXPECT_NE(msg.find("coupler.elastic.modulus"), std::string::npos) << msg;
}

}  // namespace
}  // namespace fourbar
