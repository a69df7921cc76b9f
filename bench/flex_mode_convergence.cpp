// The thesis coupler (25 × 4 mm steel bar, 309 mm between the pins) as an
// elastic link with 1, 2, 4 and 8 pinned–pinned modes: its frequencies and
// its quasi-static response by modal superposition, each against the
// Euler–Bernoulli closed form. Prints the markdown table in docs/flex.md.
//
//   build/bench/flex_mode_convergence

#include <cmath>
#include <cstdio>
#include <numbers>

#include "sim/flex/elastic_body.hpp"
#include "sim/flex/elastic_link.hpp"

using namespace fourbar;

int main() {
  BeamSection sec;
  sec.youngs_modulus_Pa = 210e9;
  sec.density_kg_m3 = 7850;
  sec.area_m2 = 25e-3 * 4e-3;
  sec.second_moment_m4 = 4e-3 * std::pow(25e-3, 3) / 12;
  sec.depth_m = 25e-3;
  const double L = 0.309, ei = sec.youngs_modulus_Pa * sec.second_moment_m4;
  const double mu = sec.density_kg_m3 * sec.area_m2;
  const double g = 9.81, load = mu * g;        // the bar's own weight, across it
  const double p = 1.0, a = 0.185, b = L - a;  // 1 N at the mass centre (185 mm from A)
  // Closed forms (Euler–Bernoulli, simply supported):
  const double uniform_mid = 5 * load * std::pow(L, 4) / (384 * ei);
  const double uniform_moment = load * L * L / 8;  // mid-span bending moment
  const double point_at_load = p * a * a * b * b / (3 * ei * L);
  std::printf(
      "| modes | highest f (Hz) | f1 error | own weight: mid deflection (µm), error | mid moment error | 1 N at S3: "
      "deflection error |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (int n : {1, 2, 4, 8}) {
    const ElasticLink link = build_elastic_link(pinned_pinned_link(L, sec, n));
    const double f1_exact = std::pow(std::numbers::pi / L, 2) * std::sqrt(ei / mu);
    // Uniform load: F_k = q·∫Φy_k ds = (q/μ)·S̄_yk; point load: F_k = P·Φy_k(a).
    const Eigen::VectorXd f_uniform = (load / mu) * link.shape_moment.row(1).transpose();
    Eigen::VectorXd f_point(n);
    for (int k = 0; k < n; ++k) f_point(k) = p * std::sin((k + 1) * std::numbers::pi * a / L);
    const Eigen::VectorXd eta_u = link.modal_stiffness.ldlt().solve(f_uniform);
    const Eigen::VectorXd eta_p = link.modal_stiffness.ldlt().solve(f_point);
    const double mid = deflection(link, L / 2, eta_u).y;
    double curvature = 0;  // Σ η_k·(kπ/L)²·sin(kπ/2)
    for (int k = 0; k < n; ++k)
      curvature += eta_u(k) * std::pow((k + 1) * std::numbers::pi / L, 2) * std::sin((k + 1) * std::numbers::pi / 2);
    const double at_load = deflection(link, a, eta_p).y;
    std::printf("| %d | %.1f | %.1e | %.4f, %.1e | %.1e | %.1e |\n", n,
                link.frequencies_rad_s(n - 1) / (2 * std::numbers::pi),
                std::abs(link.frequencies_rad_s(0) / f1_exact - 1), mid * 1e6, std::abs(mid / uniform_mid - 1),
                std::abs(ei * curvature / uniform_moment - 1), std::abs(at_load / point_at_load - 1));
  }
  return 0;
}
