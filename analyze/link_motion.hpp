#pragma once
// The nominal motion of a sensed link (coupler or rocker) at the measured
// crank state: what the conversion (conversion.hpp) takes the link angle,
// the offset term's ω and the first joint's acceleration from.
//
// Exact per sample (nominal_link_motion: one closed-form solution, thesis
// eq. 2.1-1 … 2.1-3), or from a table over the crank angle (LinkTable): the
// link angle θ depends on θ2 alone, so with K(θ2) = dθ/dθ2 and
// K'(θ2) = d²θ/dθ2²
//   ω = ω2·K(θ2),   α = α2·K(θ2) + ω2²·K'(θ2),
// and the coupler's first joint (the crank pin) accelerates with
//   a_A = l2·(α2·n2 − ω2²·u2).
// K, K' (the link's ω and α at ω2 = 1, α2 = 0), cos θ, sin θ, cos θ2 and
// sin θ2 are tabulated once per rig at M crank angles and read by 4-point
// Lagrange interpolation: one table read per sample instead of one nominal
// solution, for any crank speed and acceleration.

#include <array>
#include <span>
#include <vector>

#include "analyze/sensor_mount.hpp"
#include "mechanism/kinematics.hpp"

namespace fourbar {

/// Crank state per sample, as measured (acquire): continuous angle, speed,
/// acceleration. All spans have the length of the channel.
struct CrankTrack {
  std::span<const double> angle_rad, speed_rad_s, accel_rad_s2;
  std::size_t size() const { return angle_rad.size(); }
  CrankState at(std::size_t i) const { return {angle_rad[i], speed_rad_s[i], accel_rad_s2[i]}; }
};

/// The motion of the sensed link at one instant.
struct SensedLinkMotion {
  Vec2 u;                 ///< link direction
  double omega_rad_s = 0;
  double alpha_rad_s2 = 0;
  Vec2 joint_accel_m_s2;  ///< a_J of the link's first joint
};

/// The nominal motion of the sensed link at one crank state (exact).
SensedLinkMotion nominal_link_motion(const Rig& rig, SensedLink link, const CrankState& crank);

/// The same for every sample of a crank track. Throws InputError when the
/// track's spans differ in length.
std::vector<SensedLinkMotion> nominal_link_track(const Rig& rig, SensedLink link, const CrankTrack& crank);

/// Throws InputError when the spans of `crank` differ in length.
void check_crank_track(const CrankTrack& crank);

/// The nominal motion of one link tabulated over the crank angle, in the
/// terms the conversions need. With the link direction u, n = u turned +90°,
/// the first joint's acceleration is a_J = α2·(p_n·n + p_u·u) − ω2²·(q_n·n + q_u·u):
/// for the coupler (a_A = l2·(α2·n2 − ω2²·u2)) p_n = q_u = l2·cos(θ2 − θ),
/// q_n = −p_u = l2·sin(θ2 − θ); for the rocker all four are 0.
///   tangential terms  K, cos θ, p_n, q_n     (a_J·n = α2·p_n − ω2²·q_n)
///   normal terms      K, K', sin θ, p_u, q_u (a_J·u = α2·p_u − ω2²·q_u)
class LinkTable {
 public:
  /// Largest interpolation error accepted, relative to each tabulated
  /// function's largest magnitude, checked half-way between table points
  /// (where a 4-point interpolation errs most).
  static constexpr double kTolerance = 1e-11;

  /// Tabulates at 4096 crank angles, doubling up to 2^20 until the check
  /// passes; a rig that still fails (a mechanism close to a dead point,
  /// whose K varies too sharply) is served exactly, per sample.
  LinkTable(const Rig& rig, SensedLink link);

  struct Tangential {
    double k, cos_theta, p_n, q_n;
  };
  struct Normal {
    double k, k_prime, sin_theta, p_u, q_u;
  };

  SensedLink link() const { return link_; }
  /// The motion at one crank state (any speed and acceleration).
  SensedLinkMotion motion(const CrankState& crank) const;
  /// The terms at crank angle θ2 (interpolated; exact when served exactly).
  Tangential tangential(double theta2_rad) const;
  Normal normal(double theta2_rad) const;
  /// Points per crank turn; 0 when served exactly.
  std::size_t points() const { return m_; }
  /// The measured interpolation error (relative, as kTolerance).
  double max_error() const { return max_error_; }

 private:
  using TangentialRow = std::array<double, 4>;  // k, cos θ, p_n, q_n
  using NormalRow = std::array<double, 5>;      // k, k', sin θ, p_u, q_u
  TangentialRow exact_tangential(double theta2) const;
  NormalRow exact_normal(double theta2) const;
  template <std::size_t F>
  std::array<double, F> interpolate(const std::vector<std::array<double, F>>& rows, double theta2) const;
  bool build(std::size_t m);

  Rig rig_;
  SensedLink link_;
  std::size_t m_ = 0, mask_ = 0;
  double scale_ = 0;  // m / 2π
  // rows[i + 1] at θ2 = 2πi/m, i = −1 … m + 1
  std::vector<TangentialRow> tangential_;
  std::vector<NormalRow> normal_;
  double max_error_ = 0;
};

// Inline: read once per sample in the conversion loops. 4-point Lagrange in
// the crank angle, over every field of the row.
template <std::size_t F>
inline std::array<double, F> LinkTable::interpolate(const std::vector<std::array<double, F>>& rows,
                                                    double theta2) const {
  const double x = theta2 * scale_;
  long long q = static_cast<long long>(x);  // floor without a libm call
  if (x < static_cast<double>(q)) --q;
  const double t = x - static_cast<double>(q);
  // Points i − 1 … i + 2 are rows[i] … rows[i + 3]; m is a power of two,
  // so the index wraps by a mask (two's complement for negative angles).
  const std::size_t i = static_cast<std::size_t>(q) & mask_;
  constexpr double sixth = 1.0 / 6.0;
  const double tm1 = t - 1, tm2 = t - 2, tp1 = t + 1;
  const double w0 = -sixth * t * tm1 * tm2, w1 = 0.5 * tp1 * tm1 * tm2, w2 = -0.5 * tp1 * t * tm2,
               w3 = sixth * tp1 * t * tm1;
  const std::array<double, F>& a = rows[i];
  const std::array<double, F>& b = rows[i + 1];
  const std::array<double, F>& c = rows[i + 2];
  const std::array<double, F>& d = rows[i + 3];
  std::array<double, F> r;
  for (std::size_t f = 0; f < F; ++f) r[f] = w0 * a[f] + w1 * b[f] + w2 * c[f] + w3 * d[f];
  return r;
}

inline LinkTable::Tangential LinkTable::tangential(double theta2) const {
  const TangentialRow r = m_ == 0 ? exact_tangential(theta2) : interpolate(tangential_, theta2);
  return {r[0], r[1], r[2], r[3]};
}

inline LinkTable::Normal LinkTable::normal(double theta2) const {
  const NormalRow r = m_ == 0 ? exact_normal(theta2) : interpolate(normal_, theta2);
  return {r[0], r[1], r[2], r[3], r[4]};
}

inline SensedLinkMotion LinkTable::motion(const CrankState& crank) const {
  const Tangential t = tangential(crank.angle_rad);
  const Normal nr = normal(crank.angle_rad);
  const double w2 = crank.speed_rad_s, a2 = crank.accel_rad_s2, w2sq = w2 * w2;
  SensedLinkMotion out;
  out.u = {t.cos_theta, nr.sin_theta};
  out.omega_rad_s = w2 * t.k;
  out.alpha_rad_s2 = a2 * nr.k + w2sq * nr.k_prime;
  out.joint_accel_m_s2 = (a2 * t.p_n - w2sq * t.q_n) * out.u.perp() + (a2 * nr.p_u - w2sq * nr.q_u) * out.u;
  return out;
}

}  // namespace fourbar
