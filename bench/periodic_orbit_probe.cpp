// Is a periodic motion the virtual rig recorded a stable orbit of the
// three-mode model, and how far from it does the model still fall onto it?
// (docs/fit.md "A periodic recording": the fit's runs of the e = 0.8
// session never reached the period-2 motion of its 250 rpm, 0.254 mm
// recording.) Reads the recording's noise-free truth (`fourbar virtual-rig`
// writes REC.truth.csv: time_s, theta3_rad, omega3_rad_s, theta4_rad,
// omega4_rad_s), starts the model in free flight from the truth's state at a
// crank angle, and follows the turn-start states x_k (δ3, δ4 over ξ/l3, their
// rates over ω2·ξ/l3) for TURNS turns. A period p shows as
// |x_{k+p} − x_k| ≪ |x_{k+1} − x_k|; printed: the median over the last half of
// the turns of |x_{k+2} − x_k| / |x_{k+1} − x_k|. Then the same from starts
// perturbed by ε (in those units) in random directions: the share that still
// ends on the period-2 motion (ratio < 1e-3), per ε. With NEWTON_STARTS,
// Newton shooting for period-2 orbits from the model's own irregular turns
// (sim/studies/periodic_orbit.hpp, the search the fit runs; docs/fit.md
// "Newton shooting finds it").
//
//   bench/periodic_orbit_probe TRUTH.csv RPM CLEARANCE_MM RESTITUTION [TURNS] [DIRECTIONS] [NEWTON_STARTS]

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "common/units.hpp"
#include "mechanism/kinematics.hpp"
#include "sim/studies/periodic_orbit.hpp"
#include "sim/three_mode/simulator.hpp"

using namespace fourbar;

namespace {

struct TruthRow {
  double t, th3, w3, th4, w4;
};

std::vector<TruthRow> read_truth(const char* path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream hs(line);
  for (std::string c; std::getline(hs, c, ',');) names.push_back(c);
  auto col = [&](const char* n) { return static_cast<std::size_t>(std::find(names.begin(), names.end(), n) - names.begin()); };
  const std::size_t it = col("time_s"), i3 = col("theta3_rad"), iw3 = col("omega3_rad_s"), i4 = col("theta4_rad"), iw4 = col("omega4_rad_s");
  std::vector<TruthRow> rows;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::stringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) v.push_back(std::atof(c.c_str()));
    if (v.size() > std::max({it, i3, iw3, i4, iw4})) rows.push_back({v[it], v[i3], v[iw3], v[i4], v[iw4]});
  }
  return rows;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s TRUTH.csv RPM CLEARANCE_MM RESTITUTION [TURNS] [DIRECTIONS]\n", argv[0]);
    return 2;
  }
  const std::vector<TruthRow> truth = read_truth(argv[1]);
  if (truth.empty()) {
    std::fprintf(stderr, "fourbar: %s: no rows with time_s, theta3_rad, omega3_rad_s, theta4_rad, omega4_rad_s; give the "
                 "REC.truth.csv that fourbar virtual-rig writes\n", argv[1]);
    return 2;
  }
  const double w = units::rpm_to_rad_s(std::atof(argv[2])), xi = std::atof(argv[3]) * 1e-3, e = std::atof(argv[4]);
  const int turns = argc > 5 ? std::atoi(argv[5]) : 40, directions = argc > 6 ? std::atoi(argv[6]) : 8;
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml");
  const ClearanceModel model(rig, xi);
  const ConstantSpeedCrank crank(0.0, w);
  ClearanceSettings s;
  s.restitution = e;
  s.tolerance = 1e-8;  // the virtual rig scene's
  const double T = units::kTwoPi / w, ang = xi / rig.coupler.length_m;
  using State = std::array<double, 4>;
  // Turn-start states of a run started in free flight at t0 from `start`.
  auto run_for = [&](double t0, State start, std::vector<State>& out, int n_turns) {
    ClearanceSimulator sim(model, crank, s);
    const NominalMotion nm = solve_motion(rig, crank.at(t0));
    (void)nm;
    LinkMotion lm{{std::cos(start[0]), std::sin(start[0])}, {std::cos(start[1]), std::sin(start[1])}, start[2], start[3]};
    try {
      sim.start_free(t0, lm);
    } catch (const std::exception&) {
      return false;
    }
    out.clear();
    for (int k = 1; k <= n_turns; ++k) {
      sim.advance_to(t0 + k * T);
      const LinkMotion l = sim.current_links();
      const NominalMotion n = solve_motion(rig, crank.at(t0 + k * T));
      out.push_back({std::atan2(cross(n.pose.u3, l.u3), dot(n.pose.u3, l.u3)) / ang,
                     std::atan2(cross(n.pose.u4, l.u4), dot(n.pose.u4, l.u4)) / ang, (l.omega3_rad_s - n.omega3_rad_s) / (w * ang),
                     (l.omega4_rad_s - n.omega4_rad_s) / (w * ang)});
    }
    return true;
  };
  auto run = [&](double t0, State start, std::vector<State>& out) { return run_for(t0, start, out, turns); };
  auto dist = [](const State& a, const State& b) {
    double d = 0;
    for (std::size_t i = 0; i < 4; ++i) d += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(d);
  };
  auto lag2_ratio = [&](const std::vector<State>& x) {
    std::vector<double> r;
    for (std::size_t k = x.size() / 2; k + 2 < x.size(); ++k) r.push_back(dist(x[k + 2], x[k]) / std::max(dist(x[k + 1], x[k]), 1e-300));
    std::sort(r.begin(), r.end());
    return r.empty() ? 1.0 : r[r.size() / 2];
  };
  // The truth's state at the first crank angle (0°, 30°, …) where a free-flight start is accepted.
  std::vector<State> x;
  double t0 = -1;
  State star{};
  for (int a = 0; a < 12 && t0 < 0; ++a) {
    const double t = T * a / 12.0;
    const auto row = std::min_element(truth.begin(), truth.end(), [&](const TruthRow& p, const TruthRow& q) { return std::abs(p.t - t) < std::abs(q.t - t); });
    const State st{row->th3, row->th4, row->w3, row->w4};
    if (run(row->t, st, x)) t0 = row->t, star = st;
  }
  if (t0 < 0) {
    std::fprintf(stderr, "no free-flight start accepted\n");
    return 1;
  }
  std::printf("start on the truth at t = %.6f s (crank %.1f deg): lag-2 / lag-1 of the turn-start states %.3g over turns %d-%d\n", t0,
              t0 / T * 360.0, lag2_ratio(x), turns / 2, turns);
  std::mt19937 gen(5);
  std::normal_distribution<double> g(0.0, 1.0);
  for (double eps : {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 3e-2, 0.1, 0.3}) {
    int periodic = 0, refused = 0;
    for (int d = 0; d < directions; ++d) {
      State dir{};
      double norm = 0;
      for (double& v : dir) v = g(gen), norm += v * v;
      norm = std::sqrt(norm);
      State st = star;
      st[0] += eps * ang * dir[0] / norm, st[1] += eps * ang * dir[1] / norm;
      st[2] += eps * w * ang * dir[2] / norm, st[3] += eps * w * ang * dir[3] / norm;
      if (!run(t0, st, x)) {
        ++refused;
        continue;
      }
      if (lag2_ratio(x) < 1e-3) ++periodic;
    }
    std::printf("eps %.0e: %d of %d on the period-2 motion after %d turns (%d starts refused: outside the bushing)\n", eps, periodic,
                directions - refused, turns, refused);
  }
  // Newton on G(x) = P²(x) − x (P: one turn) from the turn-start states of
  // a run of the fit's kind (nominal start at crank 0), turns 21 … 20 +
  // STARTS: does it find the period-2 orbit the recording took, or another,
  // from the model's usual, irregular motion?
  const int starts = argc > 7 ? std::atoi(argv[7]) : 0;
  if (starts <= 0) return 0;
  if (t0 != 0.0) {
    std::fprintf(stderr, "newton: the truth's start is not at crank 0\n");
    return 1;
  }
  // The recorded orbit's two turn-start states at crank 0 (t0 = 0 above:
  // every turn start is at crank 0), in the same units.
  std::vector<State> recorded;
  run(t0, star, recorded);
  const State orbit_a = recorded[recorded.size() - 1], orbit_b = recorded[recorded.size() - 2];
  std::printf("recorded orbit's turn starts at crank 0: (%.10g, %.10g, %.10g, %.10g) and (%.10g, %.10g, %.10g, %.10g)\n", orbit_a[0],
              orbit_a[1], orbit_a[2], orbit_a[3], orbit_b[0], orbit_b[1], orbit_b[2], orbit_b[3]);
  // sim/studies/periodic_orbit.hpp: the same search the fit runs.
  const TurnMap map(rig, xi, w, s);
  OrbitSearchSettings os;
  os.period = 2;
  os.starts = starts;
  os.skip_turns = 20;
  os.check_turns = turns;
  const OrbitSearchResult found = find_periodic_orbits(map, os);
  int to_recorded = 0;
  for (const FoundOrbit& o : found.orbits) {
    const State x{o.start(0), o.start(1), o.start(2), o.start(3)};
    const double d = std::min(dist(x, orbit_a), dist(x, orbit_b));
    to_recorded += d < 1e-3;
    std::printf("orbit: distance to the recorded orbit %.3g, repeats to %.2g over turns %d-%d: %s\n", d, o.repeat_distance,
                turns / 2, turns, o.stable ? "stable" : "unstable");
  }
  std::printf("newton: %d of %d starts converged onto %zu distinct period-2 orbits (%d onto shorter periods), %d of them "
              "the recorded one; %d starts reached a stable orbit\n",
              found.converged, found.starts, found.orbits.size(), found.shorter, to_recorded, found.stable_from);
  return 0;
}
