#include "report/deviation_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <openssl/evp.h>

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
  double largest = 0;
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    dev[i] = rows_[i] - nominal_cols[i % columns_];
    largest = std::max(largest, std::abs(dev[i]));
  }
  std::string bytes(dev.size(), '\0');
  for (std::size_t i = 0; i < dev.size(); ++i)
    bytes[i] = static_cast<char>(static_cast<signed char>(largest > 0 ? std::lround(127.0 * dev[i] / largest) : 0));
  std::string b64(4 * ((bytes.size() + 2) / 3) + 1, '\0');
  const int n = EVP_EncodeBlock(reinterpret_cast<unsigned char*>(b64.data()),
                                reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<int>(bytes.size()));
  b64.resize(static_cast<std::size_t>(n));
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
          {"crank_direction", direction},
          {"grid_points_per_column", m},
          {"every_kth_revolution", every_},
          {"largest_abs_rad_s2", largest},
          {"rad_s2_per_count", largest / 127.0},
          {"deviation_int8_base64", b64},
          {"rule", std::string("rows: ") +
                       (every_ == 1 ? "every averaged revolution"
                                    : "the averaged revolutions numbered a multiple of " + std::to_string(every_)) +
                       " (at most " + std::to_string(kMapMaxRows) + "); columns: mean of " +
                       std::to_string(m) + " consecutive grid angles (" + std::to_string(columns_) +
                       " per turn); values: measured − nominal, in steps of 1/127 of the largest |deviation|"}};
}

std::vector<int> decode_map_counts(const std::string& b64) {
  std::string bytes(3 * (b64.size() / 4) + 3, '\0');
  const int n = EVP_DecodeBlock(reinterpret_cast<unsigned char*>(bytes.data()),
                                reinterpret_cast<const unsigned char*>(b64.data()), static_cast<int>(b64.size()));
  if (n < 0) return {};
  std::size_t len = static_cast<std::size_t>(n);
  // EVP_DecodeBlock counts the padding's zero bytes.
  if (!b64.empty() && b64.back() == '=') --len;
  if (b64.size() > 1 && b64[b64.size() - 2] == '=') --len;
  std::vector<int> out(len);
  for (std::size_t i = 0; i < len; ++i) out[i] = static_cast<signed char>(bytes[i]);
  return out;
}

}  // namespace fourbar
