// The linkage model as the virtual rig's motion source
// (virtual_rig/linkage_motion_source.hpp): its sensors' readings against the
// virtual rig's own sensor formula (virtual_rig/sensor_signal.hpp) on rigid
// links, and an elastic coupler's vibration against the closed-form free
// decay of its first mode (frequency and damping from sim/flex).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "sim/linkage/linkage_model.hpp"
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

// An elastic coupler with one mode: between contacts nothing but the links'
// slow inertia loads it, so what the mid-span sensor reads beyond the rigid
// formula is the mode's free decay, e^{−ζωt}(a·cos ω_d t + b·sin ω_d t), at
// the frequency and damping sim/flex gives the link, plus a slow part.
TEST(LinkageMotionSource, ElasticCouplerRingsAtItsModeBetweenContacts) {
  testing::TempDir dir;
  const Scene scene = linkage_scene(dir, true);
  const std::vector<ChannelSpec> channels{sensor(ChannelRole::coupler_tangential, 154.5)};
  const double end_s = 1.0;
  const LinkageMotionSource src(scene, drive_of(scene), channels, -1.0, -0.01, end_s, 1 / kFs);
  ASSERT_TRUE(src.elastic());
  const LinkageModel model = build_linkage(*scene.rig, scene.linkage.spec);
  const ElasticLink& link = *model.elastic(1);
  const double w = link.frequencies_rad_s(0), zeta = link.damping_ratios(0);
  const double wd = w * std::sqrt(1 - zeta * zeta);
  ASSERT_NEAR(w / units::kTwoPi, 614, 10);  // docs/linkage-model.md: the thesis coupler's first mode

  // The longest contact-free stretch inside the record after a contact with an impact.
  double best_start = 0, best_length = 0;
  const auto& cs = src.contacts();
  for (std::size_t k = 0; k < cs.size(); ++k) {
    if (!cs[k].impact || cs[k].release_time_s < 0) continue;
    const double next = k + 1 < cs.size() ? cs[k + 1].time_s : end_s;
    if (next - cs[k].release_time_s > best_length) best_start = cs[k].release_time_s, best_length = next - cs[k].release_time_s;
  }
  const double window_s = std::min(best_length, 0.03);
  ASSERT_GT(window_s, 8 * units::kTwoPi / w) << "no free stretch of eight periods after an impact";

  // Least squares: the decay at (ω_d, ζ) scaled by `detune`, and a quadratic slow part.
  auto fit = [&](double detune, double* oscillation_rms) {
    const double t0 = best_start + 2 / kFs, s = zeta * w, f = wd * detune;
    const int n = static_cast<int>(window_s * kFs) - 3;
    Eigen::MatrixXd a(n, 5);
    Eigen::VectorXd y(n);
    for (int i = 0; i < n; ++i) {
      const double tau = i / kFs, t = t0 + tau;
      const LinkState st = src.at(t);
      y(i) = src.reading(0, t) - specific_force(*scene.rig, st, channels[0].role, channels[0].position_m, 0.0);
      const double decay = std::exp(-s * tau);
      a.row(i) << decay * std::cos(f * tau), decay * std::sin(f * tau), 1.0, tau, tau * tau;
    }
    const Eigen::VectorXd c = a.colPivHouseholderQr().solve(y);
    const Eigen::VectorXd osc = a.leftCols(2) * c.head(2);
    *oscillation_rms = std::sqrt(osc.squaredNorm() / n);
    return std::sqrt((y - a * c).squaredNorm() / n);
  };
  double osc = 0, osc_off = 0;
  const double residual = fit(1.0, &osc);
  EXPECT_GT(osc, 1.0) << "the mode rings with at least 1 m/s2 at mid-span";
  EXPECT_LT(residual, 0.05 * osc) << "free decay over " << window_s * 1e3 << " ms from " << best_start << " s";
  // Two per cent off the mode's frequency the same fit leaves far more.
  EXPECT_GT(fit(1.02, &osc_off), 3 * residual);
  EXPECT_GT(fit(0.98, &osc_off), 3 * residual);
}

}  // namespace
}  // namespace fourbar
