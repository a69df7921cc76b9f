#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "compare/metrics.hpp"
#include "compare/session_severity.hpp"
#include "common/units.hpp"

namespace fourbar {
namespace {

std::vector<double> wave(std::size_t n, double (*f)(double), double scale = 1) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = scale * f(units::kTwoPi * static_cast<double>(i) / static_cast<double>(n));
  return x;
}

TEST(CompareMetrics, RmsCorrelationPeakOfKnownWaves) {
  const auto s = wave(720, [](double t) { return std::sin(t); });
  const auto s2 = wave(720, [](double t) { return std::sin(t); }, 2.0);
  const auto c = wave(720, [](double t) { return std::cos(t); });
  EXPECT_NEAR(rms(s), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(rms_difference(s2, s), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(rms_difference(s, c), 1.0, 1e-12);  // |sin − cos| has RMS 1
  EXPECT_NEAR(correlation(s, s2), 1.0, 1e-12);
  EXPECT_NEAR(correlation(s, c), 0.0, 1e-12);
  std::vector<double> neg(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) neg[i] = -3 * s[i] + 5;
  EXPECT_NEAR(correlation(s, neg), -1.0, 1e-12);
  EXPECT_NEAR(peak_ratio(s2, s), 2.0, 1e-12);
  EXPECT_EQ(correlation(s, std::vector<double>(720, 1.0)), 0.0);
}

TEST(CompareMetrics, LargestPeaksKeepTheirDistanceAroundTheTurn) {
  std::vector<double> x(360, 0.0);
  x[359] = 10, x[1] = 9;  // 2 points apart across the wrap: one burst
  x[100] = -8, x[105] = 7, x[200] = 6;
  const auto p = largest_peaks(x, 3, 10);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0], 359u);
  EXPECT_EQ(p[1], 100u);
  EXPECT_EQ(p[2], 200u);
  EXPECT_EQ(circular_distance(359, 1, 360), 2u);
}

TEST(SessionSeverity, GroupsBySpeedAndByClearance) {
  std::vector<SeverityPoint> pts;
  for (double rpm : {350.3, 249.8, 250.2, 349.9})
    for (double c : {0.254, 0.0254}) {
      SeverityPoint p;
      p.recording = std::to_string(rpm) + "_" + std::to_string(c);
      p.speed_rpm = rpm, p.clearance_mm = c;
      pts.push_back(p);
    }
  const SeverityTables t = severity_tables(pts);
  ASSERT_EQ(t.by_speed.size(), 2u);
  EXPECT_NEAR(t.by_speed[0].value, 250.0, 1e-9);
  EXPECT_EQ(t.by_speed[0].points.size(), 4u);
  EXPECT_LE(t.by_speed[0].points.front().clearance_mm, t.by_speed[0].points.back().clearance_mm);
  ASSERT_EQ(t.by_clearance.size(), 2u);
  EXPECT_NEAR(t.by_clearance[1].value, 0.254, 1e-12);
  EXPECT_LT(t.by_clearance[1].points.front().speed_rpm, t.by_clearance[1].points.back().speed_rpm);
}

}  // namespace
}  // namespace fourbar
