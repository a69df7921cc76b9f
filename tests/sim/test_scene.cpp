// Scene loading: rig resolved relative to the scene, outputs validated.

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/units.hpp"
#include "sim/scene.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

using testing::replace;
using testing::TempDir;

const std::string kScene = R"(rig = "rigs/r.toml"
model = "nominal"
crank_speed_rpm = 350
start_angle_deg = 10
revolutions = 2
samples_per_revolution = 720
outputs = ["alpha3_rad_s2", "crank_torque_Nm"]
)";

std::string scene_error(const std::string& text) {
  TempDir dir;
  dir.write("rigs/r.toml", testing::thesis_rig_toml());
  const auto file = dir.write("s.toml", text);
  try {
    load_scene(file);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return {};
}

TEST(Scene, LoadsWithRigRelativeToSceneFile) {
  TempDir dir;
  dir.write("rigs/r.toml", testing::thesis_rig_toml());
  const Scene s = load_scene(dir.write("s.toml", kScene));
  EXPECT_NEAR(s.crank_speed_rad_s, 36.651914291880923, 1e-12);
  EXPECT_NEAR(s.start_angle_rad, units::deg_to_rad(10), 1e-15);
  EXPECT_EQ(s.revolutions, 2);
  EXPECT_EQ(s.samples_per_revolution, 720);
  ASSERT_EQ(s.outputs.size(), 2u);
  EXPECT_DOUBLE_EQ(s.rig->coupler.length_m, 0.309);
}

TEST(Scene, RejectsUnknownOutputWithSuggestion) {
  const auto msg = scene_error(replace(kScene, "\"crank_torque_Nm\"", "\"crank_torque_nm\""));
  EXPECT_NE(msg.find("unknown output 'crank_torque_nm'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("did you mean 'crank_torque_Nm'"), std::string::npos) << msg;
}

TEST(Scene, RejectsBadValues) {
  EXPECT_NE(scene_error(replace(kScene, "revolutions = 2", "revolutions = 0")).find("revolutions"), std::string::npos);
  EXPECT_NE(scene_error(replace(kScene, "= 350", "= 0")).find("crank_speed_rpm"), std::string::npos);
  EXPECT_NE(scene_error(replace(kScene, "\"nominal\"", "\"nominall\"")).find("did you mean 'nominal'"),
            std::string::npos);
  EXPECT_NE(scene_error(replace(kScene, "rigs/r.toml", "rigs/none.toml")).find("no such file"), std::string::npos);
  EXPECT_NE(scene_error(replace(kScene, "revolutions = 2", "revolutionz = 2")).find("revolutionz"),
            std::string::npos);
  EXPECT_NE(scene_error(replace(kScene, "outputs = [\"alpha3_rad_s2\", ", "outputs = [\"alpha3_rad_s2\", \"alpha3_rad_s2\", "))
                .find("twice"),
            std::string::npos);
}

TEST(Scene, BadRigIsReportedThroughTheScene) {
  TempDir dir;
  dir.write("rigs/r.toml", replace(testing::thesis_rig_toml(), "mass_kg = 0.6095", "mass_kg = -1"));
  try {
    load_scene(dir.write("s.toml", kScene));
    FAIL();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("s.toml"), std::string::npos) << msg;
    EXPECT_NE(msg.find("crank.mass_kg"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace fourbar
