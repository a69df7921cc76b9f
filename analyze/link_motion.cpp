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

// 4-point Lagrange weights at fraction t ∈ [0, 1) for points −1, 0, 1, 2.
std::array<double, 4> lagrange4(double t) {
  return {-t * (t - 1) * (t - 2) / 6, (t + 1) * (t - 1) * (t - 2) / 2, -(t + 1) * t * (t - 2) / 2,
          (t + 1) * t * (t - 1) / 6};
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

LinkTable::LinkTable(const Rig& rig, SensedLink link) : rig_(rig), link_(link), l2_(rig.crank.length_m) {
  for (std::size_t m = std::size_t{1} << 14; m <= (std::size_t{1} << 20); m *= 2)
    if (build(m)) return;
  // Served exactly: motion() solves the mechanism per sample.
  m_ = 0;
  rows_.clear();
  rows_.shrink_to_fit();
}

LinkTable::Row LinkTable::exact_row(double theta2) const {
  const SensedLinkMotion k = nominal_link_motion(rig_, link_, {theta2, 1.0, 0.0});
  return {k.u.x, k.u.y, k.omega_rad_s, k.alpha_rad_s2, std::cos(theta2), std::sin(theta2)};
}

LinkTable::Row LinkTable::interpolated_row(double theta2) const {
  const double x = theta2 * scale_;
  const double fl = std::floor(x);
  long long q = static_cast<long long>(fl) % static_cast<long long>(m_);
  if (q < 0) q += static_cast<long long>(m_);
  const auto i = static_cast<std::size_t>(q);
  const std::array<double, 4> w = lagrange4(x - fl);
  const Row& a = rows_[i];  // point i − 1
  const Row& b = rows_[i + 1];
  const Row& c = rows_[i + 2];
  const Row& d = rows_[i + 3];
  Row r;
  for (std::size_t f = 0; f < r.size(); ++f) r[f] = w[0] * a[f] + w[1] * b[f] + w[2] * c[f] + w[3] * d[f];
  return r;
}

bool LinkTable::build(std::size_t m) {
  m_ = m;
  scale_ = static_cast<double>(m) / units::kTwoPi;
  rows_.resize(m + 3);
  for (std::size_t i = 0; i < m; ++i) rows_[i + 1] = exact_row(units::kTwoPi * static_cast<double>(i) / m);
  rows_[0] = rows_[m];          // θ2 = −2π/m
  rows_[m + 1] = rows_[1];      // 2π
  rows_[m + 2] = rows_[2];      // 2π + 2π/m
  // Check half-way between the points against the exact solution.
  Row peak{}, err{};
  for (std::size_t i = 0; i < m; ++i) {
    const double theta2 = units::kTwoPi * (static_cast<double>(i) + 0.5) / m;
    const Row e = exact_row(theta2), g = interpolated_row(theta2);
    for (std::size_t f = 0; f < e.size(); ++f) {
      peak[f] = std::max(peak[f], std::abs(e[f]));
      err[f] = std::max(err[f], std::abs(g[f] - e[f]));
    }
  }
  max_error_ = 0;
  for (std::size_t f = 0; f < peak.size(); ++f)
    if (peak[f] > 0) max_error_ = std::max(max_error_, err[f] / peak[f]);
  return max_error_ <= kTolerance;
}

SensedLinkMotion LinkTable::motion(const CrankState& crank) const {
  if (m_ == 0) return nominal_link_motion(rig_, link_, crank);
  const Row r = interpolated_row(crank.angle_rad);
  const double w2 = crank.speed_rad_s, a2 = crank.accel_rad_s2;
  SensedLinkMotion out;
  out.u = {r[0], r[1]};
  out.omega_rad_s = w2 * r[2];
  out.alpha_rad_s2 = a2 * r[2] + w2 * w2 * r[3];
  if (link_ == SensedLink::coupler) {
    const Vec2 u2{r[4], r[5]};
    out.joint_accel_m_s2 = l2_ * (a2 * u2.perp() - w2 * w2 * u2);
  }
  return out;
}

}  // namespace fourbar
