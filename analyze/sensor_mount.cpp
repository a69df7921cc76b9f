#include "analyze/sensor_mount.hpp"

#include <cmath>
#include <sstream>

#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {

const char* to_string(SensedLink l) { return l == SensedLink::coupler ? "coupler" : "rocker"; }
const char* to_string(SensorAxis a) { return a == SensorAxis::tangential ? "tangential" : "normal"; }

double link_length_m(const Rig& rig, SensedLink link) {
  return link == SensedLink::coupler ? rig.coupler.length_m : rig.rocker.length_m;
}

namespace {

[[noreturn]] void fail(const AccelerometerMount& m, const std::string& what) {
  std::ostringstream os;
  os << "channel '" << (m.channel.empty() ? std::string("?") : m.channel) << "' (" << to_string(m.link) << ' '
     << to_string(m.axis) << " accelerometer): " << what;
  throw InputError(os.str());
}

}  // namespace

ResolvedMount resolve_mount(const Rig& rig, const AccelerometerMount& m) {
  const double l = link_length_m(rig, m.link);
  const char* far = m.link == SensedLink::coupler ? "coupler-rocker joint B" : "bushing centre C";
  const char* first = m.link == SensedLink::coupler ? "crank pin A" : "rocker pivot O4";
  if (!std::isfinite(m.distance_m) || !std::isfinite(m.offset_m)) fail(m, "sensor position is not a finite number");
  if (m.distance_m < 0 || m.distance_m > l) {
    std::ostringstream os;
    os << "sensor distance " << units::m_to_mm(m.distance_m) << " mm from the "
       << (m.from == MeasuredFrom::first_joint ? first : far) << " lies outside the link (length "
       << units::m_to_mm(l) << " mm in the rig file" << (rig.name.empty() ? std::string() : " of '" + rig.name + "'")
       << "); give a distance between 0 and the link length or, if the sensor does sit there, correct the "
          "manifest's rig: it names the wrong rig file";
    fail(m, os.str());
  }
  ResolvedMount r;
  r.link = m.link;
  r.axis = m.axis;
  r.r_m = m.from == MeasuredFrom::first_joint ? m.distance_m : l - m.distance_m;
  r.h_m = m.offset_m;
  if (!(r.r_m > 1e-9 * l)) {
    std::ostringstream os;
    os << "sensor sits at the " << first << " (r = 0): it does not turn with the link, so it cannot give its "
       << "angular motion; mount it away from the " << first;
    fail(m, os.str());
  }
  if (m.axis_sign != 1 && m.axis_sign != -1) fail(m, "axis sign " + std::to_string(m.axis_sign) + " must be +1 or -1");
  r.sign = m.axis_sign;
  if (!std::isfinite(m.high_pass_corner_hz) || m.high_pass_corner_hz < 0) {
    std::ostringstream os;
    os << "high-pass corner " << m.high_pass_corner_hz << " Hz must be >= 0 (0 for a DC-coupled sensor)";
    fail(m, os.str());
  }
  r.high_pass_corner_hz = m.high_pass_corner_hz;
  return r;
}

}  // namespace fourbar
