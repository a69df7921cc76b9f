#include "analyze/link_analysis.hpp"

#include <algorithm>
#include <sstream>

#include "analyze/known_response.hpp"
#include "common/error.hpp"
#include "common/reused_vector.hpp"

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

RecordAnalyzer::RecordAnalyzer(const Rig& rig, const CrankTrack& crank, double fs, const AngleGridSpec& grid,
                               std::shared_ptr<const RigTables> tables)
    : rig_(rig),
      crank_(crank),
      fs_(fs),
      direction_(grid.direction < 0 ? -1.0 : 1.0),
      grid_(crank.angle_rad, grid.grid_points_per_rev, grid.start_rad, grid.direction),
      tables_(std::move(tables)) {
  check_crank_track(crank);
  speed_grid_ = grid_.resample(crank.speed_rad_s);
  if (!tables_) tables_ = std::make_shared<const RigTables>(rig);
}

void RecordAnalyzer::reset(const CrankTrack& crank) {
  check_crank_track(crank);
  if (crank.size() != crank_.size()) filters_.clear();  // made for the old length
  crank_ = crank;
  grid_.plan(crank.angle_rad);
  grid_.resample(crank.speed_rad_s, speed_grid_);
}

void RecordAnalyzer::filter(const FilterSpec& spec, Boundary boundary, std::span<double> x) {
  auto cached = std::find_if(filters_.begin(), filters_.end(),
                             [&](const CachedFilter& c) { return c.boundary == boundary && same(c.spec, spec); });
  if (cached == filters_.end()) {
    std::shared_ptr<RealFft> shared;  // another filter's transform, if of the same length
    for (const CachedFilter& c : filters_)
      if (c.boundary == boundary) shared = c.filter->transform();
    filters_.push_back({spec, boundary, std::make_unique<FftFilter>(spec, fs_, crank_.size(), boundary, shared)});
    cached = filters_.end() - 1;
  }
  cached->filter->apply(x, x);
}

std::vector<double> RecordAnalyzer::converted(const AccelerometerMount& mount, std::span<const double> reading,
                                              std::span<const double> link_alpha) {
  std::vector<double> x(reading.size());
  converted(mount, reading, link_alpha, x);
  return x;
}

void RecordAnalyzer::converted(const AccelerometerMount& mount, std::span<const double> reading,
                               std::span<const double> link_alpha, std::span<double> out) {
  if (mount.sample_delay_s != 0 || !mount.known_response.empty()) {
    // What the manifest states of the channel's timing and analog path is
    // undone first (known_response.hpp).
    std::vector<double> aligned(reading.begin(), reading.end());
    undo_known_response(aligned, fs_, mount.sample_delay_s, mount.known_response);
    convert_reading(rig_, mount, (*tables_)[mount.link], crank_, fs_, aligned, link_alpha, out);
    return;
  }
  convert_reading(rig_, mount, (*tables_)[mount.link], crank_, fs_, reading, link_alpha, out);
}

LinkGrids RecordAnalyzer::on_grid(SensedLink link, std::span<const double> alpha, PeriodicMethod method,
                                  bool keep_slope) {
  LinkGrids out;
  on_grid(link, alpha, method, keep_slope, out);
  return out;
}

void RecordAnalyzer::on_grid(SensedLink link, std::span<const double> alpha, PeriodicMethod method, bool keep_slope,
                             LinkGrids& out) {
  const std::size_t N = grid_.grid_points_per_rev();
  out.grid_points_per_rev = N;
  out.revolutions = grid_.revolutions();
  out.first_revolution = grid_.first_revolution();
  grid_.resample(alpha, out.alpha_grid);
  resize_reusing(out.omega_grid, out.alpha_grid.size());
  // Integrate in ψ = direction·θ2 (increasing): dω/dψ = α/(direction·ω2),
  // and over one turn Δθ_link/Δψ = direction·turns.
  PeriodicIntegrator integrator(N);
  std::vector<double> psi_speed(N);
  const double turns = direction_ * link_turns_per_crank_turn(rig_, link);
  for (std::size_t r = 0; r < out.revolutions; ++r) {
    const std::size_t at = r * N;
    for (std::size_t k = 0; k < N; ++k) psi_speed[k] = direction_ * speed_grid_[at + k];
    integrator.integrate(method, std::span(out.alpha_grid).subspan(at, N), psi_speed, turns,
                         std::span(out.omega_grid).subspan(at, N), keep_slope);
  }
}

LinkAnalysis RecordAnalyzer::tangential(const AccelerometerMount& mount, std::span<const double> reading,
                                        const ChannelOptions& opt) {
  require_axis(mount, SensorAxis::tangential);
  LinkAnalysis out;
  out.link = mount.link;
  out.alpha_rad_s2 = converted(mount, reading);
  filter(opt.filter, opt.boundary, out.alpha_rad_s2);
  static_cast<LinkGrids&>(out) = on_grid(mount.link, out.alpha_rad_s2, opt.integration, opt.keep_slope);
  out.alpha = guarded_average(out.alpha_grid, out.revolutions, out.grid_points_per_rev, opt.guard_revolutions);
  out.omega = guarded_average(out.omega_grid, out.revolutions, out.grid_points_per_rev, opt.guard_revolutions);
  return out;
}

NormalChannelAnalysis RecordAnalyzer::normal(const AccelerometerMount& mount, std::span<const double> reading,
                                             std::span<const double> link_alpha, const ChannelOptions& opt) {
  require_axis(mount, SensorAxis::normal);
  NormalChannelAnalysis out;
  out.grid_points_per_rev = grid_.grid_points_per_rev();
  out.revolutions = grid_.revolutions();
  std::vector<double> x = converted(mount, reading, link_alpha);
  filter(opt.filter, opt.boundary, x);
  out.omega_sq_grid = grid_.resample(x);
  out.omega_sq = guarded_average(out.omega_sq_grid, out.revolutions, out.grid_points_per_rev, opt.guard_revolutions);
  return out;
}

}  // namespace fourbar
