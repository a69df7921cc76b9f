#pragma once
// The fit's simulations, cached by (recording, e, μ) and computed in
// batches over the threads or MPI ranks of cluster/case_queue (described
// cases: each travels as its recording's name, the parameters and the
// simulation settings in exact hexadecimal, so a rank needs only the
// recordings' targets: simulate_described). The
// parameters are rounded to 1e-6 before they key the cache and before they
// are simulated, so a point asked for twice is simulated once and gives the
// same statistics.

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "fit/fit_model.hpp"
#include "fit/recording_target.hpp"

namespace fourbar {

struct SimulationSettings {
  int warmup_turns = 20;
  int simulated_turns = 50;
  double tolerance = 1e-8;
  unsigned threads = 1;
  FitModel model;  ///< the theory simulated (fit_model.hpp)
  /// Called after each simulation arrives (one call at a time, maybe from a
  /// worker thread): progress for `fourbar fit`; may be empty.
  std::function<void()> on_simulation;
};

/// A simulation's outcome: the statistics, or why the model failed there.
struct CachedSimulation {
  SimulatedStatistics statistics;
  std::string error;  ///< empty when it ran
};

class SimulationCache {
 public:
  SimulationCache(const std::vector<RecordingTarget>& targets, SimulationSettings settings);

  /// The parameters as simulated (rounded; μ = 0 and any μ with the smooth law map to smooth).
  static ContactParameters canonical(const ContactParameters& p);

  /// Makes sure every (recording, point) pair is simulated: the missing ones
  /// in one batch over the queue.
  void ensure(const std::vector<ContactParameters>& points);
  /// A simulated pair (ensure() first).
  const CachedSimulation& at(std::size_t recording, const ContactParameters& p) const;

  /// The simulation a case description names, among `targets` (by name),
  /// as encoded result bytes: what every rank computes for ensure(). A
  /// simulation that fails is a result (its reason); a description naming
  /// no target throws RunError.
  static std::string simulate_described(const std::vector<RecordingTarget>& targets, const std::string& description);

  int simulations() const { return simulations_; }
  /// Of these, run by this process (under MPI: rank 0's own share).
  int computed_here() const { return computed_here_; }
  long long turns_simulated() const { return turns_; }
  double compute_seconds() const { return compute_s_; }
  /// CPU time of the simulations computed by this process's threads (each
  /// timed on its thread's clock), and the wall time they would take on
  /// `threads` idle cores: each batch list-scheduled in queue order with
  /// those times (what the queue does when no other load competes). Under
  /// MPI the other ranks' cases are not timed.
  double simulation_cpu_seconds() const { return cpu_s_; }
  double idle_wall_seconds() const { return idle_wall_s_; }
  const std::vector<RecordingTarget>& targets() const { return targets_; }

 private:
  using Key = std::tuple<std::size_t, std::int64_t, std::int64_t>;
  static Key key(std::size_t recording, const ContactParameters& p);

  const std::vector<RecordingTarget>& targets_;
  SimulationSettings settings_;
  std::map<Key, CachedSimulation> cache_;
  int simulations_ = 0, computed_here_ = 0;
  long long turns_ = 0;
  double compute_s_ = 0, cpu_s_ = 0, idle_wall_s_ = 0;
};

}  // namespace fourbar
