// The analysis of one recording on several threads (AnalyzeOptions::threads)
// gives the result of one thread bit for bit: every revolution's grids, in
// the same order to the observer, the averages and spreads, the spectra, the
// normal channels' check, the warnings. Chunks of a few revolutions (many
// chunks in flight), two pulse-train segments, guard revolutions, and both
// this chain and the thesis's (ideal filter, running trapezoid carried from
// chunk to chunk).

#include <gtest/gtest.h>

#include <cstring>

#include "virtual_session.hpp"

namespace fourbar {
namespace {

using testing::VirtualSetup;

/// Every revolution as the observer saw it, in order.
struct Recorder final : RevolutionObserver {
  std::vector<std::size_t> numbers;
  std::vector<bool> averaged;
  std::vector<double> values;
  void on_revolution(const AnalyzedRevolution& r) override {
    numbers.push_back(r.number);
    averaged.push_back(r.averaged);
    for (const auto& v : {r.crank_speed_rad_s, r.alpha3_rad_s2, r.omega3_rad_s, r.alpha4_rad_s2, r.omega4_rad_s})
      values.insert(values.end(), v.begin(), v.end());
  }
};

/// Equal bit for bit (NaN included), and how many values differ otherwise.
void expect_identical(const std::vector<double>& a, const std::vector<double>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) differ += std::memcmp(&a[i], &b[i], sizeof(double)) != 0;
  EXPECT_EQ(differ, 0u) << what << ": " << differ << " of " << a.size() << " values differ";
}

void expect_identical(const AngleAverage& a, const AngleAverage& b, const char* what) {
  EXPECT_EQ(a.revolutions, b.revolutions) << what;
  expect_identical(a.mean, b.mean, what);
  expect_identical(a.std, b.std, what);
}

void expect_same_analysis(const RecordingAnalysis& one, const RecordingAnalysis& many) {
  EXPECT_EQ(one.revolutions, many.revolutions);
  EXPECT_EQ(one.revolutions_clipped, many.revolutions_clipped);
  EXPECT_EQ(one.revolution_numbers, many.revolution_numbers);
  EXPECT_EQ(one.chunk_revolutions, many.chunk_revolutions);
  EXPECT_EQ(one.warnings, many.warnings);
  EXPECT_EQ(one.spectra.segments, many.spectra.segments);
  EXPECT_EQ(std::memcmp(&one.mean_crank_speed_rad_s, &many.mean_crank_speed_rad_s, sizeof(double)), 0);
  expect_identical(one.crank_speed_rad_s, many.crank_speed_rad_s, "crank speed");
  for (const auto link : {&RecordingAnalysis::coupler, &RecordingAnalysis::rocker}) {
    ASSERT_EQ((one.*link).has_value(), (many.*link).has_value());
    if (!(one.*link)) continue;
    const LinkResult& a = *(one.*link);
    const LinkResult& b = *(many.*link);
    expect_identical(a.alpha_rad_s2, b.alpha_rad_s2, "alpha average");
    expect_identical(a.omega_rad_s, b.omega_rad_s, "omega average");
    expect_identical(a.alpha_grid, b.alpha_grid, "alpha per revolution");
    expect_identical(a.omega_grid, b.omega_grid, "omega per revolution");
    expect_identical(a.alpha_amplitude, b.alpha_amplitude, "alpha spectrum");
    ASSERT_EQ(a.normal.has_value(), b.normal.has_value());
    if (a.normal) {
      expect_identical(a.normal->omega_sq_rad2_s2, b.normal->omega_sq_rad2_s2, "normal omega^2");
      expect_identical(a.normal->omega_sq_integrated_rad2_s2, b.normal->omega_sq_integrated_rad2_s2,
                       "integrated omega^2");
    }
  }
}

struct Case {
  const char* name;
  AnalyzeOptions options;
};

TEST(ChunkThreads, ResultIsBitForBitTheOneOfOneThread) {
  VirtualSetup v;
  testing::housing_sensors(v);  // a normal channel too
  testing::noisy_lab(v);
  v.spec.revolutions = 60;
  v.spec.pulse.missing = {31, 32, 33, 34, 35, 36, 37};  // two segments
  const VirtualRigResult written = v.write("threads.wav", false);

  std::vector<Case> cases;
  AnalyzeOptions chain;
  chain.chunk_revolutions = 3;
  chain.guard_revolutions = 1;
  chain.spectrum_segment = 2048;  // spectrum segments inside chunks and across their ends
  cases.push_back({"this chain", chain});
  AnalyzeOptions thesis = AnalyzeOptions::thesis_method();
  thesis.chunk_revolutions = 4;
  cases.push_back({"thesis method", thesis});
  AnalyzeOptions automatic;  // the default chunks and spectrum segment
  cases.push_back({"default chunks", automatic});

  for (Case& c : cases) {
    SCOPED_TRACE(c.name);
    c.options.progress = false;
    c.options.keep_revolutions = true;
    c.options.threads = 1;
    Recorder seen_one, seen_many;
    const RecordingAnalysis one = analyze_recording(written.recording, {}, c.options, &seen_one);
    c.options.threads = 3;
    const RecordingAnalysis many = analyze_recording(written.recording, {}, c.options, &seen_many);
    ASSERT_EQ(one.acquisition.pulses.segments.size(), 2u);
    ASSERT_GT(one.revolutions, 40u);
    if (c.options.chunk_revolutions > 0) EXPECT_EQ(one.chunk_revolutions, c.options.chunk_revolutions);
    EXPECT_GT(one.spectra.segments, 0u);
    expect_same_analysis(one, many);
    EXPECT_EQ(seen_one.numbers, seen_many.numbers);
    EXPECT_EQ(seen_one.averaged, seen_many.averaged);
    expect_identical(seen_one.values, seen_many.values, "observed revolutions");
  }
}

// With every revolution a guard revolution the analysis fails with the same
// error on several threads as on one (the chunks in flight are waited for).
TEST(ChunkThreads, NoRevolutionLeftFailsAsWithOneThread) {
  VirtualSetup v;
  testing::housing_sensors(v);
  v.spec.revolutions = 12;
  const VirtualRigResult written = v.write("threads_error.wav", false);
  AnalyzeOptions o;
  o.progress = false;
  o.chunk_revolutions = 2;
  o.guard_revolutions = 50;
  for (unsigned threads : {1u, 3u}) {
    o.threads = threads;
    try {
      analyze_recording(written.recording, {}, o);
      ADD_FAILURE() << threads << " threads: no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("no revolution left to average"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace fourbar
