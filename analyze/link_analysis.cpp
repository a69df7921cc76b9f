#include "analyze/link_analysis.hpp"

#include <sstream>

#include "common/error.hpp"

namespace fourbar {

namespace {

// Average of the revolutions between the guard revolutions.
AngleAverage guarded_average(const std::vector<double>& grid, std::size_t revolutions, std::size_t n,
                             std::size_t guard) {
  if (2 * guard >= revolutions) {
    std::ostringstream os;
    os << "averaging: " << guard << " guard revolutions at each end leave none of the " << revolutions
       << " revolutions in the record; give fewer guard revolutions";
    throw InputError(os.str());
  }
  return synchronous_average(std::span(grid).subspan(guard * n, (revolutions - 2 * guard) * n), n);
}

void require_axis(const AccelerometerMount& m, SensorAxis want) {
  if (m.axis != want) {
    std::ostringstream os;
    os << "channel '" << m.channel << "' is a " << to_string(m.axis) << " accelerometer; expected a " << to_string(want)
       << " one";
    throw InputError(os.str());
  }
}

bool same(const FilterSpec& a, const FilterSpec& b) {
  return a.band == b.band && a.low_hz == b.low_hz && a.high_hz == b.high_hz && a.mains_hz == b.mains_hz &&
         a.mains_width_hz == b.mains_width_hz && a.window.type == b.window.type &&
         a.window.parameter == b.window.parameter && a.transition_hz == b.transition_hz;
}

}  // namespace

RecordAnalyzer::RecordAnalyzer(const Rig& rig, const CrankTrack& crank, double fs, const AngleGridSpec& grid)
    : rig_(rig), crank_(crank), fs_(fs), grid_(crank.angle_rad, grid.points_per_rev, grid.start_rad) {
  if (crank.speed_rad_s.size() != crank.size() || crank.accel_rad_s2.size() != crank.size())
    throw InputError("crank track: angles, speeds and accelerations differ in length");
  speed_grid_ = grid_.resample(crank.speed_rad_s);
}

const std::vector<LinkMotion>& RecordAnalyzer::track(SensedLink link) {
  if (!tracks_) tracks_ = nominal_link_tracks(rig_, crank_);
  return link == SensedLink::coupler ? tracks_->coupler : tracks_->rocker;
}

FftFilter& RecordAnalyzer::filter(const FilterSpec& spec, Boundary boundary) {
  for (CachedFilter& c : filters_)
    if (c.boundary == boundary && same(c.spec, spec)) return *c.filter;
  filters_.push_back({spec, boundary, std::make_unique<FftFilter>(spec, fs_, crank_.size(), boundary)});
  return *filters_.back().filter;
}

std::vector<double> RecordAnalyzer::converted(const AccelerometerMount& mount, std::span<const double> reading,
                                              std::span<const double> link_alpha, const ChannelOptions& opt) {
  const std::vector<LinkMotion>& nominal = track(mount.link);
  std::vector<double> x(reading.size());
  restore_dc_coupled_reading(rig_, mount, nominal, fs_, reading, x);
  if (mount.axis == SensorAxis::tangential) angular_acceleration_from_tangential(rig_, mount, nominal, x, x);
  else angular_speed_squared_from_normal(rig_, mount, nominal, x, link_alpha, x);
  filter(opt.filter, opt.boundary).apply(x, x);
  return x;
}

LinkAnalysis RecordAnalyzer::tangential(const AccelerometerMount& mount, std::span<const double> reading,
                                        const ChannelOptions& opt) {
  require_axis(mount, SensorAxis::tangential);
  LinkAnalysis out;
  out.link = mount.link;
  out.alpha_rad_s2 = converted(mount, reading, {}, opt);
  // Onto the crank-angle grid; integrate each revolution.
  const std::size_t N = grid_.points_per_rev();
  out.points_per_rev = N;
  out.revolutions = grid_.revolutions();
  out.first_revolution = grid_.first_revolution();
  out.alpha_grid = grid_.resample(out.alpha_rad_s2);
  out.omega_grid.resize(out.alpha_grid.size());
  PeriodicIntegrator integrator(N);
  const double turns = link_turns_per_crank_turn(rig_, mount.link);
  for (std::size_t r = 0; r < out.revolutions; ++r) {
    const std::size_t at = r * N;
    integrator.integrate(opt.integration, std::span(out.alpha_grid).subspan(at, N),
                         std::span(speed_grid_).subspan(at, N), turns, std::span(out.omega_grid).subspan(at, N));
  }
  out.alpha = guarded_average(out.alpha_grid, out.revolutions, N, opt.guard_revolutions);
  out.omega = guarded_average(out.omega_grid, out.revolutions, N, opt.guard_revolutions);
  return out;
}

NormalChannelAnalysis RecordAnalyzer::normal(const AccelerometerMount& mount, std::span<const double> reading,
                                             std::span<const double> link_alpha, const ChannelOptions& opt) {
  require_axis(mount, SensorAxis::normal);
  NormalChannelAnalysis out;
  out.points_per_rev = grid_.points_per_rev();
  out.revolutions = grid_.revolutions();
  out.omega_sq_grid = grid_.resample(converted(mount, reading, link_alpha, opt));
  out.omega_sq = guarded_average(out.omega_sq_grid, out.revolutions, out.points_per_rev, opt.guard_revolutions);
  return out;
}

}  // namespace fourbar
