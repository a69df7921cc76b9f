// ChunkedAnalysis's result assembly (chunked_analysis.hpp): the guard
// revolutions held back at a segment's ends, each committed revolution into
// the observer, the kept grids and the averages (clipped revolutions left
// out), and, after acquire, the finished RecordingAnalysis: averages, RMS
// values, spectra, the normal channels' check, warnings.
#include "analyze/chunked_analysis.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "common/statistics.hpp"

namespace fourbar {

void ChunkedAnalysis::accept(Pending&& rev) {
  const std::size_t guard = result_.options.guard_revolutions;
  if (guard == 0) return commit(rev, true);
  guard_queue_.push_back(std::make_unique<Pending>(std::move(rev)));
  if (guard_queue_.size() > guard) {
    commit(*guard_queue_.front(), !guard_queue_.front()->leading_guard);
    guard_queue_.pop_front();
  }
}

void ChunkedAnalysis::commit(Pending& rev, bool averaged) {
  const bool clipped = rev.number < clipped_.size() && clipped_[rev.number];
  if (averaged && clipped) ++result_.revolutions_clipped;
  averaged = averaged && !clipped;
  AnalyzedRevolution out;
  out.number = rev.number;
  out.averaged = averaged;
  out.crank_speed_rad_s = rev.speed;
  hold_for_repeat(rev, averaged);
  if (averaged) speed_avg_->add(rev.speed);
  if (result_.options.keep_revolutions) result_.revolution_numbers.push_back(rev.number);
  for (std::size_t j = 0; j < channels_.links.size(); ++j) {
    const bool coupler = channels_.links[j].link == SensedLink::coupler;
    LinkResult& lr = coupler ? *result_.coupler : *result_.rocker;
    (coupler ? out.alpha3_rad_s2 : out.alpha4_rad_s2) = rev.alpha[j];
    (coupler ? out.omega3_rad_s : out.omega4_rad_s) = rev.omega[j];
    if (result_.options.keep_revolutions) {
      lr.alpha_grid.insert(lr.alpha_grid.end(), rev.alpha[j].begin(), rev.alpha[j].end());
      lr.omega_grid.insert(lr.omega_grid.end(), rev.omega[j].begin(), rev.omega[j].end());
    }
    if (!averaged) continue;
    alpha_avg_[j].add(rev.alpha[j]);
    omega_avg_[j].add(rev.omega[j]);
    if (!rev.omega_sq[j].empty()) {
      normal_avg_[j].add(rev.omega_sq[j]);
      std::vector<double> sq(rev.omega[j].size());
      for (std::size_t k = 0; k < sq.size(); ++k) sq[k] = rev.omega[j][k] * rev.omega[j][k];
      omega_sq_avg_[j].add(sq);
    }
  }
  if (observer_) observer_->on_revolution(out);
}

void ChunkedAnalysis::hold_for_repeat(const Pending& rev, bool averaged) {
  // Turns kTurnRepeatEdgeTurns revolutions before this one are clear of the
  // segment's end: into the measure, in order; a turn missing between two
  // (clipped, a guard) breaks the lags' pairs.
  while (!repeat_held_.empty() && rev.number >= repeat_held_.front().number + kTurnRepeatEdgeTurns) {
    HeldTurn& h = repeat_held_.front();
    const bool follows = repeat_last_added_ && *repeat_last_added_ + 1 == h.number;
    for (std::size_t j = 0; j < alpha_repeat_.size(); ++j) {
      if (!follows) alpha_repeat_[j].gap();
      alpha_repeat_[j].add(h.alpha[j]);
    }
    repeat_last_added_ = h.number;
    repeat_held_.pop_front();
  }
  if (averaged && rev.index_in_segment >= kTurnRepeatEdgeTurns) repeat_held_.push_back({rev.number, rev.alpha});
}

void ChunkedAnalysis::finish() {
  if (!planned_) return;
  end_segment();
  RecordingAnalysis& r = result_;
  r.revolutions = speed_avg_->revolutions();
  if (r.revolutions == 0)
    throw InputError("analyze: no revolution left to average (" + std::to_string(r.options.guard_revolutions) +
                     " guard revolutions at each segment end, " + std::to_string(r.revolutions_clipped) +
                     " clipped); give fewer --guard-revolutions or record longer");
  r.crank_speed_rad_s = speed_avg_->result();
  r.mean_crank_speed_rad_s = 0;
  for (double w : r.crank_speed_rad_s.mean) r.mean_crank_speed_rad_s += w / double(r.grid_points_per_rev);
  r.spectra.segments = spectra_.front()->segments();
  if (r.spectra.segments == 0)
    r.warnings.push_back("no spectrum: every pulse-train segment is shorter than one spectrum segment of " +
                         std::to_string(r.spectra.segment_length) + " samples");
  if (r.revolutions_clipped > 0)
    r.warnings.push_back(std::to_string(r.revolutions_clipped) +
                         " clipped revolutions left out of the averages (a sample hit the input range)");
  for (std::size_t j = 0; j < channels_.links.size(); ++j) {
    LinkResult& lr = channels_.links[j].link == SensedLink::coupler ? *r.coupler : *r.rocker;
    lr.alpha_rad_s2 = alpha_avg_[j].result();
    lr.omega_rad_s = omega_avg_[j].result();
    lr.alpha_rms_rad_s2 = rms(lr.alpha_rad_s2.mean);
    lr.omega_rms_rad_s = rms(lr.omega_rad_s.mean);
    lr.alpha_std_rms_rad_s2 = rms(lr.alpha_rad_s2.std);
    lr.omega_std_rms_rad_s = rms(lr.omega_rad_s.std);
    lr.alpha_amplitude = spectra_[j]->amplitude();
    lr.alpha_repeat = alpha_repeat_[j].result();
    if (lr.normal) {
      lr.normal->omega_sq_rad2_s2 = normal_avg_[j].result();
      for (double w2 : lr.normal->omega_sq_rad2_s2.mean) lr.normal->omega_abs_rad_s.push_back(std::sqrt(std::max(0.0, w2)));
      lr.normal->omega_sq_integrated_rad2_s2 = omega_sq_avg_[j].result().mean;
      std::vector<double> diff(r.grid_points_per_rev);
      for (std::size_t k = 0; k < diff.size(); ++k)
        diff[k] = lr.normal->omega_sq_rad2_s2.mean[k] - lr.normal->omega_sq_integrated_rad2_s2[k];
      lr.normal->rel_rms_difference = rms(diff) / rms(lr.normal->omega_sq_integrated_rad2_s2);
    }
  }
}

}  // namespace fourbar
