// The thresholds acquire sets on the pulse channel and its one rule for a
// noisy channel: the "hysteresis widened" warning is given exactly when
// automatic_thresholds widened the band for the noise. Each case is checked
// against the band itself (widened: half of it wider than
// kHysteresisHalfBandOfSwing of the swing), not against the flag alone.

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "acquire/acquisition.hpp"
#include "acquire/pulse_thresholds.hpp"
#include "virtual_recording.hpp"
#include "pulse_manifest.hpp"

namespace fourbar {
namespace {

using testing::pulse_manifest;
constexpr double kSwing_V = 5.0;

/// The scan pass's histogram of a pulse signal: 0 V idle, 5 V pulses for 6 %
/// of the time, plus white Gaussian noise of `noise_of_swing` × the swing.
LevelHistogram noisy_pulses(double noise_of_swing) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0, noise_of_swing * kSwing_V);
  LevelHistogram h;
  for (int i = 0; i < 50000; ++i) h.add((i % 100 < 6 ? kSwing_V : 0.0) + noise(rng));
  return h;
}

bool warns_widened(const std::vector<std::string>& warnings) {
  return std::any_of(warnings.begin(), warnings.end(),
                     [](const std::string& w) { return w.find("hysteresis widened") != std::string::npos; });
}

/// From the band as set, independent of the flag (1e-9: rounding of mid ± half band).
bool band_wider_than_clean(const PulseThresholds& t) {
  return 0.5 * (t.high - t.low) > kHysteresisHalfBandOfSwing * (t.top_level - t.bottom_level) * (1 + 1e-9);
}

ThresholdChoice thresholds_for(const LevelHistogram& h, const Manifest& m = pulse_manifest(3)) {
  return pulse_thresholds(h, ChannelStats{}, m, "synthetic.wav");
}

// From a clean signal to one too noisy for the 15 % band: the warning comes
// with the widening and only with it.
TEST(PulseThresholds, WarnsExactlyWhenTheHysteresisIsWidened) {
  for (double noise_of_swing : {0.005, 0.02, 0.03, 0.05, 0.06, 0.09, 0.12}) {
    const ThresholdChoice c = thresholds_for(noisy_pulses(noise_of_swing));
    const bool widened = band_wider_than_clean(c.thresholds);
    EXPECT_EQ(c.thresholds.hysteresis_widened, widened) << noise_of_swing;
    EXPECT_EQ(warns_widened(c.warnings), widened) << noise_of_swing;
    // 4σ against 15 % of the swing: the band widens above 3.75 % noise.
    EXPECT_EQ(widened, noise_of_swing > 0.0375) << noise_of_swing;
  }
}

// Noise of 6 % of the swing lies between the two limits that used to disagree
// (band widened above 3.75 %, warning only above 10 %): the band is widened,
// so the warning is given.
TEST(PulseThresholds, NoiseBetweenTheOldLimitsIsWidenedAndWarned) {
  const ThresholdChoice c = thresholds_for(noisy_pulses(0.06));
  const PulseThresholds& t = c.thresholds;
  const double swing_V = t.top_level - t.bottom_level;
  EXPECT_GT(t.noise, kHysteresisHalfBandOfSwing / kHysteresisNoiseSigmas * swing_V);
  EXPECT_LT(t.noise, 0.1 * swing_V);
  EXPECT_TRUE(band_wider_than_clean(t));
  EXPECT_NEAR(0.5 * (t.high - t.low), kHysteresisNoiseSigmas * t.noise, 1e-9);
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("pulse channel 'crank_pulse' (index 3) is noisy"), std::string::npos) << c.warnings[0];
}

// The manifest's thresholds are used as given: nothing is widened, so even a
// very noisy channel gives no "hysteresis widened" warning.
TEST(PulseThresholds, ManifestThresholdsAreNeverWidened) {
  Manifest m = pulse_manifest(3);
  m.channels[0].threshold_low_V = 1.5;
  m.channels[0].threshold_high_V = 3.5;
  const ThresholdChoice c = thresholds_for(noisy_pulses(0.12), m);
  EXPECT_FALSE(c.thresholds.automatic);
  EXPECT_EQ(c.thresholds.low, 1.5);
  EXPECT_EQ(c.thresholds.high, 3.5);
  EXPECT_FALSE(c.thresholds.hysteresis_widened);
  EXPECT_FALSE(warns_widened(c.warnings));
}

// End to end: a recording whose tacho carries 6 % noise is acquired with a
// widened band, every pulse counted once, and the warning in the report.
TEST(PulseThresholds, AcquireReportsTheWideningItUsed) {
  testing::VirtualSetup v;
  v.spec.revolutions = 6;
  v.spec.pulse.noise_V = 0.3;  // 6 % of the 5 V swing
  const VirtualRigResult vr = v.write("noisy6.wav", false);
  OpenedRecording o = open_with_manifest(vr.recording, {});
  AcquireOptions options;
  options.progress = false;
  AcquisitionSink ignore;
  const AcquisitionReport rep = acquire(*o.reader, o.manifest, options, ignore);
  EXPECT_TRUE(band_wider_than_clean(rep.thresholds));
  EXPECT_TRUE(rep.thresholds.hysteresis_widened);
  EXPECT_TRUE(warns_widened(rep.warnings));
  EXPECT_EQ(rep.pulses.edges, vr.pulse_times_s.size());
}

}  // namespace
}  // namespace fourbar
