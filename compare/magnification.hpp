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
// Orders at mains hum are left out as well (mains_order.hpp): hum at
// h·f_mains that falls within kMainsOrderBins bins of order k (or within the
// order range the crank-speed spread sweeps it over) adds to A_meas,k what
// the clearance model cannot have, and pulls a_spec down. `orders_used`
// lists the orders a_spec was computed from.
// Orders 1 … K, where the nominal response lives (all but kNominalBandResidual
// of its energy), are left out too: there the measured deviation holds the
// nominal model's own errors at the measured crank motion (the crank speed
// changing from turn to turn, gravity on the sensor, its position), which no
// clearance model has. A clearance-free virtual-rig recording of the thesis
// rig at 250 rpm shows orders 1, 2, 3 at 130, 35 and 9 times the floor.
//
// The same orders give the synchronous clearance effect: the RMS of the
// measured deviation's order lines over the RMS of the floor between them
// (≈ 1.2 for noise alone; the clearance model's lines over the same floor
// say what the model expects to be seen).

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "compare/mains_order.hpp"

namespace fourbar {

struct OrderRatio {
  int order = 0;
  double measured_amplitude = 0;   ///< of d_meas, unit of the quantity
  double simulated_amplitude = 0;  ///< of d_sim
  double measured_floor = 0;       ///< noise floor near this order (0 when unknown)
  bool significant = false;       ///< measured amplitude 3× above its floor
  bool mains = false;             ///< at a mains-hum harmonic: left out of a_spec
  std::optional<double> factor;    ///< A_sim / A_meas (absent when A_meas = 0)
};

/// Share of the nominal response's energy allowed above its band (orders 1 … K).
inline constexpr double kNominalBandResidual = 1e-4;

struct Magnification {
  double measured_deviation_rms = 0;   ///< RMS(measured − nominal) on the averaged grid
  double simulated_deviation_rms = 0;  ///< RMS(simulated − nominal)
  std::optional<double> time_domain;   ///< a (absent when the measurement equals the nominal)
  std::vector<OrderRatio> orders;      ///< orders 1 … max_order
  std::optional<double> spectral;      ///< a_spec over the significant orders clear of mains hum
  std::vector<int> orders_used;        ///< the orders a_spec is computed from
  int nominal_band_orders = 0;         ///< K: orders 1 … K hold the nominal response (left out of a_spec)
  double floor_rms = 0;                ///< RMS of the floor between order lines over orders 1 … max_order (noise of the averaged curve)
  /// √(Σ A_meas,k²) / √(Σ floor_k²) over the orders above K clear of mains (absent when the floor is unknown).
  std::optional<double> effect_to_floor;
  std::optional<double> model_effect_to_floor;  ///< the same with the clearance model's lines
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

/// `hum`: the mains hum whose orders a_spec leaves out (default: none).
Magnification magnification_factor(const MagnificationInput& in, int max_order = 50, const MainsHum& hum = {});

/// Amplitude of crank orders 0 … max_order of `revolutions` (R × N, R ≥ 1):
/// Hann window over all R·N points when R ≥ 2, else the one revolution
/// unwindowed (exactly periodic). `floor` (optional) gets the median
/// amplitude of the non-order bins within ±2 orders (0 when R < 6).
/// K: the smallest order such that orders above it hold at most
/// kNominalBandResidual of the energy of `nominal` (one revolution, N points).
int nominal_band_orders(std::span<const double> nominal);

std::vector<double> order_amplitudes(std::span<const double> revolutions, std::size_t grid_points_per_rev, int max_order,
                                     std::vector<double>* floor = nullptr);

}  // namespace fourbar
