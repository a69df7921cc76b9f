#pragma once
// A cascade of analog low-pass sections (acquire/analog_response.hpp: an
// accelerometer's mounted resonance, a Butterworth anti-alias filter) run on
// a sampled input: the sections' ODEs integrated by RK4 with the input
// linear between samples, in sub-steps short enough for the highest corner
// (ω0·h ≤ 0.5), so the simulated response matches H(jω) in band and the
// sections above the Nyquist frequency still act.

#include <vector>

#include "acquire/analog_response.hpp"

namespace fourbar {

class AnalogFilterSim {
 public:
  AnalogFilterSim(std::vector<AnalogSection> sections, double sample_rate_hz);
  bool empty() const { return sections_.empty(); }
  /// Sets the state to the steady response to a constant input x.
  void prime(double x);
  /// Advances one sample with the new input; returns the output.
  double operator()(double x);

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
