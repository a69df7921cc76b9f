#include "report/deviation_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "report/packed_numbers.hpp"

namespace fourbar {

using nlohmann::json;

namespace {

/// Column means of `v` (size columns × m).
void column_means(std::span<const double> v, std::size_t columns, std::vector<double>& out) {
  const std::size_t m = v.size() / columns;
  for (std::size_t c = 0; c < columns; ++c) {
    double sum = 0;
    for (std::size_t k = 0; k < m; ++k) sum += v[c * m + k];
    out.push_back(sum / static_cast<double>(m));
  }
}

}  // namespace

void DeviationMapCollector::on_start(const RecordingAnalysis& a) {
  coupler_ = a.coupler.has_value() || !a.rocker.has_value();
  points_ = a.grid_points_per_rev;
  columns_ = 1;
  for (std::size_t c = std::min(points_, kMapMaxColumns); c >= 1; --c)
    if (points_ % c == 0) {
      columns_ = c;
      break;
    }
  const std::size_t revolutions = std::max<std::size_t>(a.acquisition.revolutions, 1);
  every_ = (revolutions + kMapMaxRows - 1) / kMapMaxRows;
}

void DeviationMapCollector::on_revolution(const AnalyzedRevolution& r) {
  const std::span<const double> alpha = coupler_ ? r.alpha3_rad_s2 : r.alpha4_rad_s2;
  if (!r.averaged || alpha.size() != points_ || points_ == 0 || r.number % every_ != 0) return;
  numbers_.push_back(r.number);
  column_means(alpha, columns_, rows_);
}

json DeviationMapCollector::map_json(const std::vector<double>& nominal, double first_deg, double direction) const {
  if (numbers_.empty() || nominal.size() != points_) return nullptr;
  std::vector<double> nominal_cols;
  column_means(nominal, columns_, nominal_cols);
  std::vector<double> dev(rows_.size());
  for (std::size_t i = 0; i < rows_.size(); ++i) dev[i] = rows_[i] - nominal_cols[i % columns_];
  const PackedCounts packed = quantise(dev, 127);
  const std::size_t m = points_ / columns_;
  json centres = json::array();
  for (std::size_t c = 0; c < columns_; ++c) {
    const double deg = first_deg + direction * 360.0 * (static_cast<double>(c * m) + 0.5 * static_cast<double>(m - 1)) /
                                       static_cast<double>(points_);
    centres.push_back(std::fmod(std::fmod(deg, 360.0) + 360.0, 360.0));
  }
  return {{"quantity", coupler_ ? "alpha3_rad_s2" : "alpha4_rad_s2"},
          {"unit", "rad/s²"},
          {"rows", numbers_.size()},
          {"columns", columns_},
          {"revolution", numbers_},
          {"crank_deg", centres},
          {"first_crank_deg", std::fmod(std::fmod(first_deg, 360.0) + 360.0, 360.0)},
          {"crank_direction", direction},
          {"grid_points_per_column", m},
          {"every_kth_revolution", every_},
          {"largest_abs_rad_s2", 127.0 * packed.step},
          {"rad_s2_per_count", packed.step},
          {"deviation_int8_base64", pack_base64(packed.counts, 1)},
          {"rule", std::string("rows: ") +
                       (every_ == 1 ? "every averaged revolution"
                                    : "the averaged revolutions numbered a multiple of " + std::to_string(every_)) +
                       " (at most " + std::to_string(kMapMaxRows) + "); columns: mean of " +
                       std::to_string(m) + " consecutive grid angles (" + std::to_string(columns_) +
                       " per turn); values: measured − nominal, in steps of 1/127 of the largest |deviation|"}};
}

std::vector<int> decode_map_counts(const std::string& b64) {
  const std::vector<std::int32_t> c = unpack_base64(b64, 1);
  return {c.begin(), c.end()};
}

}  // namespace fourbar
