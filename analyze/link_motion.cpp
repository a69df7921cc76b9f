#include "analyze/link_motion.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

SensedLinkMotion link_part(const Rig& rig, SensedLink link, const NominalMotion& m) {
  SensedLinkMotion out;
  if (link == SensedLink::coupler) {
    // Crank pin: a_A = l2(α2·n2 − ω2²·u2).
    const double l2 = rig.crank.length_m, w2 = m.crank.speed_rad_s;
    out.u = m.pose.u3;
    out.omega_rad_s = m.omega3_rad_s;
    out.alpha_rad_s2 = m.alpha3_rad_s2;
    out.joint_accel_m_s2 = l2 * (m.crank.accel_rad_s2 * m.pose.u2.perp() - w2 * w2 * m.pose.u2);
  } else {
    out.u = m.pose.u4;
    out.omega_rad_s = m.omega4_rad_s;
    out.alpha_rad_s2 = m.alpha4_rad_s2;
  }
  return out;
}

}  // namespace

void check_crank_track(const CrankTrack& crank) {
  const std::size_t n = crank.size();
  if (crank.speed_rad_s.size() != n || crank.accel_rad_s2.size() != n) {
    std::ostringstream os;
    os << "crank track: " << n << " angles, " << crank.speed_rad_s.size() << " speeds, " << crank.accel_rad_s2.size()
       << " accelerations; give one crank state per sample";
    throw InputError(os.str());
  }
}

SensedLinkMotion nominal_link_motion(const Rig& rig, SensedLink link, const CrankState& crank) {
  return link_part(rig, link, solve_motion(rig, crank));
}

std::vector<SensedLinkMotion> nominal_link_track(const Rig& rig, SensedLink link, const CrankTrack& crank) {
  check_crank_track(crank);
  std::vector<SensedLinkMotion> track(crank.size());
  for (std::size_t i = 0; i < crank.size(); ++i) track[i] = nominal_link_motion(rig, link, crank.at(i));
  return track;
}

LinkTable::LinkTable(const Rig& rig, SensedLink link) : rig_(rig), link_(link) {
  for (std::size_t m = std::size_t{1} << 12; m <= (std::size_t{1} << 20); m *= 2)
    if (build(m)) return;
  // Served exactly: the terms are solved per sample.
  m_ = 0;
  tangential_.clear(), normal_.clear();
  tangential_.shrink_to_fit(), normal_.shrink_to_fit();
}

LinkTable::TangentialRow LinkTable::exact_tangential(double theta2) const {
  const SensedLinkMotion k = nominal_link_motion(rig_, link_, {theta2, 1.0, 0.0});
  const double l2 = link_ == SensedLink::coupler ? rig_.crank.length_m : 0.0;
  const Vec2 u2{std::cos(theta2), std::sin(theta2)};
  return {k.omega_rad_s, k.u.x, l2 * dot(u2, k.u), l2 * cross(k.u, u2)};
}

LinkTable::NormalRow LinkTable::exact_normal(double theta2) const {
  const SensedLinkMotion k = nominal_link_motion(rig_, link_, {theta2, 1.0, 0.0});
  const double l2 = link_ == SensedLink::coupler ? rig_.crank.length_m : 0.0;
  const Vec2 u2{std::cos(theta2), std::sin(theta2)};
  return {k.omega_rad_s, k.alpha_rad_s2, k.u.y, -l2 * cross(k.u, u2), l2 * dot(u2, k.u)};
}

namespace {

// Fills rows[i + 1] = exact(2πi/m) with the wrap-around rows, and returns the
// largest interpolation error half-way between the points, relative to each
// field's largest magnitude.
template <std::size_t F, class Exact, class Interpolate>
double tabulate(std::vector<std::array<double, F>>& rows, std::size_t m, Exact exact, Interpolate interpolate) {
  rows.resize(m + 3);
  for (std::size_t i = 0; i < m; ++i) rows[i + 1] = exact(units::kTwoPi * static_cast<double>(i) / m);
  rows[0] = rows[m];      // θ2 = −2π/m
  rows[m + 1] = rows[1];  // 2π
  rows[m + 2] = rows[2];  // 2π + 2π/m
  std::array<double, F> peak{}, err{};
  for (std::size_t i = 0; i < m; ++i) {
    const double theta2 = units::kTwoPi * (static_cast<double>(i) + 0.5) / m;
    const std::array<double, F> e = exact(theta2), g = interpolate(theta2);
    for (std::size_t f = 0; f < F; ++f) {
      peak[f] = std::max(peak[f], std::abs(e[f]));
      err[f] = std::max(err[f], std::abs(g[f] - e[f]));
    }
  }
  double worst = 0;
  for (std::size_t f = 0; f < F; ++f)
    if (peak[f] > 0) worst = std::max(worst, err[f] / peak[f]);
  return worst;
}

}  // namespace

bool LinkTable::build(std::size_t m) {
  m_ = m;
  mask_ = m - 1;  // m is a power of two
  scale_ = static_cast<double>(m) / units::kTwoPi;
  const double et = tabulate(
      tangential_, m, [&](double th) { return exact_tangential(th); },
      [&](double th) { return interpolate(tangential_, th); });
  const double en = tabulate(
      normal_, m, [&](double th) { return exact_normal(th); }, [&](double th) { return interpolate(normal_, th); });
  max_error_ = std::max(et, en);
  return max_error_ <= kTolerance;
}

}  // namespace fourbar
