// Scene [clearance] table: defaults, overrides and rejected values.

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "sim/scene.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

using testing::TempDir;

const std::string kScene = R"(rig = "r.toml"
model = "clearance"
crank_speed_rpm = 350
outputs = ["alpha3_rad_s2", "mode", "gap_mm"]

[clearance]
radial_mm = 0.1
restitution = 0.5
contact = "stick-slip"
friction_coefficient = 0.2
)";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto i = text.find(from);
  EXPECT_NE(i, std::string::npos) << from;
  return text.replace(i, from.size(), to);
}

std::string error_of(const std::string& text) {
  TempDir dir;
  dir.write("r.toml", testing::thesis_rig_toml());
  try {
    load_scene(dir.write("s.toml", text));
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return {};
}

TEST(ClearanceScene, Loads) {
  TempDir dir;
  dir.write("r.toml", testing::thesis_rig_toml());
  const Scene s = load_scene(dir.write("s.toml", kScene));
  EXPECT_EQ(s.model, Model::clearance);
  EXPECT_DOUBLE_EQ(s.clearance_m(), 0.1e-3);
  EXPECT_EQ(s.clearance.restitution, 0.5);
  EXPECT_EQ(s.clearance.contact, ContactLaw::stick_slip);
  EXPECT_EQ(s.clearance.friction_coefficient, 0.2);
  const Scene r = load_scene(dir.write("t.toml", replaced(kScene, "radial_mm = 0.1\n", "")));
  EXPECT_DOUBLE_EQ(r.clearance_m(), 0.254e-3);  // the rig's
}

TEST(ClearanceScene, RejectsBadValues) {
  auto has = [](const std::string& msg, const std::string& what) {
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  };
  has(error_of(replaced(kScene, "restitution = 0.5", "restitution = 1.5")), "restitution");
  has(error_of(replaced(kScene, "restitution = 0.5", "restitution = -0.1")), "[0, 1]");
  has(error_of(replaced(kScene, "friction_coefficient = 0.2", "friction_coefficient = -0.2")), "friction_coefficient");
  has(error_of(replaced(kScene, "radial_mm = 0.1", "radial_mm = -0.1")), "radial_mm");
  has(error_of(replaced(kScene, "radial_mm = 0.1", "radial_mm = 0")), "radial_mm");
  has(error_of(replaced(kScene, "contact = \"stick-slip\"", "contact = \"smooth\"")), "only used with contact");
  has(error_of(replaced(kScene, "friction_coefficient = 0.2\n", "")), "is required");
  has(error_of(replaced(kScene, "restitution = 0.5\n", "")), "restitution");
  has(error_of(replaced(kScene, "contact = \"stick-slip\"", "contact = \"stickslip\"")), "did you mean 'stick-slip'");
  has(error_of(kScene + "restitushun = 1\n"), "unknown key 'clearance.restitushun'");
  has(error_of(replaced(kScene, "\"mode\"", "\"crank_pivot_fx_N\"")), "does not compute");
  has(error_of(replaced(kScene, "[clearance]", "steady_state = true\n[clearance]")), "steady_state");
  has(error_of(kScene + "steady_state = true\nmax_revolutions = 0\n"), "max_revolutions");
  has(error_of(replaced(kScene, "model = \"clearance\"", "model = \"nominal\"")), "only model = \"clearance\"");
  has(error_of(replaced(kScene, "= 350", "= 0")), "crank_speed_rpm");
  has(error_of(replaced(replaced(kScene, "contact = \"stick-slip\"", "contact = \"rough\""),
                        "friction_coefficient = 0.2\n", "following_friction = true\n")),
      "following_friction");
  has(error_of(kScene + "steady_criterion = \"periodical\"\n"), "did you mean 'periodic'");
  has(error_of(kScene + "statistical_window = 1\n"), "statistical_window");
  has(error_of(kScene + "statistical_tolerance = 0\n"), "statistical_tolerance");
}

TEST(ClearanceScene, SteadyStateAndWallFrictionKeys) {
  TempDir dir;
  dir.write("r.toml", testing::thesis_rig_toml());
  const Scene d = load_scene(dir.write("d.toml", kScene));
  EXPECT_FALSE(d.clearance.following_friction);
  EXPECT_EQ(d.clearance.steady_criterion, ClearanceSettings::SteadyCriterion::either);
  EXPECT_EQ(d.clearance.statistical_window, 20);
  EXPECT_EQ(d.clearance.statistical_tolerance, 0.05);
  const Scene s = load_scene(dir.write("s.toml", kScene + "following_friction = true\nsteady_state = true\n"
                                                          "steady_criterion = \"statistical\"\n"
                                                          "statistical_window = 12\nstatistical_tolerance = 0.1\n"));
  EXPECT_TRUE(s.clearance.following_friction);
  EXPECT_EQ(s.clearance.steady_criterion, ClearanceSettings::SteadyCriterion::statistical);
  EXPECT_EQ(s.clearance.statistical_window, 12);
  EXPECT_EQ(s.clearance.statistical_tolerance, 0.1);
}

TEST(ClearanceScene, RejectsClearanceBeyondTheToggleMargin) {
  // Issue 7: with the ground made 556 mm the loop comes within 1 mm of its
  // 180° toggle; a 1.5 mm clearance cannot close the loop with the pin on the
  // wall (runs gave energy residuals of order 1), 0.5 mm can.
  EXPECT_NEAR(toggle_margin_m(thesis_rig()), 0.170, 1e-12);  // (309 + 312) − (387 + 64) mm
  TempDir dir;
  dir.write("r.toml", replaced(testing::thesis_rig_toml(), "length_mm = 387.0", "length_mm = 556.0"));
  const std::string msg = [&] {
    try {
      load_scene(dir.write("s.toml", replaced(kScene, "radial_mm = 0.1", "radial_mm = 1.5")));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  }();
  EXPECT_NE(msg.find("radial_mm"), std::string::npos) << msg;
  EXPECT_NE(msg.find("within 1 mm of a toggle"), std::string::npos) << msg;
  EXPECT_NO_THROW(load_scene(dir.write("t.toml", replaced(kScene, "radial_mm = 0.1", "radial_mm = 0.5"))));
}

}  // namespace
}  // namespace fourbar
