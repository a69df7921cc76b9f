// Stress grid of the compliant contact model (the three-mode model's is
// stress_clearance): thesis rig, ξ = 0.254 mm, start 0°, stiffness K =
// 1e6 … 1e10 N/m^1.5 × e 0.1 … 1 × wall friction μ 0, 0.3 × crank speed
// 100 … 1000 rpm, three turns each at the default tolerance 1e-10 (or
// --tolerance). A case
// passes when it reaches the end without an exception, every sample (1°)
// and diagnostic is finite, the steps per 1/8 turn stay below a bound (no
// hang), and the largest energy residual (mechanical + elastic energy vs
// crank work − damping − friction losses) stays below 1e-8 of the energy
// scale (no drift). The deepest penetration (relative to ξ) is reported:
// with a soft contact at speed the pin goes deeper than ξ, which is what
// that stiffness means, not a failure. --lubricated adds a lubricant axis:
// dry and the cavitated short-bearing film (R = L = 10 mm) at 0.01 and
// 0.1 Pa s (docs/compliant.md "Lubricated bearing"), the film's work in the
// energy balance.
//
//   stress_compliant [--quick] [--lubricated] [--turns N] [--tolerance TOL] [--csv FILE]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "sim/compliant/compliant_simulator.hpp"

using namespace fourbar;

namespace {

constexpr double kEnergyBound = 1e-8;
constexpr double kMaxStepsPerTurn = 2e6;

struct Case {
  double stiffness, e, mu, rpm, viscosity;
  int turns;
  double tolerance;
};

struct Result {
  bool ok = true;
  std::string failure;
  double energy = 0, penetration = 0, seconds = 0, steps_per_turn = 0;
  std::size_t impacts = 0;
};

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

bool finite(const ClearanceSample& s) {
  const double v[] = {s.links.omega3_rad_s, s.links.omega4_rad_s, s.alpha3_rad_s2, s.alpha4_rad_s2,
                      s.bearing_force_N.x, s.bearing_force_N.y, s.crank_torque_Nm, s.gap_m, s.normal_force_N,
                      s.penetration_m, s.kinetic_energy_J};
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

Result run(const Case& c) {
  Result r;
  const double t0 = cpu_seconds();
  auto fail = [&](const std::string& why) {
    if (r.ok) r.failure = why;
    r.ok = false;
  };
  try {
    ClearanceSettings s;
    s.model = ClearanceKind::compliant;
    s.restitution = c.e;
    s.friction_coefficient = c.mu;
    s.compliant.stiffness_N_per_m_n = c.stiffness;
    s.tolerance = c.tolerance;
    s.compliant.film = {c.viscosity, 10e-3, 10e-3, 0.254e-3, FilmExtent::cavitated, 0.95};
    const ClearanceModel model(thesis_rig(), 0.254e-3);
    const double w = units::rpm_to_rad_s(c.rpm), period = units::kTwoPi / w;
    const ConstantSpeedCrank crank(0.0, w);
    CompliantSimulator sim(model, crank, s);
    std::vector<double> times;
    for (int i = 0; i <= 360 * c.turns; ++i) times.push_back(period * i / 360.0);
    sim.set_sample_times(times);
    sim.set_revolution_origin(0.0);
    sim.start_nominal(0.0);
    std::size_t steps = 0;
    for (int k = 1; k <= 8 * c.turns && r.ok; ++k) {
      sim.advance_to(times[static_cast<std::size_t>(k * 45)]);
      const ClearanceDiagnostics d = sim.diagnostics();
      const double slice = static_cast<double>(d.steps - steps);
      r.steps_per_turn = std::max(r.steps_per_turn, 8 * slice);
      if (slice > kMaxStepsPerTurn / 8) fail("steps per 1/8 turn above the bound");
      steps = d.steps;
    }
    const ClearanceDiagnostics d = sim.diagnostics();
    if (sim.samples().size() != times.size()) fail("missing samples");
    for (const auto& x : sim.samples())
      if (!finite(x)) {
        fail("NaN/Inf in a sample");
        break;
      }
    for (double x : {d.max_energy_residual_J, d.crank_work_J, d.impact_loss_J, d.friction_loss_J, d.film_loss_J,
                     d.max_penetration})
      if (!std::isfinite(x)) fail("NaN/Inf in the diagnostics");
    r.energy = d.max_energy_residual_J / d.energy_scale_J;
    r.penetration = d.max_penetration;
    r.impacts = d.impacts;
    if (!(r.energy < kEnergyBound)) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "energy residual %.2e", r.energy);
      fail(buf);
    }
  } catch (const std::exception& e) {
    fail(std::string("exception: ") + e.what());
  }
  r.seconds = cpu_seconds() - t0;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false, lubricated = false;
  int turns = 3;
  double tolerance = 1e-10;
  std::string csv_path;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--lubricated")) lubricated = true;
    else if (!std::strcmp(argv[i], "--turns") && i + 1 < argc) turns = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--tolerance") && i + 1 < argc) tolerance = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--csv") && i + 1 < argc) csv_path = argv[++i];
    else {
      std::fprintf(stderr, "usage: stress_compliant [--quick] [--lubricated] [--turns N] [--tolerance TOL] [--csv FILE]\n");
      return 2;
    }
  }
  const std::vector<double> ks = quick ? std::vector<double>{1e6, 1e10} : std::vector<double>{1e6, 1e7, 1e8, 1e9, 1e10};
  const std::vector<double> es = quick ? std::vector<double>{0.5} : std::vector<double>{0.1, 0.5, 0.9, 1.0};
  const std::vector<double> mus{0.0, 0.3};
  const std::vector<double> rpms = quick ? std::vector<double>{350} : std::vector<double>{100, 350, 1000};
  const std::vector<double> viscosities = lubricated ? std::vector<double>{0.0, 0.01, 0.1} : std::vector<double>{0.0};
  std::vector<Case> cases;
  for (double k : ks)
    for (double e : es)
      for (double mu : mus)
        for (double rpm : rpms)
          for (double v : viscosities) cases.push_back({k, e, mu, rpm, v, turns, tolerance});
  std::ofstream csv;
  if (!csv_path.empty()) {
    csv.open(csv_path);
    csv << "stiffness_N_per_m_n,restitution,friction_coefficient,crank_speed_rpm,viscosity_Pa_s,turns,ok,failure,"
           "energy_residual_rel,max_penetration_rel,impacts,max_steps_per_turn,cpu_seconds\n";
  }
  std::size_t failures = 0;
  double worst_energy = 0, worst_pen = 0, slowest = 0, total = 0, most_steps = 0;
  std::printf("%-8s %-4s %-4s %-5s %-5s | %-4s | %10s | %10s | %7s | %10s | %7s\n", "K", "e", "mu", "rpm", "Pa_s", "ok",
              "energy", "pen/xi", "impacts", "steps/turn", "cpu s");
  for (const Case& c : cases) {
    const Result r = run(c);
    failures += !r.ok;
    worst_energy = std::max(worst_energy, r.energy);
    worst_pen = std::max(worst_pen, r.penetration);
    slowest = std::max(slowest, r.seconds);
    most_steps = std::max(most_steps, r.steps_per_turn);
    total += r.seconds;
    std::printf("%-8.0e %-4.1f %-4.1f %-5.0f %-5.2g | %-4s | %10.2e | %10.3e | %7zu | %10.0f | %7.2f %s\n", c.stiffness,
                c.e, c.mu, c.rpm, c.viscosity, r.ok ? "ok" : "FAIL", r.energy, r.penetration, r.impacts, r.steps_per_turn, r.seconds,
                r.failure.c_str());
    if (csv.is_open())
      csv << c.stiffness << ',' << c.e << ',' << c.mu << ',' << c.rpm << ',' << c.viscosity << ',' << c.turns << ',' << r.ok << ",\""
          << r.failure << "\"," << r.energy << ',' << r.penetration << ',' << r.impacts << ',' << r.steps_per_turn
          << ',' << r.seconds << '\n';
  }
  std::printf("\ntolerance %g: %zu cases, %zu failures; worst energy residual %.2e (bound %.0e), deepest penetration %.3g xi, most "
              "steps per turn %.0f, slowest case %.2f s, total %.1f s CPU\n",
              tolerance, cases.size(), failures, worst_energy, kEnergyBound, worst_pen, most_steps, slowest, total);
  return failures ? 1 : 0;
}
