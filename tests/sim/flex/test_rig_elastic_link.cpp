// A rig file's [coupler.elastic] / [rocker.elastic] tables as elastic links:
// the thesis rig's 25 × 4 mm steel coupler rings at the Euler–Bernoulli
// frequency, keeps the rig's rigid inertia, and measured modes set the
// frequencies.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "sim/flex/rig_elastic_link.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

TEST(RigElasticLink, ThesisCouplerFromItsSection) {
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  const std::optional<ElasticLink> coupler = rig_elastic_link(rig, RigLink::coupler);
  ASSERT_TRUE(coupler);
  EXPECT_EQ(coupler->modes(), 4);
  EXPECT_NEAR(coupler->damping_ratios(1), 0.015, 1e-15);
  // The rigid part is the rig's: 0.2439 kg, centre 185 mm from A.
  EXPECT_NEAR(coupler->mass_kg, 0.2439, 1e-15);
  EXPECT_NEAR(coupler->first_moment_kg_m.x(), 0.2439 * 0.185, 1e-15);
  EXPECT_NEAR(coupler->inertia_origin_kg_m2, rig.coupler.inertia_about_joint(), 1e-15);
  EXPECT_TRUE(rig_elastic_link(rig, RigLink::rocker));
  EXPECT_FALSE(rig_elastic_link(load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml"), RigLink::coupler));
  // Given the uniform bar's own mass, centre and inertia (m = μL at L/2,
  // m·L²/12 + m·d²/12 about it), it rings at the Euler–Bernoulli frequency.
  Rig uniform = rig;
  const double ei = 210e9 * 4e-3 * std::pow(25e-3, 3) / 12, mu = 7850 * 100e-6, L = 0.309, d = 25e-3;
  uniform.coupler.mass_kg = mu * L;
  uniform.coupler.mass_centre_m = L / 2;
  uniform.coupler.inertia_cg_kg_m2 = mu * L * (L * L + d * d) / 12;
  const std::optional<ElasticLink> bar = rig_elastic_link(uniform, RigLink::coupler);
  ASSERT_TRUE(bar);
  EXPECT_NEAR(bar->frequencies_rad_s(0) / (std::pow(std::numbers::pi / L, 2) * std::sqrt(ei / mu)), 1.0, 1e-12);
}

// The rig's measured mass, centre and inertia and the modes' integrals come
// from one mass distribution (linear μ and a rotary inertia), so the link's
// mass matrix is positive definite for any number of modes. Before, the modal
// integrals were the uniform bar's beside the measured rigid part: with 3 or
// more sines the modes nearly represent a rigid motion and the thesis
// coupler's and rocker's mass matrices were indefinite (the linkage's energy
// books did not close).
TEST(RigElasticLink, MassMatrixPositiveDefiniteForAnyModeCount) {
  Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  for (RigLink which : {RigLink::coupler, RigLink::rocker})
    for (int modes = 1; modes <= 8; ++modes) {
      (which == RigLink::coupler ? rig.coupler_elastic : rig.rocker_elastic)->modes = modes;
      const std::optional<ElasticLink> link = rig_elastic_link(rig, which);
      ASSERT_TRUE(link);
      const int n = link->modes();
      Eigen::MatrixXd m = Eigen::MatrixXd::Zero(3 + n, 3 + n);
      m(0, 0) = m(1, 1) = link->mass_kg;
      m(1, 2) = m(2, 1) = link->first_moment_kg_m.x();
      m(2, 2) = link->inertia_origin_kg_m2;
      m.block(0, 3, 2, n) = link->shape_moment;
      m.block(3, 0, n, 2) = link->shape_moment.transpose();
      m.block(2, 3, 1, n) = link->bending_coupling.transpose();
      m.block(3, 2, n, 1) = link->bending_coupling;
      m.block(3, 3, n, n) = link->modal_mass;
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(m);
      // Smallest eigenvalue relative to the largest: well above rounding.
      EXPECT_GT(eig.eigenvalues().minCoeff(), 1e-6 * eig.eigenvalues().maxCoeff())
          << to_string(which) << ", " << modes << " modes";
    }
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
