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
// (docs/fit.md "Newton shooting finds it").
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
  // a run of the fit's kind (nominal start at crank 0, pin on the wall), turns
  // 20 … 20 + STARTS: does it find the period-2 orbit the recording took, or
  // another, from the model's usual, irregular motion? Forward differences
  // of 1e-7 in the scaled state; a full step, halved up to 10 times while
  // |G| does not fall; converged at |G| < 1e-9.
  const int starts = argc > 7 ? std::atoi(argv[7]) : 0;
  if (starts <= 0) return 0;
  if (t0 != 0.0) {
    std::fprintf(stderr, "newton: the truth's start is not at crank 0\n");
    return 1;
  }
  auto to_state = [&](double t, const State& d) {  // scaled deviations → absolute angles and rates
    const NominalMotion n = solve_motion(rig, crank.at(t));
    const double th3 = std::atan2(n.pose.u3.y, n.pose.u3.x) + d[0] * ang, th4 = std::atan2(n.pose.u4.y, n.pose.u4.x) + d[1] * ang;
    return State{th3, th4, n.omega3_rad_s + d[2] * w * ang, n.omega4_rad_s + d[3] * w * ang};
  };
  auto two_turns = [&](const State& d, State& out) {  // P² in scaled deviations at crank 0 (t = 0)
    std::vector<State> xs;
    if (!run_for(0.0, to_state(0.0, d), xs, 2)) return false;
    out = xs[1];
    return true;
  };
  std::vector<State> chaotic;
  {
    ClearanceSimulator sim(model, crank, s);
    sim.start_nominal(0.0);
    for (int k = 1; k <= 20 + starts; ++k) {
      sim.advance_to(k * T);
      if (k <= 20) continue;
      const LinkMotion l = sim.current_links();
      const NominalMotion n = solve_motion(rig, crank.at(k * T));
      chaotic.push_back({std::atan2(cross(n.pose.u3, l.u3), dot(n.pose.u3, l.u3)) / ang,
                         std::atan2(cross(n.pose.u4, l.u4), dot(n.pose.u4, l.u4)) / ang, (l.omega3_rad_s - n.omega3_rad_s) / (w * ang),
                         (l.omega4_rad_s - n.omega4_rad_s) / (w * ang)});
    }
  }
  // The recorded orbit's two turn-start states at crank 0 (t0 = 0 above:
  // every turn start is at crank 0), in the same units.
  std::vector<State> recorded;
  run(t0, star, recorded);
  const State orbit_a = recorded[recorded.size() - 1], orbit_b = recorded[recorded.size() - 2];
  int converged = 0, to_recorded = 0, stable = 0;
  for (const State& x0 : chaotic) {
    State x = x0, px{};
    if (!two_turns(x, px)) continue;
    auto g_of = [&](const State& a, const State& pa) {
      State g{};
      for (std::size_t i = 0; i < 4; ++i) g[i] = pa[i] - a[i];
      return g;
    };
    auto norm = [](const State& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]); };
    State g = g_of(x, px);
    bool ok = true;
    for (int it = 0; it < 30 && norm(g) > 1e-9 && ok; ++it) {
      Eigen::Matrix4d J;
      for (int j = 0; j < 4; ++j) {
        State xj = x, pj{};
        xj[static_cast<std::size_t>(j)] += 1e-7;
        if (!two_turns(xj, pj)) { ok = false; break; }
        const State gj = g_of(xj, pj);
        for (int i = 0; i < 4; ++i) J(i, j) = (gj[static_cast<std::size_t>(i)] - g[static_cast<std::size_t>(i)]) / 1e-7;
      }
      if (!ok) break;
      const Eigen::Vector4d step = J.fullPivLu().solve(-Eigen::Vector4d(g[0], g[1], g[2], g[3]));
      double lambda = 1;
      bool improved = false;
      for (int h = 0; h < 10; ++h, lambda /= 2) {
        State xn = x, pn{};
        for (int i = 0; i < 4; ++i) xn[static_cast<std::size_t>(i)] += lambda * step(i);
        if (!two_turns(xn, pn)) continue;
        const State gn = g_of(xn, pn);
        if (norm(gn) < norm(g)) { x = xn, g = gn, improved = true; break; }
      }
      if (!improved) ok = false;
    }
    if (!ok || norm(g) > 1e-9) continue;
    ++converged;
    const double d = std::min(dist(x, orbit_a), dist(x, orbit_b));
    if (d < 1e-3) ++to_recorded;  // distinct orbits lie ≥ 1 apart in these units
    std::vector<State> xs;
    if (run(0.0, to_state(0.0, x), xs) && lag2_ratio(xs) < 1e-3) ++stable;
    std::printf("newton from chaotic turn start: |G| %.1e, distance to the recorded orbit %.3g, period 2 over %d turns: %s\n", norm(g), d,
                turns, lag2_ratio(xs) < 1e-3 ? "yes" : "no");
  }
  std::printf("newton: %d of %zu starts converged, %d to the recorded orbit, %d stay on their orbit (stable)\n", converged,
              chaotic.size(), to_recorded, stable);
  return 0;
}
