// The linkage model as a matched theory (compare/linkage_theory.hpp), checked
// by a second computation path for each of its parts.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "common/error.hpp"
#include "common/units.hpp"
#include "compare/linkage_theory.hpp"
#include "compare/matched_theory.hpp"
#include "sim/linkage/linkage_model.hpp"

namespace fourbar {
namespace {

constexpr double kLinkageClearance_m = 0.1016e-3;

double relative_rms(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0, s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d += (a[i] - b[i]) * (a[i] - b[i]), s += b[i] * b[i];
  return std::sqrt(d / s);
}

ResolvedMount mid_coupler(const Rig& rig) {
  AccelerometerMount m;
  m.channel = "coupler_t";
  m.link = SensedLink::coupler;
  m.distance_m = 0.1545;
  return resolve_mount(rig, m);
}

LinkageTheoryRun run_on(const CrankGrid& grid, double w, int sub) {
  LinkageTheoryRun run;
  run.grid = grid;
  run.crank_speed_rad_s = w;
  run.clearance_m = kLinkageClearance_m;
  run.warmup_turns = 1;
  run.turns = 2;
  run.name = "test";
  run.sub_samples = sub;
  return run;
}

LinkageModel bearing_clearance(const Rig& rig, double clearance_m) {
  LinkageSpec spec;
  spec.clearance_m = {0.0, clearance_m, 0.0};
  spec.law = {1e10, 1.5, DampingLaw::calibrated, 0.8};
  spec.tolerance = 1e-9;
  return build_linkage(rig, spec);
}

/// Relative RMS of (α3 from the mid-span reading) − (the rigid frame's α3).
double sensor_path_error(const Rig& rig, double clearance_m) {
  const LinkageModel linkage = bearing_clearance(rig, clearance_m);
  const double w = units::rpm_to_rad_s(350);
  const CrankGrid grid{180, 0.0, 1.0};
  LinkageTheoryRun with = run_on(grid, w, 1), without = run_on(grid, w, 1);
  with.sensor[0] = mid_coupler(rig);
  const MatchedTheory a = simulate_linkage_theory(linkage, with), b = simulate_linkage_theory(linkage, without);
  const auto& x = a.series[index_of(LinkQuantity::alpha3)].clearance_revolutions;
  const auto& y = b.series[index_of(LinkQuantity::alpha3)].clearance_revolutions;
  EXPECT_EQ(x.size(), 2u * 180u);
  return relative_rms(x, y);
}

TEST(LinkageTheory, SensorReadingGivesTheRigidCouplerAlphaUpToTheNominalAngle) {
  // Rigid links, the clearance at the coupler–rocker joint: the crank pin A
  // moves as the nominal crank says, and analyze's conversion of the
  // mid-span tangential reading returns the coupler's own α3 but for the
  // angle it projects A's acceleration with — the nominal θ3, which the
  // clearance moves by up to ξ/l3 (3.3e-4 rad at 0.1016 mm). So the two
  // paths (sensor kinematics then conversion; the model's rigid frame)
  // differ by O(ξ/l3), and by 10x less at a 10x smaller clearance.
  const Rig rig = thesis_rig();
  const double big = sensor_path_error(rig, 0.1016e-3), small = sensor_path_error(rig, 0.01016e-3);
  EXPECT_LT(big, 3 * 0.1016e-3 / 0.309);
  EXPECT_LT(small, 0.25 * big);
  EXPECT_GT(small, 0.0);
}

TEST(LinkageTheory, CellMeansAreTheVelocityChangeOverTheCell) {
  // The cell mean of α3 is (ω3(end) − ω3(start)) / cell exactly (the
  // three-mode theory's definition); the trapezoid rule over 8 sub-samples
  // approaches it, impacts in the bearing included. ω3 at every half cell
  // from a point-sampled run on the doubled grid gives the exact means.
  const Rig rig = thesis_rig();
  const LinkageModel linkage = bearing_clearance(rig, 0.1016e-3);
  const double w = units::rpm_to_rad_s(350);
  const std::size_t n = 180;
  const MatchedTheory cells = simulate_linkage_theory(linkage, run_on(CrankGrid{n, 0.0, 1.0}, w, 8));
  // Half cells: the same run (same start) sampled on the doubled grid; cell
  // j runs from its half-grid point 2j − 1 to 2j + 1 (the first cell's start
  // lies before the kept turns: left out).
  const MatchedTheory halves = simulate_linkage_theory(linkage, run_on(CrankGrid{2 * n, 0.0, 1.0}, w, 1));
  EXPECT_GT(halves.severity.impacts_per_rev, 0.0);
  const auto& omega = halves.series[index_of(LinkQuantity::omega3)].clearance_revolutions;
  const auto& alpha = cells.series[index_of(LinkQuantity::alpha3)].clearance_revolutions;
  const double cell_s = units::kTwoPi / (static_cast<double>(n) * w);
  std::vector<double> exact, trapezoid;
  for (std::size_t j = 1; j < 2 * n; ++j) {
    exact.push_back((omega[2 * j + 1] - omega[2 * j - 1]) / cell_s);
    trapezoid.push_back(alpha[j]);
  }
  const double error = relative_rms(trapezoid, exact);
  EXPECT_LT(error, 0.02);
  std::cout << "[ cell means ] trapezoid over 8 sub-samples against Δω3/cell: relative RMS " << error << "\n";
}

TEST(LinkageTheory, RunErrorsAreNamed) {
  const Rig rig = thesis_rig();
  const LinkageModel linkage = bearing_clearance(rig, 0.1016e-3);
  LinkageTheoryRun run = run_on(CrankGrid{90, 0.0, 1.0}, -units::rpm_to_rad_s(350), 1);
  EXPECT_THROW(simulate_linkage_theory(linkage, run), RunError);  // the grid turns against the crank
  run = run_on(CrankGrid{90, 0.0, 1.0}, units::rpm_to_rad_s(350), 8);
  run.warmup_turns = 0;
  EXPECT_THROW(simulate_linkage_theory(linkage, run), RunError);  // cell means need a warm-up turn
}

}  // namespace
}  // namespace fourbar
