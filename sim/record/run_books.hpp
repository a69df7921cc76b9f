#pragma once
// What a clearance simulator records as its run passes sample times, contact
// events and turn boundaries: the requested samples, the impacts (contacts),
// the revolution records with their per-turn α3 statistics and the run's
// diagnostics. Written once for the three-mode and the compliant simulator;
// each gives what only it knows (the state at a turn's start, α3 at a time,
// a sample) as a function, and the books never change the run.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "common/units.hpp"
#include "sim/drive/crank_motion.hpp"
#include "sim/record/local_clock.hpp"
#include "sim/record/revolution_clock.hpp"
#include "sim/record/run_records.hpp"

namespace fourbar {

struct RunBooks {
  std::vector<double> sample_times;  ///< absolute
  std::size_t next_sample = 0;
  std::vector<ClearanceSample> samples;
  std::vector<ImpactRecord> impacts;  ///< the compliant model: one per contact
  std::vector<RevolutionRecord> revolutions;
  bool revolutions_on = false;
  int stats_per_turn = 0;   ///< α3-deviation samples per turn (0 = off)
  long long next_stat = 0;  ///< index of the next one, counted from the revolution origin
  double rev_origin_rad = 0;
  int rev_dir = 1;
  ClearanceDiagnostics diag;

  RevolutionClock revolution_clock() const { return {rev_origin_rad, rev_dir}; }
  /// The revolution holding local `time`.
  int revolution_of(const CrankMotion& crank, const LocalClock& clock, double time) const {
    return revolution_clock().index_at(crank, clock.absolute(time));
  }
  /// Absolute start time of revolution k.
  double revolution_start(const CrankMotion& crank, int k) const { return revolution_clock().start_s(crank, k); }
  /// Record k, opening the records up to it.
  RevolutionRecord& revolution(const CrankMotion& crank, int k) {
    return revolution_clock().record(crank, revolutions, k);
  }

  /// Books the local interval [ta, tb] spent in contact (`following`) or in
  /// free flight, in the diagnostics and in every revolution it overlaps;
  /// record_start_state(r) is called once for each turn r whose start it reaches.
  template <class RecordStartState>
  void book_interval(const CrankMotion& crank, const LocalClock& clock, double ta, double tb, bool following,
                     RecordStartState&& record_start_state) {
    (following ? diag.time_following_s : diag.time_free_s) += tb - ta;
    if (!revolutions_on) return;
    int k = std::max(0, revolution_of(crank, clock, ta));
    double a = ta;
    for (;;) {
      RevolutionRecord& r = revolution(crank, k);
      const double end = clock.local(r.end_time_s);
      const double b = std::min(tb, end);
      if (b > a) (following ? r.following_time_s : r.free_time_s) += b - a;
      if (end > tb) break;
      // Reached the start of turn k + 1: record its state once.
      RevolutionRecord& next = revolution(crank, k + 1);
      if (!next.has_start_state) record_start_state(next);
      a = end;
      ++k;
      if (a >= tb) break;
    }
  }

  /// Local time of the i-th α3-deviation sample (i counted from the revolution origin).
  double stat_time(const CrankMotion& crank, const LocalClock& clock, long long i) const {
    return clock.local(
        crank.time_at_angle(rev_origin_rad + rev_dir * units::kTwoPi * static_cast<double>(i) / stats_per_turn));
  }

  /// Adds the α3-deviation samples up to local `up_to` to their turns'
  /// RMS; alpha3_deviation_at(ts) gives α3 − α3,nominal at local ts, or
  /// nothing for a time before the run's start.
  template <class Deviation>
  void emit_statistics(const CrankMotion& crank, const LocalClock& clock, double up_to, Deviation&& alpha3_deviation_at) {
    if (stats_per_turn <= 0) return;
    for (double ts = stat_time(crank, clock, next_stat); ts <= up_to; ts = stat_time(crank, clock, ++next_stat)) {
      const std::optional<double> deviation = alpha3_deviation_at(ts);
      if (!deviation) continue;  // before the start
      const double d = *deviation;
      RevolutionRecord& r = revolution(crank, static_cast<int>(next_stat / stats_per_turn));
      r.alpha3_deviation_sum_sq += d * d;
      ++r.alpha3_deviation_samples;
      r.alpha3_deviation_rms_rad_s2 = std::sqrt(r.alpha3_deviation_sum_sq / r.alpha3_deviation_samples);
    }
  }

  /// Takes the requested samples up to local `up_to`; sample_at(t) gives the
  /// sample at absolute time t.
  template <class SampleAt>
  void emit_samples(const LocalClock& clock, double up_to, SampleAt&& sample_at) {
    while (next_sample < sample_times.size() && clock.local(sample_times[next_sample]) <= up_to) {
      samples.push_back(sample_at(sample_times[next_sample]));
      ++next_sample;
    }
  }
};

}  // namespace fourbar
