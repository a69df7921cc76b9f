#include "sim/linkage/linkage_sensor.hpp"

namespace fourbar {

SensorReading sensor_reading(const LinkageModel& m, const LinkageCoordinates& c, const LinkageWorkspace& w,
                             const LinkSensor& s) {
  const FrameState f = frame_state(w, s.body, true);
  const Vec2 u = w.body[static_cast<std::size_t>(s.body)].u, n = u.perp();
  const double om = f.angular_velocity_rad_s, al = f.angular_acceleration_rad_s2;
  Vec2 a, t = u;
  if (const ElasticLink* link = m.elastic(s.body)) {
    const ModalState modal = modal_state(m, c, w, s.body, true);
    a = point_acceleration(*link, s.distance_m, f, modal);
    t = axis_tangent(*link, s.distance_m, f, modal);
  } else {
    a = f.acceleration_m_s2 + s.distance_m * (al * n - om * om * u);
  }
  a += s.offset_m * (-al * u - om * om * n);
  const Vec2 sf = a + Vec2{0.0, m.rig().gravity_m_s2};
  return {dot(sf, t.perp()), dot(sf, t)};
}

double midspan_deflection_m(const LinkageModel& m, const LinkageCoordinates& c, const LinkageWorkspace& w, int body) {
  const ElasticLink* link = m.elastic(body);
  if (!link) return 0.0;
  return deflection(*link, 0.5 * link->length_m, modal_state(m, c, w, body, false).eta_m).y;
}

}  // namespace fourbar
