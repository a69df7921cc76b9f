#include "report/theory_omega.hpp"

#include <cmath>
#include <span>
#include <vector>

#include "analyze/averaging.hpp"
#include "analyze/integration.hpp"

namespace fourbar {

bool integrate_theory_omega(MatchedTheory& theory, const Rig& rig, IntegrationMethod method) {
  if (method == IntegrationMethod::trapezoid) return false;
  const std::size_t n = theory.grid.grid_points_per_rev;
  const double direction = theory.grid.direction;
  // In ψ = direction·θ2 (increasing along the grid), as RecordAnalyzer::on_grid.
  const std::vector<double> psi_speed(n, direction * theory.crank_speed_rad_s);
  const PeriodicMethod periodic =
      method == IntegrationMethod::closed_trapezoid ? PeriodicMethod::closed_trapezoid : PeriodicMethod::spectral;
  // No slope is kept, whatever the measurement's method: the model turns the
  // crank at a constant speed, so its α has next to no mean over a turn to
  // follow (the sampled ω changes by 0.06 rad/s over a turn at 250 rpm,
  // 0.0254 mm), and a kept slope follows whatever mean a turn's α has.
  const bool keep_slope = false;
  PeriodicIntegrator integrator(n);
  const std::pair<LinkQuantity, LinkQuantity> pairs[] = {{LinkQuantity::alpha3, LinkQuantity::omega3},
                                                         {LinkQuantity::alpha4, LinkQuantity::omega4}};
  for (const auto& [alpha_q, omega_q] : pairs) {
    const TheorySeries& alpha = theory.series[index_of(alpha_q)];
    TheorySeries& omega = theory.series[index_of(omega_q)];
    const SensedLink link = alpha_q == LinkQuantity::alpha3 ? SensedLink::coupler : SensedLink::rocker;
    const double turns = direction * link_turns_per_crank_turn(rig, link);
    const std::size_t revolutions = alpha.clearance_revolutions.size() / n;
    omega.clearance_revolutions.resize(revolutions * n);
    for (std::size_t r = 0; r < revolutions; ++r)
      integrator.integrate(periodic, std::span(alpha.clearance_revolutions).subspan(r * n, n), psi_speed, turns,
                           std::span(omega.clearance_revolutions).subspan(r * n, n), keep_slope);
    omega.clearance = synchronous_average(omega.clearance_revolutions, n);
  }
  return true;
}

}  // namespace fourbar
