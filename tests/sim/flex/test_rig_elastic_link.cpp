// A rig file's [coupler.elastic] / [rocker.elastic] tables as elastic links:
// the thesis rig's 25 × 4 mm steel coupler rings at the Euler–Bernoulli
// frequency, keeps the rig's rigid inertia, and measured modes set the
// frequencies.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/flex/rig_elastic_link.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

TEST(RigElasticLink, ThesisCouplerFromItsSection) {
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  const std::optional<ElasticLink> coupler = rig_elastic_link(rig, RigLink::coupler);
  ASSERT_TRUE(coupler);
  const double ei = 210e9 * 4e-3 * std::pow(25e-3, 3) / 12, mu = 7850 * 100e-6, L = 0.309;
  EXPECT_NEAR(coupler->frequencies_rad_s(0) / (std::pow(std::numbers::pi / L, 2) * std::sqrt(ei / mu)), 1.0, 1e-12);
  EXPECT_EQ(coupler->modes(), 4);
  EXPECT_NEAR(coupler->damping_ratios(1), 0.015, 1e-15);
  // The rigid part is the rig's: 0.2439 kg, centre 185 mm from A.
  EXPECT_DOUBLE_EQ(coupler->mass_kg, 0.2439);
  EXPECT_DOUBLE_EQ(coupler->first_moment_kg_m.x(), 0.2439 * 0.185);
  EXPECT_DOUBLE_EQ(coupler->inertia_origin_kg_m2, rig.coupler.inertia_about_joint());
  EXPECT_TRUE(rig_elastic_link(rig, RigLink::rocker));
  EXPECT_FALSE(rig_elastic_link(load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml"), RigLink::coupler));
}

TEST(RigElasticLink, MeasuredModes) {
  testing::TempDir dir;
  const Rig rig = load_rig(dir.write("rig.toml", testing::thesis_rig_toml() +
                                                     "\n[rocker.elastic]\nmode_frequencies_Hz = [598.5, 2391]\n"
                                                     "damping_ratios = [0.012]\n"));
  const std::optional<ElasticLink> rocker = rig_elastic_link(rig, RigLink::rocker);
  ASSERT_TRUE(rocker);
  EXPECT_NEAR(rocker->frequencies_rad_s(0) / (2 * std::numbers::pi), 598.5, 1e-9);
  EXPECT_NEAR(rocker->frequencies_rad_s(1) / (2 * std::numbers::pi), 2391, 1e-9);
  EXPECT_DOUBLE_EQ(rocker->damping_ratios(1), 0.012);  // the last ratio repeats
  // Without a section the modes' mass is the link's, spread over its length.
  EXPECT_NEAR(rocker->modal_mass(0, 0), rig.rocker.mass_kg / 2, 1e-14);
}

}  // namespace
}  // namespace fourbar
