#include "fit/matched_magnification.hpp"

#include <cmath>

namespace fourbar {

std::optional<MatchedMagnification> matched_magnification(const StatisticValues& measured, std::size_t measured_turns,
                                                          const StatisticValues& model, std::size_t model_turns) {
  const auto md = index_of(ResponseStatistic::mean_deviation), sp = index_of(ResponseStatistic::spread);
  const double md_meas = measured.value[md];
  if (!(md_meas > 0) || measured_turns < 2 || model_turns < 2) return std::nullopt;
  const double R = static_cast<double>(measured_turns), M = static_cast<double>(model_turns);
  const double m = model.value[md], s = model.value[sp];
  const double c = 1.0 / R - 1.0 / M;  // negative when the model ran fewer turns: the same formula takes scatter out
  const double pred2 = m * m + s * s * c;
  if (!(pred2 > 0)) return std::nullopt;
  const double pred = std::sqrt(pred2);
  MatchedMagnification a;
  a.value = pred / md_meas;
  a.measured_relative_error = measured.standard_error[md] / md_meas;
  // var(pred²) ≈ (2 m se_m)² + (2 c s se_s)²; rel(pred) = sd(pred²) / (2 pred²).
  const double sd_pred2 = std::hypot(2 * m * model.standard_error[md], 2 * c * s * model.standard_error[sp]);
  a.model_relative_error = sd_pred2 / (2 * pred2);
  a.standard_error = a.value * std::hypot(a.measured_relative_error, a.model_relative_error);
  return a;
}

}  // namespace fourbar
