#include "compare/session_severity.hpp"

#include <algorithm>
#include <cmath>

namespace fourbar {

namespace {

/// Groups points whose key lies within `tol` (relative) of the group's first.
std::vector<SeverityGroup> group_by(std::vector<SeverityPoint> points, double SeverityPoint::*key,
                                    double SeverityPoint::*order, double tol) {
  std::sort(points.begin(), points.end(), [&](const auto& a, const auto& b) { return a.*key < b.*key; });
  std::vector<SeverityGroup> groups;
  double first = 0;
  for (auto& p : points) {
    if (groups.empty() || std::abs(p.*key - first) > tol * std::abs(first)) {
      groups.emplace_back();
      first = p.*key;
    }
    groups.back().points.push_back(std::move(p));
  }
  for (auto& g : groups) {
    double sum = 0;
    for (const auto& p : g.points) sum += p.*key;
    g.value = sum / static_cast<double>(g.points.size());
    std::stable_sort(g.points.begin(), g.points.end(), [&](const auto& a, const auto& b) { return a.*order < b.*order; });
  }
  return groups;
}

}  // namespace

SeverityTables severity_tables(std::vector<SeverityPoint> points, double speed_tolerance) {
  SeverityTables t;
  t.by_speed = group_by(points, &SeverityPoint::speed_rpm, &SeverityPoint::clearance_mm, speed_tolerance);
  t.by_clearance = group_by(std::move(points), &SeverityPoint::clearance_mm, &SeverityPoint::speed_rpm, 0.01);
  return t;
}

}  // namespace fourbar
