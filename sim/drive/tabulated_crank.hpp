#pragma once
// A crank motion prescribed as a table of angles θ2(t_i) on a uniform time
// grid (e.g. the Siconos tutorial's controlled crank,
// shared/benchmarks/three-clearance-crank-motion.csv): the C² cubic
// B-spline through the angles (Boost.Math cardinal_cubic_b_spline) with the
// tabulated speeds as end slopes, so θ2, ω2 = θ2' and α2 = θ2'' are exact
// derivatives of one curve and α2 is continuous (the BDF integrator needs no
// restart at the knots). Unlike MeasuredSpeedCrank the motion may start at
// rest and reverse. Outside the table: the last state held at constant speed.

#include <filesystem>
#include <memory>
#include <vector>

#include "sim/drive/crank_motion.hpp"

namespace fourbar {

class TabulatedCrank final : public CrankMotion {
 public:
  /// Uniform times (at least 4 samples, spacing equal to 1e-9 relative),
  /// finite angles; speeds give the end slopes. InputError otherwise.
  TabulatedCrank(std::vector<double> times_s, std::vector<double> angles_rad, double start_speed_rad_s,
                 double end_speed_rad_s);
  ~TabulatedCrank() override;

  /// From a CSV file with the header `time_s,crank_rad,crank_rad_s`;
  /// InputError naming the file, line and column otherwise.
  static std::unique_ptr<TabulatedCrank> from_csv(const std::filesystem::path& file);

  CrankState at(double time_s) const override;
  /// The first time the crank reaches `angle_rad` (bisection on the table); RunError if never.
  double time_at_angle(double angle_rad) const override;
  double end_time_s() const { return t0_ + h_ * static_cast<double>(n_ - 1); }
  /// The tabulated speed at sample i (for checks against the spline's).
  const std::vector<double>& table_speeds() const { return speeds_; }

 private:
  struct Spline;
  std::unique_ptr<Spline> spline_;
  double t0_ = 0, h_ = 0;
  std::size_t n_ = 0;
  std::vector<double> speeds_;
};

}  // namespace fourbar
