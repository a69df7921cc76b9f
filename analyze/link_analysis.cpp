#include "analyze/link_analysis.hpp"

#include "analyze/angle_resampler.hpp"

namespace fourbar {

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
  out.alpha = synchronous_average(out.alpha_grid, N);
  out.omega = synchronous_average(out.omega_grid, N);
  return out;
}

}  // namespace fourbar
