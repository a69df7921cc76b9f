#pragma once
// Pipeline stage "nominal run": the scene's requested outputs over its crank
// revolutions, at constant crank speed, sampled uniformly in crank angle.

#include <string>
#include <vector>

#include "sim/scene.hpp"

namespace fourbar {

/// A table of per-sample series, column-major: columns[0] is crank_deg.
struct SeriesTable {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  std::size_t rows() const { return columns.empty() ? 0 : columns[0].size(); }
};

/// Work counters of a run, so tests can see that nothing unrequested ran.
struct NominalRunStats {
  std::size_t kinematics_evaluations = 0;
  std::size_t load_evaluations = 0;
  std::size_t energy_evaluations = 0;
};

/// Evaluates the nominal mechanism at revolutions·samples_per_revolution + 1
/// crank angles (first and last sample one whole number of turns apart).
SeriesTable run_nominal(const Scene& scene, NominalRunStats* stats = nullptr);

}  // namespace fourbar
