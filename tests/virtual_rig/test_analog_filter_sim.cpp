// The time-domain simulation of the analog sections (RK4 on their ODEs)
// against their closed-form response H(jω) (acquire/analog_response.hpp):
// a sinusoid through the simulated cascade, after its transient, has the
// gain |H| and phase arg H; and the Butterworth sections have |H(fc)| = 1/√2.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "acquire/analog_response.hpp"
#include "virtual_rig/analog_filter_sim.hpp"

namespace fourbar {
namespace {

// Amplitude and phase of the simulated output at f, by projection on cos/sin
// over whole periods after 2 s of run-in.
std::complex<double> simulated_response(const std::vector<AnalogSection>& sections, double fs, double f) {
  AnalogFilterSim sim(sections, fs);
  sim.prime(0);
  const double w = 2 * std::numbers::pi * f;
  const auto n_run = static_cast<long>(2.0 * fs);
  const auto periods = static_cast<long>(std::floor(1.0 * f));
  const auto n_meas = static_cast<long>(std::llround(static_cast<double>(periods) / f * fs));
  std::complex<double> acc = 0;
  for (long i = 1; i < n_run + n_meas; ++i) {
    const double t = static_cast<double>(i) / fs;
    const double y = sim.step(t - 1.0 / fs, [w](double tau) { return std::sin(w * tau); });
    if (i >= n_run) acc += y * std::exp(std::complex<double>(0, -w * t));
  }
  // y = |H| sin(ωt + φ) → projection on e^{−jωt}: (|H|/2j) e^{jφ}·n.
  return acc * std::complex<double>(0, 2) / static_cast<double>(n_meas);
}

TEST(AnalogFilterSim, MatchesTheClosedFormResponse) {
  const double fs = 12800;
  const std::vector<std::vector<AnalogSection>> cases{
      butterworth_sections(6, 2000), butterworth_sections(3, 1000), {{2, 1000, 10}}, {{2, 20000, 30}}};
  for (const auto& sections : cases)
    for (double f : {50.0, 200.0, 700.0, 1500.0}) {
      const std::complex<double> sim = simulated_response(sections, fs, f), h = analog_response(sections, f);
      // RK4 at ω0·h ≤ 0.25: largest measured 1.4e-4 (1 kHz, Q 10, at 1.5 kHz).
      EXPECT_NEAR(std::abs(sim - h), 0.0, 3e-4 * std::max(1.0, std::abs(h))) << sections.size() << " sections, " << f << " Hz";
    }
}

TEST(AnalogFilterSim, ButterworthSectionsHaveTheHalfPowerCutoff) {
  for (int order = 1; order <= 8; ++order) {
    EXPECT_NEAR(std::abs(analog_response(butterworth_sections(order, 3000), 3000)), std::sqrt(0.5), 1e-12) << order;
    // |H|² = 1/(1 + (f/fc)^(2n)) at any f.
    for (double f : {300.0, 2000.0, 7000.0})
      EXPECT_NEAR(std::abs(analog_response(butterworth_sections(order, 3000), f)),
                  1.0 / std::sqrt(1.0 + std::pow(f / 3000, 2 * order)), 1e-12)
          << order << ", " << f << " Hz";
  }
}

}  // namespace
}  // namespace fourbar
