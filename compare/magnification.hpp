#pragma once
// The magnification (conversion) factor of thesis sec. 8.1, both ways.
//
// The thesis compared simulation and experiment indirectly, each against the
// nominal (clearance-free) response at its own instants: with
// d_sim = sim − nominal and d_meas = measured − nominal,
//   time domain:  a = RMS(d_sim) / RMS(d_meas)
// (the text says "ratio of the two average deviations"; its "experimental and
// nominal" is a slip for experimental and simulated, as its value 30 for a
// simulation 30× too violent shows), and the modified analytical response is
//   modified = nominal + d_sim / a                       (thesis Fig. 8.4).
// The spectral method, which the thesis preferred but could not use with its
// rectangular window (eq. 8.1.2: A_i = a·C_i per frequency), is done here per
// crank order k: the amplitude of order k of d_sim and of d_meas over whole
// revolutions in the crank-angle domain, Hann-windowed over all R revolutions
// (order k sits exactly on bin k·R; the window keeps the leakage of
// non-synchronous content — noise, chaotic revolutions — out of the order
// lines), a_k = A_sim,k / A_meas,k. An order counts as significant when the
// measured amplitude stands 3× above the measurement's own floor (median of
// the bins between order lines near it). The spectral factor over the band is
// a_spec = √(Σ A_sim,k² / Σ A_meas,k²) over the significant orders — by
// Parseval the same as the time-domain factor restricted to those orders.

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fourbar {

struct OrderRatio {
  int order = 0;
  double measured_amplitude = 0;   ///< of d_meas, unit of the quantity
  double simulated_amplitude = 0;  ///< of d_sim
  double measured_floor = 0;       ///< noise floor near this order (0 when unknown)
  bool significant = false;
  std::optional<double> factor;    ///< A_sim / A_meas (absent when A_meas = 0)
};

struct Magnification {
  double measured_deviation_rms = 0;   ///< RMS(measured − nominal) on the averaged grid
  double simulated_deviation_rms = 0;  ///< RMS(simulated − nominal)
  std::optional<double> time_domain;   ///< a (absent when the measurement equals the nominal)
  std::vector<OrderRatio> orders;      ///< orders 1 … max_order
  std::optional<double> spectral;      ///< a_spec over the significant orders
  std::string spectral_method;         ///< what the order amplitudes were computed from
  std::vector<double> modified;        ///< nominal + d_sim / a (empty when a is absent)
};

struct MagnificationInput {
  std::span<const double> nominal;             ///< N
  std::span<const double> measured_mean;       ///< N
  std::span<const double> simulated_mean;      ///< N
  std::span<const double> measured_revolutions;   ///< R_m × N (may be empty: then the mean is used)
  std::span<const double> simulated_revolutions;  ///< R_s × N (may be empty)
};

Magnification magnification_factor(const MagnificationInput& in, int max_order = 50);

/// Amplitude of crank orders 0 … max_order of `revolutions` (R × N, R ≥ 1):
/// Hann window over all R·N points when R ≥ 2, else the one revolution
/// unwindowed (exactly periodic). `floor` (optional) gets the median
/// amplitude of the non-order bins within ±2 orders (0 when R < 6).
std::vector<double> order_amplitudes(std::span<const double> revolutions, std::size_t grid_points_per_rev, int max_order,
                                     std::vector<double>* floor = nullptr);

}  // namespace fourbar
