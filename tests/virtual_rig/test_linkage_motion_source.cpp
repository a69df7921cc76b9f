// The linkage model as the virtual rig's motion source
// (virtual_rig/linkage_motion_source.hpp): its sensors' readings against the
// virtual rig's own sensor formula (virtual_rig/sensor_signal.hpp) on rigid
// links. (An elastic coupler's vibration between contacts is NOT the free
// decay of sim/flex's first pinned–pinned mode: with the pin free at B the
// frame and the mode couple; docs/virtual-rig.md — no closed-form check yet.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "support/temp_dir.hpp"
#include "virtual_rig/linkage_motion_source.hpp"
#include "virtual_rig/sensor_signal.hpp"

namespace fourbar {
namespace {

constexpr double kFs = 12800;

Scene linkage_scene(const testing::TempDir& dir, bool elastic) {
  const std::string text = std::string("rig = \"") + FOURBAR_SOURCE_DIR + "/data/rigs/thesis_elastic.toml\"\n" +
                           "model = \"linkage\"\ncrank_speed_rpm = 350.0\nstart_angle_deg = 30.0\noutputs = [\"alpha3_rad_s2\"]\n"
                           "[linkage]\ncoupler_rocker_radial_mm = 0.254\nrestitution = 0.8\n"
                           "contact_stiffness_N_per_m_n = 1e10\ntolerance = 1e-9\n" +
                           (elastic ? "elastic_links = [\"coupler\"]\nelastic_modes = 1\n" : "");
  return load_scene(dir.write("scene.toml", text));
}

ChannelSpec sensor(ChannelRole role, double position_mm, double offset_mm = 0) {
  ChannelSpec c;
  c.role = role;
  c.position_m = position_mm * 1e-3;
  c.offset_m = offset_mm * 1e-3;
  return c;
}

CrankDrive drive_of(const Scene& scene) {
  CrankDrive d;
  d.start_angle_rad = scene.start_angle_rad;
  d.mean_speed_rad_s = scene.crank_speed_rad_s;
  return d;
}

// On rigid links the simulator's sensor (sim/linkage/linkage_sensor.cpp) and
// the virtual rig's formula from the links' angles, rates and accelerations
// are two formulations of the same reading: they agree at every node.
TEST(LinkageMotionSource, RigidLinksReadAsTheVirtualRigsSensorFormula) {
  testing::TempDir dir;
  const Scene scene = linkage_scene(dir, false);
  const std::vector<ChannelSpec> channels{sensor(ChannelRole::coupler_tangential, 289.0, 5.0),
                                          sensor(ChannelRole::rocker_tangential, 292.0),
                                          sensor(ChannelRole::coupler_normal, 150.0)};
  const LinkageMotionSource src(scene, drive_of(scene), channels, -0.4, -0.01, 0.2, 1 / kFs);
  EXPECT_FALSE(src.elastic());
  EXPECT_TRUE(src.reads(0));
  EXPECT_TRUE(src.reads(1));
  EXPECT_FALSE(src.reads(2));  // a normal axis: from the links' state, as on the clearance model
  EXPECT_FALSE(src.contacts().empty());
  double scale = 0, worst = 0;
  for (int i = 0; i < static_cast<int>(0.2 * kFs); ++i) {
    const double t = i / kFs;
    const LinkState st = src.at(t);
    for (std::size_t c = 0; c < 2; ++c) {
      const double formula = specific_force(*scene.rig, st, channels[c].role, channels[c].position_m, channels[c].offset_m);
      scale = std::max(scale, std::abs(formula));
      worst = std::max(worst, std::abs(src.reading(c, t) - formula));
    }
  }
  EXPECT_GT(scale, 10.0);
  EXPECT_LT(worst, 1e-9 * scale) << "largest difference " << worst << " m/s2 of " << scale;
}

}  // namespace
}  // namespace fourbar
