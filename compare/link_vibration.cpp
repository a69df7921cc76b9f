#include "compare/link_vibration.hpp"

#include <algorithm>
#include <cmath>

#include "common/statistics.hpp"

namespace fourbar {

LinkVibrationCheck check_link_vibration(ModelFamilyCheck& c, std::span<const double> measured,
                                        std::span<const double> model, std::span<const double> rigid,
                                        std::span<const double> elastic, std::span<const double> nominal) {
  LinkVibrationCheck v;
  if (!c.checked) {
    v.not_checked = "the model family was not checked";
    return v;
  }
  const std::size_t n = nominal.size();
  if (n == 0 || elastic.size() % n != 0 || elastic.size() / n < 4 || rigid.size() % n != 0 || rigid.size() / n < 4) {
    v.not_checked = "fewer than 4 turns of the linkage model";
    return v;
  }
  v.elastic_ms = band_mean_squares(elastic, nominal, c.crank_hz, c.bands);
  v.rigid_band_ms = band_mean_squares(rigid, nominal, c.crank_hz, c.bands);
  const std::vector<double>& rb = v.rigid_band_ms;
  const std::size_t nb = c.bands.size();
  for (std::size_t b = 0; b < nb; ++b)
    if (rb[b] > 0 && v.elastic_ms[b] >= kVibrationBandRatio * rb[b]) v.vibration_bands.push_back(b);
  if (v.vibration_bands.empty()) {
    v.not_checked = "the elastic model has no band with " + std::to_string(static_cast<int>(kVibrationBandRatio)) +
                    "x the rigid-link model's energy up to " + std::to_string(static_cast<int>(c.checked_up_to_hz)) + " Hz";
    return v;
  }
  const std::size_t first = v.vibration_bands.front();
  std::vector<double> r, q;
  for (std::size_t b = first; b-- > 0 && v.reference_bands.size() < kReferenceBandCount;) {
    const FamilyBand& fb = c.bands[b];
    if (!(rb[b] > 0) || !(fb.measured_ms > 0) || !(v.elastic_ms[b] > 0)) continue;
    v.reference_bands.push_back(b);
    r.push_back(fb.measured_ms / rb[b]);
    q.push_back(v.elastic_ms[b] / rb[b]);
  }
  if (v.reference_bands.size() < kMinReferenceBands) {
    v.not_checked = "fewer than " + std::to_string(kMinReferenceBands) +
                    " checked bands below the links' vibration to scale the models by";
    return v;
  }
  v.reference_ratio = median(r);
  v.elastic_reference_ratio = median(q);
  v.low_hz = c.bands[first].low_hz;
  v.high_hz = c.bands[v.vibration_bands.back()].high_hz;
  double peak = -1, peak_hz = 0;
  for (std::size_t b : v.vibration_bands) {
    const FamilyBand& fb = c.bands[b];
    v.measured_ms += fb.measured_ms;
    v.rigid_ms += rb[b];
    v.elastic_ms_sum += v.elastic_ms[b];
    const double excess = fb.measured_ms - v.reference_ratio * rb[b];
    if (excess > peak) peak = excess, peak_hz = 0.5 * (fb.low_hz + fb.high_hz);
  }
  v.checked = true;
  const double span = std::log(v.elastic_ms_sum / (v.elastic_reference_ratio * v.rigid_ms));
  const double above = std::log(v.measured_ms / (v.reference_ratio * v.rigid_ms));
  // The elastic model scaled as it meets the impacts below: no vibration of
  // its own (span ≤ 0) leaves nothing to place the measurement against.
  if (!(span > 0)) {
    v.checked = false;
    v.not_checked = "the elastic-link model, scaled by its own energy below, has no more energy than the rigid-link model in the vibration bands";
    return v;
  }
  v.position = above / span;
  double measured_total = 0;
  for (double x : measured) measured_total += x * x;
  measured_total /= static_cast<double>(std::max<std::size_t>(measured.size(), 1));
  const double excess = v.measured_ms - v.reference_ratio * v.rigid_ms;
  v.rms_share = measured_total > 0 && excess > 0 ? std::sqrt(excess / measured_total) : 0.0;
  v.present = v.position >= kPresentPosition && v.rms_share >= kMinRmsShare;
  if (!v.present) return v;
  UnmodelledEnergy u;
  u.kind = "link vibration";
  u.low_hz = v.low_hz;
  u.high_hz = v.high_hz;
  u.peak_hz = peak_hz;
  u.rms_share = v.rms_share;
  u.excess_ratio = v.measured_ms / (v.reference_ratio * v.rigid_ms);
  judge_below(u, measured, model, n, c.crank_hz);
  // One finding per span: a finding of the rigid check inside the
  // vibration's span is the same energy.
  std::erase_if(c.unmodelled, [&](const UnmodelledEnergy& f) { return f.low_hz >= u.low_hz && f.high_hz <= u.high_hz; });
  c.unmodelled.push_back(u);
  std::sort(c.unmodelled.begin(), c.unmodelled.end(),
            [](const UnmodelledEnergy& a, const UnmodelledEnergy& b) { return a.low_hz < b.low_hz; });
  judge_below_first_finding(c);
  return v;
}

}  // namespace fourbar
