// The smooth model of the noisy objective: a known quadratic plus noise of
// a known size gives back its minimum, the interval where it stays within Δ,
// and the e–μ correlation of its curvature.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fit/objective_surrogate.hpp"
#include "fit/session_fit.hpp"
#include "common/error.hpp"

namespace fourbar {
namespace {

TEST(ObjectiveSurrogate, RecoversMinimumIntervalAndCorrelation) {
  // χ²(e, μ) = 40 + 400·(e − 0.4)² + 2·c·(e − 0.4)(μ − 0.2)·400 + 400·(μ − 0.2)², c = 0.5
  const double c = 0.5, noise = 2.0;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g(0.0, noise);
  std::vector<EvaluatedPoint> pts;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 5; ++j) {
      const double e = 0.1 * i, mu = 0.1 * j, de = e - 0.4, dm = mu - 0.2;
      pts.push_back({e, mu, 40 + 400 * (de * de + 2 * c * de * dm + dm * dm) + g(rng)});
    }
  const SurrogateFit s = fit_surrogate(pts, 0, 1, 0, 0.5, true, 9.0);
  ASSERT_TRUE(s.ok);
  EXPECT_NEAR(s.restitution, 0.4, 0.03);
  EXPECT_NEAR(s.friction, 0.2, 0.03);
  // Profile of e: min over μ gives 400·(1 − c²)·de² ≤ Δ → de = √(Δ/300).
  const double half = std::sqrt(s.delta / (400 * (1 - c * c)));
  EXPECT_NEAR(s.restitution_high - s.restitution_low, 2 * half, 0.04);
  ASSERT_TRUE(s.correlation.has_value());
  EXPECT_NEAR(*s.correlation, -c, 0.1);  // a positive cross term is a negative correlation of the estimates
  EXPECT_GE(s.delta, 9.0);
}

TEST(ObjectiveSurrogate, FlatObjectiveIsNotBounded) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g(0.0, 3.0);
  std::vector<EvaluatedPoint> pts;
  for (int i = 0; i <= 10; ++i) pts.push_back({0.1 * i, 0, 50 + g(rng)});
  const SurrogateFit s = fit_surrogate(pts, 0, 1, 0, 1, false, 9.0);
  // Either no upward curvature, or an interval that covers most of the box.
  EXPECT_TRUE(!s.ok || s.restitution_high - s.restitution_low > 0.5);
}

TEST(FitOptions, BackwardsBoxIsNamed) {
  FitOptions o;
  o.box.restitution_low = 0.9, o.box.restitution_high = 0.1;
  try {
    validate_fit_options(o);
    FAIL() << "a backwards box was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--restitution"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("backwards"), std::string::npos) << e.what();
  }
  o = FitOptions{};
  o.box.friction_low = 0.4, o.box.friction_high = 0.2;
  EXPECT_THROW(validate_fit_options(o), InputError);
  EXPECT_NO_THROW(validate_fit_options(FitOptions{}));
}

}  // namespace
}  // namespace fourbar
