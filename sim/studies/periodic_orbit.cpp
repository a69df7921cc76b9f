#include "sim/studies/periodic_orbit.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

#include "common/units.hpp"
#include "mechanism/kinematics.hpp"
#include "sim/three_mode/simulator.hpp"

namespace fourbar {

std::optional<Eigen::VectorXd> shoot_fixed_point(const StateMap& map, Eigen::VectorXd x, const ShootingSettings& s) {
  const Eigen::Index n = x.size();
  Eigen::VectorXd image(n);
  if (!map(x, image)) return std::nullopt;
  Eigen::VectorXd g = image - x;
  Eigen::MatrixXd jacobian(n, n);
  Eigen::VectorXd xj(n), gj(n);
  for (int it = 0; it < s.max_iterations && g.norm() > s.tolerance; ++it) {
    for (Eigen::Index j = 0; j < n; ++j) {
      xj = x;
      xj(j) += s.difference_step;
      if (!map(xj, image)) return std::nullopt;
      jacobian.col(j) = ((image - xj) - g) / s.difference_step;
    }
    const Eigen::VectorXd step = jacobian.fullPivLu().solve(-g);
    if (!step.allFinite()) return std::nullopt;
    bool improved = false;
    double lambda = 1;
    for (int h = 0; h <= s.max_halvings && !improved; ++h, lambda /= 2) {
      xj = x + lambda * step;
      if (!map(xj, image)) continue;
      gj = image - xj;
      if (gj.norm() < g.norm()) x = xj, g = gj, improved = true;
    }
    if (!improved) return std::nullopt;
  }
  if (!(g.norm() <= s.tolerance)) return std::nullopt;
  return x;
}

TurnMap::TurnMap(const Rig& rig, double clearance_m, double crank_speed_rad_s, const ClearanceSettings& settings)
    : model_(rig, clearance_m),
      crank_(0.0, crank_speed_rad_s),
      settings_(settings),
      speed_rad_s_(std::abs(crank_speed_rad_s)),
      angle_scale_rad_(clearance_m / rig.coupler.length_m) {}

Eigen::Vector4d TurnMap::deviation(double time_s, const LinkMotion& l) const {
  const NominalMotion n = solve_motion(model_.rig(), crank_.at(time_s));
  const double a = angle_scale_rad_, r = speed_rad_s_ * angle_scale_rad_;
  return {std::atan2(cross(n.pose.u3, l.u3), dot(n.pose.u3, l.u3)) / a,
          std::atan2(cross(n.pose.u4, l.u4), dot(n.pose.u4, l.u4)) / a, (l.omega3_rad_s - n.omega3_rad_s) / r,
          (l.omega4_rad_s - n.omega4_rad_s) / r};
}

bool TurnMap::run(const Eigen::Vector4d& x, int turns, std::vector<Eigen::Vector4d>& starts) const {
  const NominalMotion n = solve_motion(model_.rig(), crank_.at(0.0));
  const double a = angle_scale_rad_, r = speed_rad_s_ * angle_scale_rad_;
  const double th3 = std::atan2(n.pose.u3.y, n.pose.u3.x) + x(0) * a, th4 = std::atan2(n.pose.u4.y, n.pose.u4.x) + x(1) * a;
  const LinkMotion start{{std::cos(th3), std::sin(th3)}, {std::cos(th4), std::sin(th4)}, n.omega3_rad_s + x(2) * r,
                         n.omega4_rad_s + x(3) * r};
  const double period_s = units::kTwoPi / speed_rad_s_;
  starts.clear();
  try {
    ClearanceSimulator sim(model_, crank_, settings_);
    sim.start_free(0.0, start);
    for (int k = 1; k <= turns; ++k) {
      sim.advance_to(k * period_s);
      starts.push_back(deviation(k * period_s, sim.current_links()));
    }
  } catch (const std::exception&) {  // outside the bushing, or a run the integrator could not finish
    return false;
  }
  return true;
}

std::vector<Eigen::Vector4d> TurnMap::own_turns(int skip, int count) const {
  const double period_s = units::kTwoPi / speed_rad_s_;
  ClearanceSimulator sim(model_, crank_, settings_);
  sim.start_nominal(0.0);
  std::vector<Eigen::Vector4d> out;
  for (int k = 1; k <= skip + count; ++k) {
    sim.advance_to(k * period_s);
    if (k > skip) out.push_back(deviation(k * period_s, sim.current_links()));
  }
  return out;
}

double repeat_distance(const std::vector<Eigen::Vector4d>& starts, int period) {
  std::vector<double> r;
  const auto p = static_cast<std::size_t>(period);
  for (std::size_t k = starts.size() / 2; k + p < starts.size(); ++k) r.push_back((starts[k + p] - starts[k]).norm());
  if (r.empty()) return std::numeric_limits<double>::infinity();
  std::nth_element(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2), r.end());
  return r[r.size() / 2];
}

bool OrbitSearchResult::any_stable() const {
  return std::any_of(orbits.begin(), orbits.end(), [](const FoundOrbit& o) { return o.stable; });
}

OrbitSearchResult find_periodic_orbits(const TurnMap& map, const OrbitSearchSettings& s) {
  OrbitSearchResult out;
  std::vector<Eigen::Vector4d> turns;
  const StateMap power = [&](const Eigen::VectorXd& x, Eigen::VectorXd& image) {
    if (!(x.norm() <= s.max_state_norm) || !map.run(Eigen::Vector4d(x), s.period, turns)) return false;
    image = turns.back();
    return true;
  };
  // Two roots of G on one orbit (its p turn starts) or on the same one twice
  // are one orbit: within this of each other in the scaled units (distinct
  // orbits lie ~1 apart, docs/fit.md "Newton shooting finds it").
  constexpr double kSameOrbit = 1e-4;
  // The orbit found before whose start is x or one of x's next p − 1 turn starts.
  auto known = [&](const Eigen::Vector4d& x, const std::vector<Eigen::Vector4d>& cycle) -> FoundOrbit* {
    for (FoundOrbit& o : out.orbits) {
      if ((o.start - x).norm() < kSameOrbit) return &o;
      for (const Eigen::Vector4d& c : cycle)
        if ((o.start - c).norm() < kSameOrbit) return &o;
    }
    return nullptr;
  };
  for (const Eigen::Vector4d& x0 : map.own_turns(s.skip_turns, s.starts)) {
    ++out.starts;
    const std::optional<Eigen::VectorXd> root = shoot_fixed_point(power, Eigen::VectorXd(x0), s.shooting);
    if (!root) continue;
    const Eigen::Vector4d x(*root);
    // x's next p − 1 turn starts. An orbit of a shorter period q | p is also a
    // root; it is not the motion looked for.
    std::vector<Eigen::Vector4d> cycle;
    bool shorter = false;
    if (s.period > 1 && map.run(x, s.period - 1, cycle))
      for (int q = 1; q < s.period && !shorter; ++q)
        shorter = s.period % q == 0 && (cycle[static_cast<std::size_t>(q - 1)] - x).norm() < kSameOrbit;
    if (shorter) {
      ++out.shorter;
      continue;
    }
    ++out.converged;
    FoundOrbit* o = known(x, cycle);
    if (!o) {
      std::vector<Eigen::Vector4d> check;
      FoundOrbit f{x, false, std::numeric_limits<double>::infinity()};
      if (map.run(x, s.check_turns, check)) f.repeat_distance = repeat_distance(check, s.period);
      f.stable = f.repeat_distance < s.repeat_distance;
      out.orbits.push_back(f);
      o = &out.orbits.back();
    }
    if (o->stable) ++out.stable_from;
    if (o->stable && s.stop_at_first_stable) break;
  }
  return out;
}

}  // namespace fourbar
