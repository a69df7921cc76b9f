// Automatic thresholds on real pickups: ringing with 50 % overshoot, a
// baseline drifting by half the swing, 20 dB noise, and all three at once,
// read with no thresholds in the manifest. The signal is the analytic tacho
// (tacho_signal.hpp) at 25.6 kHz through a second-order pickup response; the
// thresholds come from the channel's levels as acquire's scan pass collects
// them (global histogram and local windows), the edges from the Schmitt
// trigger on the signal minus the local mid-level where the thresholds follow it.

#include <gtest/gtest.h>

#include <algorithm>

#include "acquire/edge_detector.hpp"
#include "acquire/pulse_thresholds.hpp"
#include "acquire/pulse_train.hpp"
#include "tacho_signal.hpp"
#include "pulse_manifest.hpp"

namespace fourbar {
namespace {

using testing::pulse_manifest;
using testing::PickupFaults;

constexpr double kFs = 25600;

struct Read {
  ThresholdChoice choice;
  std::vector<double> edges;
};

Read read_automatic(const std::vector<double>& x, const Manifest& m = pulse_manifest(0)) {
  LevelHistogram global;
  LocalLevels local(kFs);
  for (double v : x) global.add(v), local.add(v);
  local.finish();
  Read r{pulse_thresholds(global, ChannelStats{}, m, "synthetic.wav", &local), {}};
  std::vector<double> s = x;
  if (r.choice.thresholds.follows_baseline)
    for (std::size_t i = 0; i < s.size(); ++i) s[i] -= local.mid_at(i);
  EdgeDetector d(r.choice.thresholds, PulsePolarity::rising, kFs, 0, 0);
  d.push(s.data(), s.size(), 1);
  r.edges = d.edges();
  return r;
}

/// 8 s at 350 rpm, a 36° mark.
testing::TachoSignal clean_tacho() {
  return testing::tacho_signal({{0, 8}, {350.0 / 60, 350.0 / 60}}, kFs, 0.1, 0.3);
}

// Each fault alone and all together: every pulse found once, timed within
// the delay the pickup's response puts on the mid-level crossing.
TEST(PulseLevels, RingingDriftAndNoiseReadWithAutomaticThresholds) {
  const auto tacho = clean_tacho();
  struct Case {
    const char* name;
    PickupFaults faults;
    double timing_tolerance_s;
  };
  PickupFaults ringing, drift, noisy, all;
  ringing.overshoot = 0.5;
  drift.drift_of_swing = 0.5;
  noisy.snr_db = 20;
  all.overshoot = 0.5, all.drift_of_swing = 0.5, all.snr_db = 20;
  // The second-order response reaches mid-level about 0.1 ms late at 2 kHz;
  // 20 dB noise on a 4-sample ramp moves the crossing by a fraction of a sample.
  for (const Case& c : {Case{"ringing 50 %", ringing, 2e-4}, Case{"drift of half the swing", drift, 1e-4},
                        Case{"20 dB noise", noisy, 2e-4}, Case{"all three", all, 3e-4}}) {
    SCOPED_TRACE(c.name);
    const auto x = testing::with_faults(tacho.volts, kFs, c.faults);
    const Read r = read_automatic(x);
    EXPECT_TRUE(r.choice.thresholds.automatic);
    ASSERT_EQ(r.edges.size(), tacho.pulse_times.size());
    for (std::size_t k = 0; k < r.edges.size(); ++k)
      EXPECT_NEAR(r.edges[k], tacho.pulse_times[k], c.timing_tolerance_s) << k;
    const PulseTrain p = clean_pulse_train(r.edges);
    EXPECT_TRUE(p.removed_s.empty());
    EXPECT_EQ(p.revolutions(), tacho.pulse_times.size() - 1);
  }
}

// The drifting baseline switches the thresholds to the local levels, and
// says so; a clean signal keeps the global levels (outputs unchanged).
TEST(PulseLevels, ThresholdsFollowTheBaselineOnlyWhenItWanders) {
  const auto tacho = clean_tacho();
  PickupFaults drift, none;
  drift.drift_of_swing = 0.5;
  const Read d = read_automatic(testing::with_faults(tacho.volts, kFs, drift));
  EXPECT_TRUE(d.choice.thresholds.follows_baseline);
  EXPECT_TRUE(std::any_of(d.choice.warnings.begin(), d.choice.warnings.end(),
                          [](const std::string& w) { return w.find("baseline wanders") != std::string::npos; }));
  const Read c = read_automatic(testing::with_faults(tacho.volts, kFs, none));
  EXPECT_FALSE(c.choice.thresholds.follows_baseline);
  EXPECT_TRUE(c.choice.warnings.empty());
}

// Manual thresholds still win: set where the drift carries the baseline
// through them, they are used as given (and count the wrong edges the user
// asked for), never replaced by the automatic ones.
TEST(PulseLevels, ManifestThresholdsWin) {
  const auto tacho = clean_tacho();
  PickupFaults drift;
  drift.drift_of_swing = 0.5;
  Manifest m = pulse_manifest(0);
  m.channels[0].threshold_low_V = 2.0;
  m.channels[0].threshold_high_V = 3.0;
  const Read r = read_automatic(testing::with_faults(tacho.volts, kFs, drift), m);
  EXPECT_FALSE(r.choice.thresholds.automatic);
  EXPECT_FALSE(r.choice.thresholds.follows_baseline);
  EXPECT_EQ(r.choice.thresholds.low, 2.0);
  EXPECT_EQ(r.choice.thresholds.high, 3.0);
}

}  // namespace
}  // namespace fourbar
