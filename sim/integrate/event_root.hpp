#pragma once
// Locating an event time: the root of a witness function on a bracket of the
// integrator's dense output (TOMS 748), kept on the far side of the event.
// Used by the clearance simulator's event scans (event_scan.cpp).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <boost/math/tools/toms748_solve.hpp>

namespace fourbar {

/// Root of f on [a, b] with f(a) and f(b) of opposite sign, to a few ulps of
/// the time (at most 1e-13 s while t < 28 s): returns the end of the final
/// bracket on the side of f(b). A fixed 1e-13 s was too coarse for tiny
/// clearances at speed: the pin reached 7.7e-9·ξ past the wall (ξ = 1 µm,
/// 3000 rpm, issue 7), above the 1e-9·ξ bound.
template <class F>
double locate_root(F&& f, double a, double b, double fa, double fb) {
  if (fb == 0) return b;
  const double tol = 1e-18 + 8 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b));
  auto stop = [tol](double x, double y) { return std::abs(y - x) <= tol; };
  std::uintmax_t iters = 200;
  const auto r = boost::math::tools::toms748_solve(f, a, b, fa, fb, stop, iters);
  // Keep the side where f has the sign of f(b) (past the event).
  const double fr = f(r.second);
  return (fr == 0 || (fr > 0) == (fb > 0)) ? r.second : r.first;
}

}  // namespace fourbar
