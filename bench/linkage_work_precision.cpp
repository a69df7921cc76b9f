// Work–precision of the linkage model beside the compliant model: thesis rig,
// 350 rpm, e = 0.5, K = 1e10 N/m^1.5, μ = 0, one turn from the nominal links.
// Error: relative RMS of α3 at 720 crank angles against a tight-tolerance
// (1e-13) compliant run; time: wall clock of the run (median of `repeats`).
// A third line: the linkage with clearance in all three joints (0.254 mm
// each), against its own 1e-13 run.
//
//   bench/linkage_work_precision [repeats]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "common/units.hpp"
#include "mechanism/kinematics.hpp"
#include "sim/compliant/compliant_simulator.hpp"
#include "sim/linkage/linkage_simulator.hpp"

using namespace fourbar;

namespace {

constexpr double kXi = 0.254e-3;

struct Result {
  std::vector<double> alpha3;
  double seconds = 0;
};

LinkageSpec spec(const std::array<double, 3>& xi, double tol) {
  LinkageSpec s;
  s.clearance_m = xi;
  s.law = {1e10, 1.5, DampingLaw::calibrated, 0.5};
  s.friction = {0.0, 1e-4, 1e-3};
  s.tolerance = tol;
  return s;
}

template <class Run>
Result timed(Run&& run, int repeats) {
  Result r;
  std::vector<double> secs;
  for (int k = 0; k < repeats; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    r.alpha3 = run();
    secs.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(secs.begin(), secs.end());
  r.seconds = secs[secs.size() / 2];
  return r;
}

double rel_rms(const std::vector<double>& a, const std::vector<double>& b) {
  double num = 0, den = 0;
  for (std::size_t i = 0; i < a.size(); ++i) num += (a[i] - b[i]) * (a[i] - b[i]), den += b[i] * b[i];
  return std::sqrt(num / den);
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const Rig rig = thesis_rig();
  const double w = units::rpm_to_rad_s(350), T = units::kTwoPi / w;
  const ConstantSpeedCrank crank(0.0, w);
  std::vector<double> times;
  for (int i = 0; i <= 720; ++i) times.push_back(T * i / 720.0);
  const NominalMotion nm = solve_motion(rig, crank.at(0.0));
  const ClearanceModel cm(rig, kXi);
  auto compliant = [&](double tol) {
    ClearanceSettings s;
    s.model = ClearanceKind::compliant;
    s.restitution = 0.5;
    s.tolerance = tol;
    s.compliant.stiffness_N_per_m_n = 1e10;
    CompliantSimulator sim(cm, crank, s);
    sim.set_sample_times(times);
    sim.start_free(0.0, LinkMotion{nm.pose.u3, nm.pose.u4, nm.omega3_rad_s, nm.omega4_rad_s});
    sim.advance_to(T);
    std::vector<double> a;
    for (const ClearanceSample& x : sim.samples()) a.push_back(x.alpha3_rad_s2);
    return a;
  };
  auto linkage = [&](const std::array<double, 3>& xi, double tol) {
    const LinkageModel m = build_linkage(rig, spec(xi, tol));
    LinkageSimulator sim(m, crank);
    sim.set_sample_times(times);
    sim.start_centred(0.0);
    sim.advance_to(T);
    std::vector<double> a;
    for (const LinkageSample& x : sim.samples()) a.push_back(x.alpha3_rad_s2);
    return a;
  };
  const std::array<double, 3> b_only{0, kXi, 0}, all{kXi, kXi, kXi};
  const std::vector<double> ref = compliant(1e-13);
  const std::vector<double> ref3 = linkage(all, 1e-13);
  std::printf("# one turn, thesis rig 350 rpm, e = 0.5, K = 1e10; error = relative RMS of alpha3\n");
  std::printf("%-8s  %-22s  %-22s  %-22s\n", "tol", "compliant (s, error)", "linkage B (s, error)",
              "linkage A+B+O4 (s, error)");
  for (double tol : {1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12}) {
    const Result c = timed([&] { return compliant(tol); }, repeats);
    const Result l = timed([&] { return linkage(b_only, tol); }, repeats);
    const Result l3 = timed([&] { return linkage(all, tol); }, repeats);
    std::printf("%-8.0e  %8.4f  %10.3e   %8.4f  %10.3e   %8.4f  %10.3e\n", tol, c.seconds, rel_rms(c.alpha3, ref),
                l.seconds, rel_rms(l.alpha3, ref), l3.seconds, rel_rms(l3.alpha3, ref3));
  }
  return 0;
}
