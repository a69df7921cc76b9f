#pragma once
// Synchronous averaging in the crank-angle domain: revolutions on a common
// grid of N angles (angle_resampler.hpp or acquire's resampler), their mean
// per angle and the spread (sample standard deviation, n − 1) per angle.
// Noise and anything not locked to the crank (mains hum, other machines)
// drop as 1/√n; the crank-locked motion stays.

#include <span>
#include <vector>

namespace fourbar {

struct AngleAverage {
  std::size_t revolutions = 0;
  std::vector<double> mean;  ///< per grid angle
  std::vector<double> std;   ///< per grid angle; 0 for a single revolution
};

/// Streams revolutions in (Welford's update: stable, bounded memory).
class SynchronousAverager {
 public:
  explicit SynchronousAverager(std::size_t grid_points_per_rev);
  /// One revolution of N values.
  void add(std::span<const double> revolution);
  std::size_t revolutions() const { return count_; }
  AngleAverage result() const;

 private:
  std::size_t n_, count_ = 0;
  std::vector<double> mean_, m2_;
};

/// Average of `rows` revolutions stored row-major (rows × N).
AngleAverage synchronous_average(std::span<const double> revolutions, std::size_t grid_points_per_rev);

}  // namespace fourbar
