#include "compare/magnification.hpp"

#include <algorithm>
#include <cmath>

#include "analyze/spectrum.hpp"
#include "common/error.hpp"
#include "compare/metrics.hpp"

namespace fourbar {

namespace {

/// rows × N minus the same N-point row from each row.
std::vector<double> minus_row(std::span<const double> rows, std::span<const double> row) {
  std::vector<double> d(rows.begin(), rows.end());
  for (std::size_t i = 0; i < d.size(); ++i) d[i] -= row[i % row.size()];
  return d;
}

}  // namespace

std::vector<double> order_amplitudes(std::span<const double> revolutions, std::size_t grid_points_per_rev, int max_order,
                                     std::vector<double>* floor) {
  const std::size_t n = grid_points_per_rev, rows = revolutions.size() / n;
  if (rows == 0 || revolutions.size() % n != 0)
    throw RunError("order_amplitudes: " + std::to_string(revolutions.size()) + " values are not whole revolutions of " +
                   std::to_string(n));
  // The sample rate in "points per revolution" puts the frequency axis in crank orders.
  const WindowSpec window{rows >= 2 ? WindowType::hann : WindowType::rectangular, 0};
  const Spectrum s = amplitude_spectrum(revolutions, static_cast<double>(n), window);
  std::vector<double> amp(static_cast<std::size_t>(max_order) + 1, 0.0);
  for (int k = 0; k <= max_order; ++k) {
    const std::size_t bin = static_cast<std::size_t>(k) * rows;
    if (bin < s.value.size()) amp[static_cast<std::size_t>(k)] = s.value[bin];
  }
  if (floor) {
    floor->assign(amp.size(), 0.0);
    if (rows >= 6) {
      // Bins at least 2 from every order line (outside the Hann main lobe).
      for (int k = 1; k <= max_order; ++k) {
        std::vector<double> between;
        for (int j = std::max(0, k - 2); j <= k + 2; ++j)
          for (std::size_t off = 2; off + 2 <= rows; ++off) {
            const std::size_t bin = static_cast<std::size_t>(j) * rows + off;
            if (bin < s.value.size()) between.push_back(s.value[bin]);
          }
        (*floor)[static_cast<std::size_t>(k)] = median(std::move(between));
      }
    }
  }
  return amp;
}

int nominal_band_orders(std::span<const double> nominal) {
  const std::size_t n = nominal.size();
  if (n < 4) return 0;
  const int top = static_cast<int>(n / 2) - 1;
  const std::vector<double> a = order_amplitudes(nominal, n, top);
  double total = 0;
  for (int k = 1; k <= top; ++k) total += a[static_cast<std::size_t>(k)] * a[static_cast<std::size_t>(k)];
  double above = total;
  for (int k = 1; k <= top; ++k) {
    if (above <= kNominalBandResidual * total) return k - 1;
    above -= a[static_cast<std::size_t>(k)] * a[static_cast<std::size_t>(k)];
  }
  return top;
}

Magnification magnification_factor(const MagnificationInput& in, int max_order, const MainsHum& mains) {
  const std::size_t n = in.nominal.size();
  Magnification m;
  m.measured_deviation_rms = rms_difference(in.measured_mean, in.nominal);
  m.simulated_deviation_rms = rms_difference(in.simulated_mean, in.nominal);
  if (m.measured_deviation_rms > 0) {
    m.time_domain = m.simulated_deviation_rms / m.measured_deviation_rms;
    m.modified.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      m.modified[i] = in.nominal[i] + (in.simulated_mean[i] - in.nominal[i]) / *m.time_domain;
  }

  // Order amplitudes of the deviations, from every revolution when given.
  max_order = std::min<int>(max_order, static_cast<int>(n / 2) - 1);
  if (max_order < 1) return m;
  const auto meas_rows = in.measured_revolutions.empty() ? in.measured_mean : in.measured_revolutions;
  const auto sim_rows = in.simulated_revolutions.empty() ? in.simulated_mean : in.simulated_revolutions;
  std::vector<double> floor;
  const std::vector<double> am = order_amplitudes(minus_row(meas_rows, in.nominal), n, max_order, &floor);
  const std::vector<double> as = order_amplitudes(minus_row(sim_rows, in.nominal), n, max_order);
  const std::size_t rm = meas_rows.size() / n, rs = sim_rows.size() / n;
  auto method = [](std::size_t r) {
    return r >= 2 ? "Hann window over " + std::to_string(r) + " revolutions"
                  : std::string("one averaged revolution, no window (exactly periodic)");
  };
  m.spectral_method = "measured: " + method(rm) + "; simulated: " + method(rs);
  double sum_sim = 0, sum_meas = 0, band_meas = 0, band_sim = 0, band_floor = 0, all_floor = 0;
  const MainsOrders hum(mains, rm);
  m.nominal_band_orders = nominal_band_orders(in.nominal);
  for (int k = 1; k <= max_order; ++k) {
    const auto i = static_cast<std::size_t>(k);
    OrderRatio o;
    o.order = k;
    o.measured_amplitude = am[i];
    o.simulated_amplitude = as[i];
    o.measured_floor = floor[i];
    o.significant = am[i] > 0 && am[i] > 3.0 * floor[i];
    o.mains = hum.at_mains(k);
    if (am[i] > 0) o.factor = as[i] / am[i];
    all_floor += floor[i] * floor[i];
    const bool effect_order = k > m.nominal_band_orders && !o.mains;
    if (effect_order) band_meas += am[i] * am[i], band_sim += as[i] * as[i], band_floor += floor[i] * floor[i];
    if (o.significant && effect_order) {
      sum_sim += as[i] * as[i], sum_meas += am[i] * am[i];
      m.orders_used.push_back(k);
    }
    m.orders.push_back(o);
  }
  if (sum_meas > 0) m.spectral = std::sqrt(sum_sim / sum_meas);
  m.floor_rms = std::sqrt(all_floor / 2);  // a line of amplitude A has RMS A/√2
  if (band_floor > 0) {
    m.effect_to_floor = std::sqrt(band_meas / band_floor);
    m.model_effect_to_floor = std::sqrt(band_sim / band_floor);
  }
  return m;
}

}  // namespace fourbar
