#include "sim/contact/restitution_calibration.hpp"

#include <cmath>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <utility>

#include <boost/math/tools/toms748_solve.hpp>

#include "common/error.hpp"
#include "sim/integrate/stiff_integrator.hpp"

namespace fourbar {

namespace {

struct ScaledCollision final : StiffSystem {
  double c = 0, n = 1.5;
  void rhs(double, const StiffState& y, StiffState& dy) override {
    dy = {};
    dy[0] = y[1];
    const double x = y[0];
    const double f = x > 0 ? std::pow(x, n) * (1.0 + c * y[1]) : 0.0;
    dy[1] = -(f > 0 ? f : 0.0);
  }
  double witness(double, const StiffState& y) override { return y[0]; }
};

}  // namespace

double effective_restitution(double c, double n) {
  ScaledCollision sys;
  sys.c = c;
  sys.n = n;
  StiffIntegrator integ(1e-12, 2, 9);  // 9 components as always: the error norm, so c(e), depends on the count
  StiffState y{};
  y[1] = 1.0;
  integ.reset(sys, 0.0, y);
  for (int i = 0; i < 1'000'000; ++i) {
    const StiffIntegrator::Step s = integ.step(1e6);
    if (s.root < 0) {
      integ.interpolate(s.end, y);
      return -y[1];
    }
    if (s.end >= 1e6) break;
  }
  throw RunError("restitution calibration: the scaled collision did not end (c = " + std::to_string(c) + ")");
}

namespace {

double solve_hysteresis(double e, double n) {
  auto f = [&](double c) { return effective_restitution(c, n) - e; };
  // effective_restitution falls from 1 at c = 0; bracket by doubling.
  double lo = 0, hi = 1, f_hi = f(hi);
  while (f_hi > 0 && hi < 1e12) lo = hi, hi *= 4, f_hi = f(hi);
  std::uintmax_t iters = 100;
  auto stop = [](double a, double b) { return std::abs(b - a) <= 1e-12 * std::abs(b); };
  const auto r = boost::math::tools::toms748_solve(f, lo, hi, f(lo), f_hi, stop, iters);
  return 0.5 * (r.first + r.second);
}

}  // namespace

double calibrated_hysteresis(double e, double n) {
  if (e >= 1) return 0.0;
  // Solved once per (e, n) in the process: a sweep or a session runs the
  // same contact law many times, and the solve costs about as much as two
  // turns of the compliant model. Deterministic, so the memo changes no result.
  static std::mutex mutex;
  static std::map<std::pair<double, double>, double> solved;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = solved.find({e, n}); it != solved.end()) return it->second;
  }
  const double c = solve_hysteresis(e, n);
  const std::lock_guard<std::mutex> lock(mutex);
  solved.emplace(std::make_pair(e, n), c);
  return c;
}

}  // namespace fourbar
