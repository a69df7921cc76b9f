#include "virtual_rig/sensor_signal.hpp"

#include "mechanism/vec2.hpp"

namespace fourbar {

double specific_force(const Rig& rig, const LinkState& st, ChannelRole role, double s, double d) {
  const bool coupler = is_on_coupler(role);
  const double theta = coupler ? st.theta3_rad : st.theta4_rad;
  const double omega = coupler ? st.omega3_rad_s : st.omega4_rad_s;
  const double alpha = coupler ? st.alpha3_rad_s2 : st.alpha4_rad_s2;
  const Vec2 u = unit(theta), n = u.perp();
  Vec2 a = alpha * (s * n - d * u) - omega * omega * (s * u + d * n);
  if (coupler) {
    const Vec2 u2 = unit(st.crank.angle_rad);
    a += rig.crank.length_m * (st.crank.accel_rad_s2 * u2.perp() - st.crank.speed_rad_s * st.crank.speed_rad_s * u2);
  }
  const Vec2 f = a + Vec2{0.0, rig.gravity_m_s2};
  return is_tangential(role) ? dot(f, n) : dot(f, u);
}

}  // namespace fourbar
