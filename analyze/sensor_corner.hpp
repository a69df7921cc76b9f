#pragma once
// The set-up check's estimate of an AC-coupled sensor's high-pass corner
// (manifest `ac_coupled`, `highpass_hz`) from one averaged revolution.
//
// The analysis undoes the sensor's first-order high-pass with the manifest's
// corner (ac_coupling.hpp), exactly. When the sensor's true corner c_t is
// another one (or it is DC-coupled: no high-pass), the reading it recovers is
// the true one times H_t/H_m per crank order, H_c(f) = g(1 − e^−iω)/(1 − d·e^−iω)
// the discrete filter at ω = 2πf/fs (H = 1 for DC): the lowest orders come out
// scaled and shifted in phase. Undoing that for a trial corner c and fitting
// the nominal template with one free scale, the corner that leaves the least
// misfit is the data's. A 5 Hz corner in the manifest on a 0.5 Hz piezo at
// 350 rpm (5.8 Hz) over-corrects the first order by 1.3× and 40°.

#include <complex>
#include <span>

namespace fourbar {

struct CornerFit {
  double corner_hz = 0;            ///< the data's corner (0: DC-coupled, no high-pass)
  double unexplained = 1;          ///< share of the reading the template leaves with it
  double unexplained_manifest = 1; ///< … with the manifest's corner
};

/// The high-pass corner that makes `reading` fit k·`templ` best. Both are
/// spectra over crank orders q = 1 … K (index q; index 0 unused), the
/// reading as the analysis recovered it with `manifest_corner_hz` (0: DC),
/// the template with the analysis filter's gain; `order_hz[q]` the order's
/// frequency. Candidates: DC, and corners from 0.01 Hz to 4× the first
/// order's frequency (log grid, then refined).
CornerFit fit_high_pass_corner(std::span<const std::complex<double>> reading,
                               std::span<const std::complex<double>> templ, std::span<const double> order_hz,
                               double manifest_corner_hz, double sample_rate_hz);

}  // namespace fourbar
