#pragma once
// How close two responses on the same crank-angle grid are (thesis ch. 8
// compared by eye): RMS difference, correlation, peak ratio, and where the
// largest deviations from the nominal response fall (the impact bursts).

#include <span>
#include <vector>

#include "common/statistics.hpp"  // rms

namespace fourbar {

/// Root mean square of a − b (a, b of equal length).
double rms_difference(std::span<const double> a, std::span<const double> b);
/// Pearson correlation of a and b; 0 when either is constant.
double correlation(std::span<const double> a, std::span<const double> b);
/// max|a| / max|b|; 0 when b is identically 0.
double peak_ratio(std::span<const double> a, std::span<const double> b);

/// The grid indices of the `count` largest |x| (x periodic over the grid),
/// each at least `min_separation` points (circularly) from the others,
/// largest first.
std::vector<std::size_t> largest_peaks(std::span<const double> x, std::size_t count, std::size_t min_separation);

/// The circular distance between two grid indices on an N-point revolution.
std::size_t circular_distance(std::size_t a, std::size_t b, std::size_t n);

}  // namespace fourbar
