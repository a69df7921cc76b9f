#pragma once
// A cascade of analog low-pass sections (acquire/analog_response.hpp: an
// accelerometer's mounted resonance, a Butterworth anti-alias filter) run on
// a continuous input: the sections' ODEs integrated by RK4, the input
// evaluated at each stage's time (not interpolated between samples, which
// would lose (πf/fs)²/3 of the gain: 4.5 % at 0.12·fs), in sub-steps short
// enough for the highest corner (ω0·h ≤ 0.25), so the simulated response
// matches H(jω) in band and the sections above the Nyquist frequency act.

#include <functional>
#include <vector>

#include "acquire/analog_response.hpp"

namespace fourbar {

class AnalogFilterSim {
 public:
  AnalogFilterSim(std::vector<AnalogSection> sections, double sample_rate_hz);
  bool empty() const { return sections_.empty(); }
  /// Sets the state to the steady response to a constant input x.
  void prime(double x);
  /// Advances from t0_s (the previous call's end; the input there is the
  /// last one seen) to t1_s = t0_s + 1/fs, the input x_at(t) evaluated at
  /// the stages inside; returns the output at t1_s.
  double step(double t0_s, const std::function<double(double)>& x_at);

 private:
  void derivative(const std::vector<double>& y, double x, std::vector<double>& dy) const;

  std::vector<AnalogSection> sections_;
  std::vector<double> w_;  // 2π·f0 per section
  std::vector<double> state_, k1_, k2_, k3_, k4_, tmp_;
  double h_ = 0;
  int substeps_ = 1;
  double x_prev_ = 0;
};

}  // namespace fourbar
