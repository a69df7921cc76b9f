#pragma once
// Turns of a link's α made for the model-family checks' tests
// (tests/compare/test_model_family.cpp, test_link_vibration.cpp): a smooth
// nominal response, impact-like single-point impulses (3 a turn at random
// angles), white noise, and optionally a damped ringing after each impulse —
// at one frequency (a link mode at steady contact) or at a frequency drawn
// per impulse from a range (modes that shift as the bearing opens and
// closes: a broad plateau).

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "common/units.hpp"

namespace fourbar::test {

using units::kPi;

inline constexpr std::size_t kN = 720;
inline constexpr double kCrankHz = 250.0 / 60.0;
inline constexpr double kGridHz = kN * kCrankHz;  // 3000 samples per second on the grid

inline std::vector<double> nominal() {
  std::vector<double> x(kN);
  for (std::size_t i = 0; i < kN; ++i)
    x[i] = 100 * std::sin(2 * kPi * static_cast<double>(i) / kN) + 30 * std::cos(4 * kPi * static_cast<double>(i) / kN);
  return x;
}

/// turns × N: nominal + `impact` × impulses + `noise` × white noise + a ring
/// of `ring` × the impulse's amplitude at ring_hz (+ a uniform draw from
/// [0, ring_spread_hz) per impulse), damping ratio zeta.
inline std::vector<double> turns(std::size_t count, double impact, double noise, double ring, std::uint64_t seed,
                                 double ring_hz = 600, double zeta = 0.02, double ring_spread_hz = 0) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> at(0, kN - 1);
  std::normal_distribution<double> normal(0, 1);
  std::uniform_real_distribution<double> spread(0, 1);
  const std::vector<double> nom = nominal();
  std::vector<double> x(count * kN);
  for (std::size_t r = 0; r < count; ++r)
    for (std::size_t i = 0; i < kN; ++i) x[r * kN + i] = nom[i] + noise * normal(rng);
  for (std::size_t r = 0; r < count; ++r)
    for (int k = 0; k < 3; ++k) {
      const std::size_t i0 = r * kN + at(rng);
      const double a = impact * (0.5 + std::abs(normal(rng)));
      const double hz = ring_hz + (ring_spread_hz > 0 ? ring_spread_hz * spread(rng) : 0.0);
      const double w = 2 * kPi * hz, sigma = zeta * w;
      x[i0] += a;
      if (ring > 0)
        for (std::size_t j = 1; i0 + j < x.size() && j < kN; ++j) {
          const double t = static_cast<double>(j) / kGridHz;
          x[i0 + j] += ring * a * std::exp(-sigma * t) * std::sin(w * t);
        }
    }
  return x;
}

}  // namespace fourbar::test
