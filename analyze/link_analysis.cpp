#include "analyze/link_analysis.hpp"

#include "analyze/angle_resampler.hpp"

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

}  // namespace

LinkAnalysis analyze_tangential_channel(const Rig& rig, const AccelerometerMount& mount, const CrankTrack& crank,
                                        double fs, std::span<const double> reading, const LinkAnalysisOptions& opt) {
  LinkAnalysis out;
  out.link = mount.link;
  const std::size_t n = reading.size();
  // Sensor reading → α per sample (restore first when AC-coupled).
  out.alpha_rad_s2.resize(n);
  restore_dc_coupled_reading(rig, mount, crank, fs, reading, out.alpha_rad_s2);
  angular_acceleration_from_tangential(rig, mount, crank, out.alpha_rad_s2, out.alpha_rad_s2);
  FftFilter filter(opt.filter, fs, n, opt.boundary);
  filter.apply(out.alpha_rad_s2, out.alpha_rad_s2);

  // Onto the crank-angle grid; integrate each revolution.
  const RevolutionResampler grid(crank.angle_rad, opt.points_per_rev, opt.grid_start_rad);
  const std::size_t N = opt.points_per_rev;
  out.points_per_rev = N;
  out.revolutions = grid.revolutions();
  out.first_revolution = grid.first_revolution();
  out.alpha_grid = grid.resample(out.alpha_rad_s2);
  out.crank_speed_grid = grid.resample(crank.speed_rad_s);
  out.omega_grid.resize(out.alpha_grid.size());
  PeriodicIntegrator integrator(N);
  const double turns = link_turns_per_crank_turn(rig, mount.link);
  for (std::size_t r = 0; r < out.revolutions; ++r) {
    const std::size_t at = r * N;
    integrator.integrate(opt.integration, std::span(out.alpha_grid).subspan(at, N),
                         std::span(out.crank_speed_grid).subspan(at, N), turns,
                         std::span(out.omega_grid).subspan(at, N));
  }
  out.alpha = guarded_average(out.alpha_grid, out.revolutions, N, opt.guard_revolutions);
  out.omega = guarded_average(out.omega_grid, out.revolutions, N, opt.guard_revolutions);
  return out;
}

NormalChannelAnalysis analyze_normal_channel(const Rig& rig, const AccelerometerMount& mount, const CrankTrack& crank,
                                             double fs, std::span<const double> reading,
                                             std::span<const double> link_alpha, const LinkAnalysisOptions& opt) {
  const std::size_t n = reading.size();
  std::vector<double> w2(n);
  restore_dc_coupled_reading(rig, mount, crank, fs, reading, w2);
  angular_speed_squared_from_normal(rig, mount, crank, w2, link_alpha, w2);
  FftFilter filter(opt.filter, fs, n, opt.boundary);
  filter.apply(w2, w2);
  const RevolutionResampler grid(crank.angle_rad, opt.points_per_rev, opt.grid_start_rad);
  NormalChannelAnalysis out;
  out.points_per_rev = opt.points_per_rev;
  out.revolutions = grid.revolutions();
  out.omega_sq_grid = grid.resample(w2);
  out.omega_sq = guarded_average(out.omega_sq_grid, out.revolutions, opt.points_per_rev, opt.guard_revolutions);
  return out;
}

}  // namespace fourbar
