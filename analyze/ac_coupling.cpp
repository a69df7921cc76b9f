#include "analyze/ac_coupling.hpp"

#include <cassert>
#include <cmath>
#include <numeric>
#include <sstream>

#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

void check(double sample_rate_hz, double corner_hz) {
  if (!(sample_rate_hz > 0) || !std::isfinite(sample_rate_hz)) {
    std::ostringstream os;
    os << "sample rate " << sample_rate_hz << " Hz must be a positive number";
    throw InputError(os.str());
  }
  if (!(corner_hz >= 0) || !std::isfinite(corner_hz) || corner_hz >= 0.5 * sample_rate_hz) {
    std::ostringstream os;
    os << "sensor high-pass corner " << corner_hz << " Hz must be >= 0 and below the Nyquist frequency "
       << 0.5 * sample_rate_hz << " Hz";
    throw InputError(os.str());
  }
}

// e^{−a} and (1 − e^{−a})/a for a = ωc/fs, accurate for tiny a.
struct Step {
  double decay, gain;
};
Step step_of(double sample_rate_hz, double corner_hz) {
  const double a = units::kTwoPi * corner_hz / sample_rate_hz;
  if (a == 0) return {1.0, 1.0};
  return {std::exp(-a), -std::expm1(-a) / a};
}

}  // namespace

void apply_sensor_high_pass(std::span<const double> input, double sample_rate_hz, double corner_hz,
                            double initial_output, std::span<double> output) {
  check(sample_rate_hz, corner_hz);
  assert(output.size() == input.size());
  if (input.empty()) return;
  const Step s = step_of(sample_rate_hz, corner_hz);
  double x_prev = input[0], y = initial_output;
  output[0] = y;
  for (std::size_t k = 1; k < input.size(); ++k) {
    const double x = input[k];
    y = s.decay * y + (x - x_prev) * s.gain;
    x_prev = x;
    output[k] = y;
  }
}

void undo_sensor_high_pass(std::span<const double> sensed, double sample_rate_hz, double corner_hz,
                           double restored_mean, std::span<double> restored) {
  check(sample_rate_hz, corner_hz);
  assert(restored.size() == sensed.size());
  if (sensed.empty()) return;
  const Step s = step_of(sample_rate_hz, corner_hz);
  const double inv_gain = 1.0 / s.gain;
  // Running inverse from x[0] = 0, then the constant from the requested mean.
  double y_prev = sensed[0], x = 0;
  restored[0] = 0;
  for (std::size_t k = 1; k < sensed.size(); ++k) {
    const double y = sensed[k];
    x += (y - s.decay * y_prev) * inv_gain;
    y_prev = y;
    restored[k] = x;
  }
  const double shift = restored_mean - std::accumulate(restored.begin(), restored.end(), 0.0) / restored.size();
  for (double& v : restored) v += shift;
}

}  // namespace fourbar
