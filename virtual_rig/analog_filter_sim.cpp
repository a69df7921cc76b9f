#include "virtual_rig/analog_filter_sim.hpp"

#include <algorithm>
#include <cmath>

#include "common/units.hpp"

namespace fourbar {

// State per section: first order (y, unused), second order (y, y').
//   first:  y' = ω0·(u − y)
//   second: y'' = ω0²·(u − y) − (ω0/Q)·y'
// with u the previous section's y (the input for the first).

AnalogFilterSim::AnalogFilterSim(std::vector<AnalogSection> sections, double fs) : sections_(std::move(sections)) {
  double w_max = 0;
  for (const AnalogSection& s : sections_) {
    w_.push_back(units::kTwoPi * s.f0_hz);
    w_max = std::max(w_max, w_.back() * (s.order == 2 ? std::max(1.0, 1.0 / s.q) : 1.0));
  }
  substeps_ = std::max(1, static_cast<int>(std::ceil(w_max / (0.25 * fs))));
  h_ = 1.0 / (fs * substeps_);
  const std::size_t n = 2 * sections_.size();
  state_.assign(n, 0.0), k1_ = k2_ = k3_ = k4_ = tmp_ = state_;
}

void AnalogFilterSim::prime(double x) {
  for (std::size_t i = 0; i < sections_.size(); ++i) state_[2 * i] = x, state_[2 * i + 1] = 0;
  x_prev_ = x;
}

void AnalogFilterSim::derivative(const std::vector<double>& y, double x, std::vector<double>& dy) const {
  double u = x;
  for (std::size_t i = 0; i < sections_.size(); ++i) {
    const double w = w_[i], yi = y[2 * i], vi = y[2 * i + 1];
    if (sections_[i].order == 1) {
      dy[2 * i] = w * (u - yi), dy[2 * i + 1] = 0;
    } else {
      dy[2 * i] = vi;
      dy[2 * i + 1] = w * w * (u - yi) - w / sections_[i].q * vi;
    }
    u = yi;
  }
}

double AnalogFilterSim::step(double t0_s, const std::function<double(double)>& x_at) {
  if (sections_.empty()) return x_prev_ = x_at(t0_s + h_ * substeps_);
  const std::size_t n = state_.size();
  double x0 = x_prev_;
  for (int s = 0; s < substeps_; ++s) {
    const double ts = t0_s + h_ * s;
    const double xm = x_at(ts + 0.5 * h_), x1 = x_at(ts + h_);
    derivative(state_, x0, k1_);
    for (std::size_t i = 0; i < n; ++i) tmp_[i] = state_[i] + 0.5 * h_ * k1_[i];
    derivative(tmp_, xm, k2_);
    for (std::size_t i = 0; i < n; ++i) tmp_[i] = state_[i] + 0.5 * h_ * k2_[i];
    derivative(tmp_, xm, k3_);
    for (std::size_t i = 0; i < n; ++i) tmp_[i] = state_[i] + h_ * k3_[i];
    derivative(tmp_, x1, k4_);
    for (std::size_t i = 0; i < n; ++i) state_[i] += h_ / 6 * (k1_[i] + 2 * k2_[i] + 2 * k3_[i] + k4_[i]);
    x0 = x1;
  }
  x_prev_ = x0;
  return state_[n - 2];
}

}  // namespace fourbar
