// Modal frequencies and damping ratios from virtual tap recordings of known
// truth (one mode, two close modes, two separated modes; SNR 20–40 dB, five
// noise seeds each): frequency within 0.5 %, damping ratio within 10 %, and
// the reported standard errors honest (the error within 5 of them). A record
// without a decay is refused.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analyze/tap_modes.hpp"
#include "common/error.hpp"
#include "tap_recording.hpp"

namespace fourbar {
namespace {

using testing::TapModeTruth;
using testing::virtual_tap;

void expect_identified(const std::vector<TapModeTruth>& truth, double snr_db) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto rec = virtual_tap(truth, snr_db, seed);
    const TapResult r = identify_tap_modes(rec.samples, rec.sample_rate_hz);
    ASSERT_EQ(r.modes.size(), truth.size()) << "seed " << seed << ", SNR " << snr_db;
    EXPECT_TRUE(r.later_strikes_s.empty()) << "a single tap taken for a bounce at " << r.later_strikes_s.front()
                                           << " s, seed " << seed << ", SNR " << snr_db;
    EXPECT_EQ(r.clipped_samples, 0u) << "seed " << seed << ", SNR " << snr_db;
    for (std::size_t k = 0; k < truth.size(); ++k) {
      const TapMode& m = r.modes[k];
      const double df = m.frequency_Hz / truth[k].frequency_Hz - 1, dz = m.damping_ratio / truth[k].damping_ratio - 1;
      SCOPED_TRACE("mode " + std::to_string(k + 1) + ", seed " + std::to_string(seed) + ", SNR " +
                   std::to_string(snr_db) + " dB: f " + std::to_string(m.frequency_Hz) + " ± " +
                   std::to_string(m.frequency_sigma_Hz) + ", zeta " + std::to_string(m.damping_ratio) + " ± " +
                   std::to_string(m.damping_sigma));
      EXPECT_LT(std::abs(df), 0.005);
      EXPECT_LT(std::abs(dz), 0.10);
      EXPECT_LT(std::abs(m.frequency_Hz - truth[k].frequency_Hz), 5 * m.frequency_sigma_Hz + 1e-9);
      EXPECT_LT(std::abs(m.damping_ratio - truth[k].damping_ratio), 5 * m.damping_sigma + 1e-12);
    }
  }
}

TEST(TapModes, OneModeAt20And40Db) {
  expect_identified({{614.0, 0.02, 1.0, 0.3}}, 20);
  expect_identified({{614.0, 0.005, 1.0, 1.2}}, 40);
}

TEST(TapModes, TwoCloseModes) {
  // 4 % apart, half-power bandwidths of 12 and 19 Hz: one hump to the eye.
  expect_identified({{600.0, 0.01, 1.0, 0.0}, {625.0, 0.015, 0.7, 2.0}}, 30);
  expect_identified({{600.0, 0.01, 1.0, 0.0}, {625.0, 0.015, 0.7, 2.0}}, 20);
}

TEST(TapModes, TheThesisCouplersFirstTwoModes) {
  expect_identified({{614.1, 0.02, 1.0, 0.5}, {2456.3, 0.015, 0.5, 1.0}}, 25);
}

void expect_lowest_two(const std::vector<TapModeTruth>& truth, double snr_db) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto rec = virtual_tap(truth, snr_db, seed);
    const TapResult r = identify_tap_modes(rec.samples, rec.sample_rate_hz, {2});
    ASSERT_EQ(r.modes.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
      const TapMode& m = r.modes[k];
      SCOPED_TRACE("mode " + std::to_string(k + 1) + ", seed " + std::to_string(seed) + ": f " +
                   std::to_string(m.frequency_Hz) + " ± " + std::to_string(m.frequency_sigma_Hz) + " (fit) ± " +
                   std::to_string(m.frequency_window_Hz) + " (later start), zeta " + std::to_string(m.damping_ratio) +
                   " ± " + std::to_string(m.damping_sigma) + " ± " + std::to_string(m.damping_window));
      EXPECT_LT(std::abs(m.frequency_Hz / truth[k].frequency_Hz - 1), 0.005);
      EXPECT_LT(std::abs(m.damping_ratio / truth[k].damping_ratio - 1), 0.10);
      EXPECT_LE(std::abs(m.frequency_Hz - truth[k].frequency_Hz), 3 * m.frequency_uncertainty_Hz());
      EXPECT_LE(std::abs(m.damping_ratio - truth[k].damping_ratio), 3 * m.damping_uncertainty());
    }
  }
}

// A hammer excites a link's higher modes strongly in acceleration (∝ ω²):
// here the third and fourth are 3x the first. --modes 2 reports the two
// lowest (the rig file's first two entries), not the two strongest (it gave
// 602 and 5422 Hz before: a rig file with the third mode as the second).
TEST(TapModes, ModesAskedAreTheLowestNotTheStrongest) {
  expect_lowest_two({{614.1, 0.02, 1.0, 0.5}, {2456.3, 0.015, 0.5, 1.0}, {5440.0, 0.03, 3.0, 0.2},
                     {9760.0, 0.054, 3.0, 1.0}},
                    60);
}

// Higher modes too damped to stand out in the spectrum still pull the fitted
// ones in the first milliseconds (a beam's fourth mode moved its third by 7
// of the fit's standard errors, tests/independent_rig/tap_beam.py). The
// uncertainty adds the change of a fit started 2 ms later and covers the truth.
TEST(TapModes, UncertaintyCoversAnUnseenHigherMode) {
  expect_lowest_two({{614.1, 0.02, 1.0, 0.5}, {2456.3, 0.015, 0.5, 1.0}, {7000.0, 0.08, 1.0, 0.2}}, 60);
}

// Mains hum under the tap fits as a component that does not decay; it is
// named as a steady tone and is not a mode (0.3 % hum under a beam's tap was
// reported as mode 1 at 50 Hz, in the default fit and with --modes 2).
TEST(TapModes, MainsHumIsASteadyToneNotAMode) {
  const std::vector<TapModeTruth> truth = {{614.1, 0.02, 1.0, 0.5}, {2456.3, 0.015, 0.5, 1.0}};
  for (const int asked : {0, 2})
    for (unsigned seed = 1; seed <= 3; ++seed) {
      auto rec = virtual_tap(truth, 40, seed);
      for (std::size_t i = 0; i < rec.samples.size(); ++i)
        rec.samples[i] += 0.02 * std::sin(2 * std::numbers::pi * 50.0 * static_cast<double>(i) / rec.sample_rate_hz + 0.3);
      const TapResult r = identify_tap_modes(rec.samples, rec.sample_rate_hz, {asked});
      SCOPED_TRACE("--modes " + std::to_string(asked) + ", seed " + std::to_string(seed));
      ASSERT_EQ(r.modes.size(), 2u);
      EXPECT_NEAR(r.modes[0].frequency_Hz / 614.1, 1.0, 0.005);
      EXPECT_NEAR(r.modes[1].frequency_Hz / 2456.3, 1.0, 0.005);
      ASSERT_EQ(r.steady_tones_Hz.size(), 1u);
      EXPECT_NEAR(r.steady_tones_Hz[0], 50.0, 0.5);
    }
}

// Hum strong enough to be fitted before a weaker, well-damped mode: the
// hum's decay rate goes to zero, its lower bound. The fit rejected every
// step that crossed the bound and raised its damping until no parameter
// moved: over these six cases (third mode 0.3 or 0.5 of the first, hum 0.06,
// 0.1 or 0.2, seeds 1–3) it failed five, with the third mode at the fit's
// starting ζ 0.0100 (truth 0.03), missing, or the second mode (2450 Hz)
// named a steady tone; first seen on tap_beam.py's beam with 3 % hum at
// 40 dB. A decay rate at its bound is now held there and the step solved
// for the rest.
TEST(TapModes, HumAtItsBoundDoesNotFreezeTheOtherModes) {
  for (const double third : {0.3, 0.5})
    for (const double hum : {0.06, 0.1, 0.2}) {
      const std::vector<TapModeTruth> truth = {
          {614.1, 0.02, 1.0, 0.5}, {2456.3, 0.015, 0.5, 1.0}, {5441.0, 0.03, third, 2.0}};
      for (unsigned seed = 1; seed <= 3; ++seed) {
        auto rec = virtual_tap(truth, 40, seed);
        for (std::size_t i = 0; i < rec.samples.size(); ++i)
          rec.samples[i] +=
              hum * std::sin(2 * std::numbers::pi * 50.0 * static_cast<double>(i) / rec.sample_rate_hz + 0.3);
        const TapResult r = identify_tap_modes(rec.samples, rec.sample_rate_hz);
        SCOPED_TRACE("third mode " + std::to_string(third) + ", hum " + std::to_string(hum) + ", seed " +
                     std::to_string(seed));
        ASSERT_EQ(r.modes.size(), 3u);
        ASSERT_EQ(r.steady_tones_Hz.size(), 1u);
        EXPECT_NEAR(r.steady_tones_Hz[0], 50.0, 0.5);
        for (std::size_t k = 0; k < 3; ++k) {
          const TapMode& m = r.modes[k];
          SCOPED_TRACE("mode " + std::to_string(k + 1) + ": f " + std::to_string(m.frequency_Hz) + ", zeta " +
                       std::to_string(m.damping_ratio) + " ± " + std::to_string(m.damping_uncertainty()));
          EXPECT_LT(std::abs(m.frequency_Hz / truth[k].frequency_Hz - 1), 0.005);
          EXPECT_LT(std::abs(m.damping_ratio / truth[k].damping_ratio - 1), 0.10);
          EXPECT_LE(std::abs(m.damping_ratio - truth[k].damping_ratio), 3 * m.damping_uncertainty());
        }
      }
    }
}

// A bouncing hammer strikes the link again a few ms after the tap; the
// record after the tap is then no free decay, and fitting it as one gave a
// spurious mode beside the first (tap_beam.py's beam, bounce 4 ms later at
// 0.3 of the force: "mode 2: 603.8 Hz, ζ 0.117" for 2451.7 Hz, 0.015). The
// strike is found, named, and the decay after it fitted.
TEST(TapModes, ABounceOfTheHammerIsFoundAndTheDecayAfterItFitted) {
  const std::vector<TapModeTruth> truth = {{614.1, 0.02, 1.0, 0.5}, {2456.3, 0.015, 0.5, 1.0}};
  for (const double delay_s : {0.004, 0.012})
    for (unsigned seed = 1; seed <= 3; ++seed) {
      auto rec = virtual_tap(truth, 30, seed);
      // The bounce: the same link struck again at 0.4 of the force.
      testing::add_strike(rec, {{614.1, 0.02, 0.4, 0.5}, {2456.3, 0.015, 0.2, 1.0}}, 0.1 + delay_s);
      const TapResult r = identify_tap_modes(rec.samples, rec.sample_rate_hz);
      SCOPED_TRACE("bounce " + std::to_string(1e3 * delay_s) + " ms after the tap, seed " + std::to_string(seed));
      ASSERT_EQ(r.later_strikes_s.size(), 1u);
      EXPECT_NEAR(r.later_strikes_s[0], 0.1 + delay_s, 5e-4);
      EXPECT_GT(r.decay_start_s, r.later_strikes_s[0]);
      ASSERT_EQ(r.modes.size(), 2u);
      for (std::size_t k = 0; k < 2; ++k) {
        const TapMode& m = r.modes[k];
        SCOPED_TRACE("mode " + std::to_string(k + 1) + ": f " + std::to_string(m.frequency_Hz) + ", zeta " +
                     std::to_string(m.damping_ratio));
        EXPECT_LT(std::abs(m.frequency_Hz / truth[k].frequency_Hz - 1), 0.005);
        EXPECT_LT(std::abs(m.damping_ratio / truth[k].damping_ratio - 1), 0.10);
      }
    }
}

// An overloaded recorder clips the tap's first cycles flat at its limits.
// Those samples were taken for bounces of the hammer, and a record clipped
// at 0.2 of the peak gave a second mode at 602 Hz (beam, tap_beam.py). The
// clip is named and the decay after it fitted; with too little left, the
// advice is to tap softer, not harder.
TEST(TapModes, AClippedTapIsNamedAndTheDecayAfterItFitted) {
  const std::vector<TapModeTruth> truth = {{614.1, 0.02, 1.0, 0.5}, {2456.3, 0.015, 0.5, 1.0}};
  for (const double limit : {0.8, 0.5})
    for (unsigned seed = 1; seed <= 3; ++seed) {
      auto rec = virtual_tap(truth, 40, seed);
      double peak = 0;
      for (double v : rec.samples) peak = std::max(peak, std::abs(v - 0.3));
      for (double& v : rec.samples) v = std::clamp(v, 0.3 - limit * peak, 0.3 + limit * peak);
      const TapResult r = identify_tap_modes(rec.samples, rec.sample_rate_hz);
      SCOPED_TRACE("limit " + std::to_string(limit) + " of the peak, seed " + std::to_string(seed));
      EXPECT_GE(r.clipped_samples, 3u);
      EXPECT_GT(r.decay_start_s, r.clipped_until_s);
      EXPECT_TRUE(r.later_strikes_s.empty());
      ASSERT_EQ(r.modes.size(), 2u);
      for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_LT(std::abs(r.modes[k].frequency_Hz / truth[k].frequency_Hz - 1), 0.005) << k;
        EXPECT_LT(std::abs(r.modes[k].damping_ratio / truth[k].damping_ratio - 1), 0.10) << k;
      }
    }
  // Clipped for most of its ringing (to 0.05 of the peak, 7 times the
  // noise), one mode left to fit of the two asked: the message says so.
  auto rec = virtual_tap({{614.1, 0.02, 1.0, 0.5}}, 40, 1, 25600, 0.25, 0.1);
  for (double& v : rec.samples) v = std::clamp(v, 0.3 - 0.05, 0.3 + 0.05);
  try {
    identify_tap_modes(rec.samples, rec.sample_rate_hz, {2});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("clipped"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("tap harder"), std::string::npos) << e.what();
  }
}

TEST(TapModes, ARecordWithoutADecayIsRefused) {
  auto rec = virtual_tap({{614.0, 0.02, 1.0, 0.0}}, 30, 1);
  // A steady tone (a shaker, mains hum): no decay.
  for (std::size_t i = 0; i < rec.samples.size(); ++i)
    rec.samples[i] = std::sin(2 * 3.14159 * 600 * static_cast<double>(i) / 25600.0);
  EXPECT_THROW(identify_tap_modes(rec.samples, rec.sample_rate_hz), InputError);
  // Noise only.
  std::vector<double> noise(25600);
  for (std::size_t i = 0; i < noise.size(); ++i) noise[i] = std::sin(1e3 * static_cast<double>(i)) * 1e-3;
  try {
    identify_tap_modes(noise, 25600);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no free decay"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fourbar
