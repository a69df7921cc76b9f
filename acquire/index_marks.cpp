#include "acquire/index_marks.hpp"

#include <algorithm>
#include <cmath>

#include "common/units.hpp"

namespace fourbar {

IndexPlacement place_index_marks(const std::vector<double>& edges, const std::vector<double>& marks) {
  IndexPlacement out;
  std::vector<double> place;
  double c = 0, s = 0;
  for (double m : marks) {
    const auto i = static_cast<std::size_t>(std::lower_bound(edges.begin(), edges.end(), m) - edges.begin());
    if (i == 0 || i == edges.size()) continue;
    const double pitch = edges[i] - edges[i - 1];
    const double f = pitch > 0 ? (m - edges[i - 1]) / pitch : 1.0;  // (0, 1]; A and B at one instant: on the edge
    place.push_back(static_cast<double>(i - 1) + f);
    c += std::cos(units::kTwoPi * f), s += std::sin(units::kTwoPi * f);
  }
  if (place.empty()) return out;
  double psi = std::atan2(s, c) / units::kTwoPi;
  if (psi < 0) psi += 1;
  out.phase_pitch = psi;
  const long long shift = psi > 0.25 ? 1 : 0;
  for (double x : place) {
    const long long k = std::llround(x - psi) + shift;
    if (k < 0 || k >= static_cast<long long>(edges.size())) continue;
    const auto e = static_cast<std::size_t>(k);
    if (out.reference_edges.empty() || e > out.reference_edges.back()) out.reference_edges.push_back(e);
  }
  return out;
}

}  // namespace fourbar
