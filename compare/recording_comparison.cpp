#include "compare/recording_comparison.hpp"

#include <cmath>

#include "common/error.hpp"
#include "common/units.hpp"
#include "compare/metrics.hpp"

namespace fourbar {

namespace {

std::vector<double> burst_angles(const std::vector<double>& x, const std::vector<double>& nominal, const CrankGrid& g) {
  std::vector<double> dev(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) dev[i] = x[i] - nominal[i];
  const auto sep = static_cast<std::size_t>(std::ceil(15.0 / 360.0 * static_cast<double>(g.grid_points_per_rev)));
  std::vector<double> deg;
  for (std::size_t k : largest_peaks(dev, 3, sep)) deg.push_back(g.turned_deg(k));
  return deg;
}

}  // namespace

RecordingComparison compare_response(const MeasuredResponse& measured, const MatchedTheory& theory) {
  const std::size_t n = theory.grid.grid_points_per_rev;
  if (measured.grid.grid_points_per_rev != n || std::abs(measured.grid.start_rad - theory.grid.start_rad) > 1e-12 ||
      measured.grid.direction != theory.grid.direction)
    throw RunError("compare: measurement and theory are on different crank-angle grids");
  RecordingComparison out;
  for (LinkQuantity q : kLinkQuantities) {
    if (!measured.series[index_of(q)]) continue;
    const AngleSeries& m = *measured.series[index_of(q)];
    if (m.mean.size() != n) throw RunError("compare: measured " + std::string(column_name(q)) + " has " +
                                           std::to_string(m.mean.size()) + " points, the grid " + std::to_string(n));
    const TheorySeries& t = theory.series[index_of(q)];
    const std::vector<double>& sim = t.clearance.mean;
    QuantityComparison c;
    c.quantity = q;
    c.measured_rms = rms(m.mean);
    c.simulated_rms = rms(sim);
    c.nominal_rms = rms(t.nominal);
    c.rms_difference_simulated = rms_difference(m.mean, sim);
    c.rms_difference_nominal = rms_difference(m.mean, t.nominal);
    c.correlation_simulated = correlation(m.mean, sim);
    c.correlation_nominal = correlation(m.mean, t.nominal);
    c.peak_ratio_simulated = peak_ratio(m.mean, sim);
    c.peak_ratio_nominal = peak_ratio(m.mean, t.nominal);
    c.measured_bursts_deg = burst_angles(m.mean, t.nominal, theory.grid);
    c.simulated_bursts_deg = burst_angles(sim, t.nominal, theory.grid);
    if (!c.measured_bursts_deg.empty() && !c.simulated_bursts_deg.empty()) {
      const double d = std::abs(c.measured_bursts_deg[0] - c.simulated_bursts_deg[0]);
      c.largest_burst_offset_deg = std::min(d, 360.0 - d);
    }
    MagnificationInput in{t.nominal, m.mean, sim, m.revolutions, t.clearance_revolutions};
    const MainsHum hum{std::abs(measured.crank_speed_rad_s) / units::kTwoPi, measured.mains_hz, measured.speed_rel_std};
    c.magnification = magnification_factor(in, theory.settings.max_order, hum);
    out.quantities[index_of(q)] = std::move(c);
  }
  return out;
}

}  // namespace fourbar
