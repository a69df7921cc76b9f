// The link-vibration check (compare/link_vibration.hpp) on turns made by
// tests/support/impact_turns.hpp. The linkage model's vibration is a plateau
// (each impact rings at a frequency drawn from 550–900 Hz), which the rigid
// family check's peak test does not see; the check places the measurement
// between a rigid-link and an elastic-link model of other impacts, scaled
// by how each meets the measurement below the vibration.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "compare/link_vibration.hpp"
#include "support/impact_turns.hpp"

namespace fourbar {
namespace {

using test::kCrankHz;
using test::kN;
using test::nominal;
using test::turns;

constexpr double kPlateauHz = 550, kPlateauSpreadHz = 350;

/// α turns with impacts of `impact` and, for ring > 0, the plateau.
std::vector<double> plateau(double impact, double noise, double ring, std::uint64_t seed) {
  return turns(25, impact, noise, ring, seed, kPlateauHz, 0.02, kPlateauSpreadHz);
}

TEST(LinkVibration, PlateauTheRigidCheckMissesIsNamedAcrossItsBand) {
  // The session's model 1.6x more violent than the measurement; the linkage
  // pair at yet another impact level (e = 0.9 against the session's e).
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const auto measured = plateau(200, 5, 1.0, seed), model = plateau(320, 0, 0, seed + 100);
    const auto rigid = plateau(150, 0, 0, seed + 200), elastic = plateau(150, 0, 1.0, seed + 300);
    ModelFamilyCheck c = check_model_family(measured, model, nominal(), kCrankHz, 1000, {});
    ASSERT_TRUE(c.checked) << c.not_checked;
    const LinkVibrationCheck v = check_link_vibration(c, measured, model, rigid, elastic, nominal());
    ASSERT_TRUE(v.checked) << v.not_checked;
    EXPECT_TRUE(v.present) << "seed " << seed << ": position " << v.position;
    EXPECT_GT(v.position, 0.7) << "seed " << seed;
    EXPECT_LT(v.position, 1.3) << "seed " << seed;
    EXPECT_LE(v.low_hz, 600);
    EXPECT_GE(v.high_hz, 850);
    // One finding for the span, the agreement judged below it.
    ASSERT_EQ(c.unmodelled.size(), 1u);
    EXPECT_EQ(c.unmodelled.front().kind, "link vibration");
    EXPECT_GE(c.unmodelled.front().peak_hz, v.low_hz);
    EXPECT_LE(c.unmodelled.front().peak_hz, v.high_hz);
    ASSERT_TRUE(c.judged_below_hz);
    EXPECT_LE(*c.judged_below_hz, v.low_hz);
    EXPECT_TRUE(c.a_scatter_below);
  }
}

TEST(LinkVibration, RigidMeasurementStaysWithTheRigidLinks) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const auto measured = plateau(200, 5, 0, seed), model = plateau(320, 0, 0, seed + 100);
    const auto rigid = plateau(150, 0, 0, seed + 200), elastic = plateau(150, 0, 1.0, seed + 300);
    ModelFamilyCheck c = check_model_family(measured, model, nominal(), kCrankHz, 1000, {});
    ASSERT_TRUE(c.checked);
    const LinkVibrationCheck v = check_link_vibration(c, measured, model, rigid, elastic, nominal());
    ASSERT_TRUE(v.checked) << v.not_checked;
    EXPECT_FALSE(v.present) << "seed " << seed << ": position " << v.position;
    EXPECT_LT(std::abs(v.position), 0.3) << "seed " << seed;
    EXPECT_TRUE(c.unmodelled.empty());
    EXPECT_FALSE(c.judged_below_hz);
  }
}

TEST(LinkVibration, PositionIsTheLogDistanceBetweenTheTwoModels) {
  // Measured = the rigid-link model × 2 below and × 2·√(E/S) over the
  // vibration bands: halfway in log between the two hypotheses.
  const auto model = plateau(320, 0, 0, 11), rigid = plateau(150, 0, 0, 12), elastic = plateau(150, 0, 1.0, 12);
  ModelFamilyCheck c = check_model_family(rigid, model, nominal(), kCrankHz, 1000, {});
  ASSERT_TRUE(c.checked);
  const std::vector<double> e = band_mean_squares(elastic, nominal(), kCrankHz, c.bands);
  const std::vector<double> s = band_mean_squares(rigid, nominal(), kCrankHz, c.bands);
  ModelFamilyCheck d = c;
  for (std::size_t b = 0; b < d.bands.size(); ++b) {
    const bool vibration = e[b] >= kVibrationBandRatio * s[b];
    d.bands[b].measured_ms = 2 * s[b] * (vibration ? std::sqrt(e[b] / s[b]) : 1.0);
  }
  // q: the elastic model's own ratio below; the measured sits at r = 2 there.
  const LinkVibrationCheck v = check_link_vibration(d, rigid, model, rigid, elastic, nominal());
  ASSERT_TRUE(v.checked) << v.not_checked;
  double sum_s = 0, sum_e = 0, sum_m = 0;
  for (std::size_t b : v.vibration_bands) sum_s += s[b], sum_e += e[b], sum_m += d.bands[b].measured_ms;
  const double expected = std::log(sum_m / (2 * sum_s)) / std::log(sum_e / (v.elastic_reference_ratio * sum_s));
  EXPECT_NEAR(v.reference_ratio, 2.0, 1e-12);
  EXPECT_NEAR(v.position, expected, 1e-12);
}

TEST(LinkVibration, NotCheckedWhenTheElasticModelAddsNothing) {
  const auto measured = plateau(200, 5, 1.0, 21), model = plateau(320, 0, 0, 22), rigid = plateau(150, 0, 0, 23);
  ModelFamilyCheck c = check_model_family(measured, model, nominal(), kCrankHz, 1000, {});
  ASSERT_TRUE(c.checked);
  const auto before = c.unmodelled.size();
  const LinkVibrationCheck v = check_link_vibration(c, measured, model, rigid, rigid, nominal());
  EXPECT_FALSE(v.checked);
  EXPECT_NE(v.not_checked.find("no band with 4x the rigid-link model's energy"), std::string::npos) << v.not_checked;
  EXPECT_EQ(c.unmodelled.size(), before);
  // Too few turns of the linkage model.
  const std::vector<double> three(rigid.begin(), rigid.begin() + 3 * kN);
  EXPECT_FALSE(check_link_vibration(c, measured, model, three, three, nominal()).checked);
}

}  // namespace
}  // namespace fourbar
