#pragma once
// Periodic motions of the three-mode clearance model at a constant crank
// speed, found by Newton shooting on the turn map (docs/fit.md "A periodic
// recording": a model can have a stable motion that repeats every p turns
// beside its usual irregular one, and not reach it from its start).
//
// The turn map P takes the links' deviations from the nominal mechanism at
// crank angle 0, x = (δ3, δ4 over ξ/l3; their rates over |ω2|·ξ/l3), to the
// same one turn later, the model started there in free flight. A period-p
// orbit is a root of G(x) = P^p(x) − x. Newton's iteration uses a
// forward-difference Jacobian of G and halves its step while |G| does not
// fall; it is started from the turn starts of the model's own run (nominal
// start at crank 0, as the report's and the fit's runs), so it looks where
// the model's motion goes. An orbit is kept as stable when a run started on
// it still repeats every p turns after `check_turns` turns (the maps are
// non-smooth at impacts, so this is checked by running, not by the
// Jacobian's eigenvalues).

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "mechanism/rig.hpp"
#include "sim/drive/crank_motion.hpp"
#include "sim/three_mode/model.hpp"
#include "sim/three_mode/settings.hpp"

namespace fourbar {

/// Newton shooting on a map of R^n: settings and the generic iteration
/// (tested on closed forms, tests/sim/studies/test_periodic_orbit.cpp).
struct ShootingSettings {
  double difference_step = 1e-7;  ///< forward-difference step, in the state's (scaled) units
  double tolerance = 1e-9;        ///< converged when |P^p(x) − x| is below this
  int max_iterations = 30;
  int max_halvings = 10;          ///< step halvings per iteration while |G| does not fall
};

/// One application of a map: false when it cannot be evaluated at x (then
/// Newton treats the point as outside the map's domain).
using StateMap = std::function<bool(const Eigen::VectorXd& x, Eigen::VectorXd& image)>;

/// A root of map(x) − x from x0 (map is P^p for a period-p orbit), or none
/// when Newton does not converge.
std::optional<Eigen::VectorXd> shoot_fixed_point(const StateMap& map, Eigen::VectorXd x0, const ShootingSettings& s = {});

/// The three-mode model's turn map at a constant crank speed.
class TurnMap {
 public:
  TurnMap(const Rig& rig, double clearance_m, double crank_speed_rad_s, const ClearanceSettings& settings);
  /// The turn starts x_1 … x_turns of a run started in free flight on x at crank 0; false when
  /// x is outside the bushing or the run fails.
  bool run(const Eigen::Vector4d& x, int turns, std::vector<Eigen::Vector4d>& starts) const;
  /// The turn starts of the model's own run (nominal start at crank 0): `count` of them after `skip` turns.
  std::vector<Eigen::Vector4d> own_turns(int skip, int count) const;

 private:
  Eigen::Vector4d deviation(double time_s, const LinkMotion& links) const;
  ClearanceModel model_;
  ConstantSpeedCrank crank_;
  ClearanceSettings settings_;
  double speed_rad_s_, angle_scale_rad_;  ///< |ω2| and ξ/l3
};

struct OrbitSearchSettings {
  int period = 2;        ///< p, turns
  int starts = 60;       ///< Newton starts: the model's own turn starts after `skip_turns`
  int skip_turns = 20;   ///< its start-up, as the report's warm-up
  int check_turns = 40;  ///< a found orbit is stable when a run on it still repeats after this many turns
  /// Repeats: the median over the run's second half of |x_{k+p} − x_k| below this, in the
  /// scaled units (distinct orbits lie about 1 apart; a stable one repeats to ~1e-6).
  double repeat_distance = 1e-3;
  bool stop_at_first_stable = false;  ///< end the search at the first stable orbit (`starts` then counts the starts used)
  /// Newton's trial states farther than this from 0 (scaled units) are
  /// outside the map: the model's own turn starts lie within ~15, and a
  /// near-singular Jacobian's step once sent a trial to rates of 1e8, where
  /// one turn took minutes to integrate.
  double max_state_norm = 100;
  ShootingSettings shooting;
};

struct FoundOrbit {
  Eigen::Vector4d start;  ///< x at crank 0 on the orbit
  bool stable = false;
  double repeat_distance = 0;  ///< of the run on it (stable: below the setting's)
};

struct OrbitSearchResult {
  int starts = 0;                 ///< Newton starts tried
  int converged = 0;              ///< of them, converged onto an orbit of least period p
  int shorter = 0;                ///< converged onto an orbit of a shorter period (not kept)
  std::vector<FoundOrbit> orbits; ///< the distinct orbits found (one entry per orbit, each of its p turn starts counted once)
  int stable_from = 0;            ///< starts that converged onto a stable orbit
  bool any_stable() const;
};

/// Newton shooting for period-p orbits of the turn map from the model's own turns.
OrbitSearchResult find_periodic_orbits(const TurnMap& map, const OrbitSearchSettings& s);

/// Median over the second half of `starts` of |x_{k+p} − x_k|.
double repeat_distance(const std::vector<Eigen::Vector4d>& starts, int period);

}  // namespace fourbar
