// Stress grid of the linkage model (issue 25; the clearance model's is
// stress_clearance, the compliant model's stress_compliant): thesis_elastic
// rig, K = 1e10 N/m^1.5, one turn per case at tolerance 1e-10 over
// start 0°, 180° × clearance in B; A and B; A, B and O4 × ξ 0.025, 0.254, 1 mm
// × e 0.1, 0.5, 1 × μ 0, 0.3 × 100, 1000 rpm × rigid links or elastic coupler
// and rocker with 2 modes (--modes N for another count), each checked by
// tests/sim/linkage/linkage_stress_case.hpp (no NaN, no hang, energy residual
// below 1e-8 of the scale, penetration below the energy bound). Prints one
// line per failing case and a summary per axis value; then one long case:
// 4 + 4 modes, clearance in all three joints, 10 turns (the energy
// check over 10 turns).
//
//   stress_linkage [--quick] [--modes N] [--joints B|AB|ABO4] [--csv FILE] [--method bdf|adams]
//   stress_linkage --long   (the 10-turn case only)
//   (--joints: only that clearance set)

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "sim/linkage/linkage_stress_case.hpp"

using namespace fourbar;
using linkage_stress::Case;

int main(int argc, char** argv) {
  bool quick = false, long_only = false;
  int modes = 2;
  LinkageMethod method = LinkageMethod::bdf;
  std::string csv, only_joints;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--long")) long_only = true;
    else if (!std::strcmp(argv[i], "--modes") && i + 1 < argc) modes = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv = argv[++i];
    else if (!std::strcmp(argv[i], "--joints") && i + 1 < argc) only_joints = argv[++i];
    else if (!std::strcmp(argv[i], "--method") && i + 1 < argc && !std::strcmp(argv[i + 1], "adams")) method = LinkageMethod::adams, ++i;
    else if (!std::strcmp(argv[i], "--method") && i + 1 < argc && !std::strcmp(argv[i + 1], "bdf")) method = LinkageMethod::bdf, ++i;
    else {
      std::fprintf(stderr, "usage: stress_linkage [--quick | --long] [--modes N] [--joints B|AB|ABO4] [--csv FILE] [--method bdf|adams]\n");
      return 2;
    }
  }
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  using Joints = std::array<bool, kJoints>;
  const std::vector<Joints> joint_sets = {{false, true, false}, {true, true, false}, {true, true, true}};
  const std::vector<double> starts = quick ? std::vector<double>{0} : std::vector<double>{0, 180};
  const std::vector<double> xis = {25e-6, 0.254e-3, 1e-3}, es = {0.1, 0.5, 1.0}, mus = {0.0, 0.3},
                            rpms = {100, 1000};
  const std::vector<int> mode_counts = quick ? std::vector<int>{modes} : std::vector<int>{0, modes};
  std::ofstream out;
  if (!csv.empty()) {
    out.open(csv);
    out << "start_deg,joints,clearance_mm,restitution,friction,rpm,modes,ok,energy_residual,penetration_ratio,"
           "steps_per_turn,contacts,wall_s,failure\n";
  }
  int total = 0, failed = 0;
  double worst_energy = 0, worst_pen = 0, worst_steps = 0, wall = 0;
  std::map<std::string, std::pair<int, int>> by_axis;  // label -> (cases, failures)
  for (double st : long_only ? std::vector<double>{} : starts)
    for (const Joints& js : joint_sets)
      for (double xi : xis)
        for (double e : es)
          for (double mu : mus)
            for (double rpm : rpms)
              for (int m : mode_counts) {
                const std::string jn = std::string(js[0] ? "A" : "") + (js[1] ? "B" : "") + (js[2] ? "O4" : "");
                if (!only_joints.empty() && jn != only_joints) continue;
                Case c;
                c.start_deg = st;
                c.joints = js;
                c.clearance_m = xi;
                c.restitution = e;
                c.friction = mu;
                c.rpm = rpm;
                c.modes = m;
                c.method = method;
                const linkage_stress::Result r = linkage_stress::run_case(rig, c);
                ++total;
                failed += r.ok ? 0 : 1;
                worst_energy = std::max(worst_energy, r.energy_residual);
                worst_pen = std::max(worst_pen, r.penetration_ratio);
                worst_steps = std::max(worst_steps, r.max_steps_per_turn);
                wall += r.wall_seconds;
                for (const std::string& key :
                     {"joints " + jn, "xi " + std::to_string(xi * 1e3).substr(0, 5) + " mm", "modes " + std::to_string(m),
                      "rpm " + std::to_string(static_cast<int>(rpm))}) {
                  by_axis[key].first += 1;
                  by_axis[key].second += r.ok ? 0 : 1;
                }
                if (!r.ok) std::printf("FAIL %s: %s\n", c.label().c_str(), r.failure.c_str());
                if (out)
                  out << st << ',' << jn << ',' << xi * 1e3 << ',' << e << ',' << mu << ',' << rpm << ',' << m << ','
                      << (r.ok ? 1 : 0) << ',' << r.energy_residual << ',' << r.penetration_ratio << ','
                      << r.max_steps_per_turn << ',' << r.contacts << ',' << r.wall_seconds << ",\"" << r.failure
                      << "\"\n";
                std::fflush(stdout);
              }
  if (!long_only)
    std::printf("%d cases, %d failed; worst energy residual %.2e of the scale, deepest penetration %.3f of the "
              "bound, most steps per turn %.0f, %.0f s wall in all\n",
              total, failed, worst_energy, worst_pen, worst_steps, wall);
  for (const auto& [key, v] : by_axis) std::printf("  %-16s %3d cases, %d failed\n", key.c_str(), v.first, v.second);
  if (!quick && only_joints.empty()) {
    Case longrun;
    longrun.joints = {true, true, true};
    longrun.modes = 4;
    longrun.turns = 10;
    longrun.friction = 0.1;
    longrun.method = method;
    const linkage_stress::Result r = linkage_stress::run_case(rig, longrun);
    std::printf("10 turns, %s: %s, energy residual %.2e of the scale, %zu contacts, %.1f s wall\n",
                longrun.label().c_str(), r.ok ? "ok" : r.failure.c_str(), r.energy_residual, r.contacts,
                r.wall_seconds);
    failed += r.ok ? 0 : 1;
  }
  return failed == 0 ? 0 : 1;
}
