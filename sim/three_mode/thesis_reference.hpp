#pragma once
// The thesis's own matrix forms, corrected per THESIS-ERRATA, kept as an
// independent reference for tests: the following-mode 6×6 system (eq. 3.3-7,
// 3.3-8) in the thesis unknowns, and the explicit impact solutions (eq. 5.4-2,
// 5.4-3) in the μ notation of eq. 5.3-1 with the ρ/α construction of sec. 5.2.

#include "mechanism/rig.hpp"

namespace fourbar {

/// Unknowns X = [λ1, λ2, λ3, α4, α3, αc] of eq. 3.3-8b.
struct ThesisFollowingSolution {
  double crank_torque_Nm = 0;  ///< λ1
  double force_y_N = 0;        ///< λ2: y force on the coupler at the pin
  double force_x_N = 0;        ///< λ3: x force on the coupler at the pin
  double alpha4_rad_s2 = 0, alpha3_rad_s2 = 0, alpha_c_rad_s2 = 0;
};

/// Solves eq. 3.3-7 (constant crank speed, α2 = 0). The clearance link of
/// length C = ξ points from the pin to the bushing centre at angle θc.
ThesisFollowingSolution thesis_following_system(const Rig& rig, double clearance_m, double theta2, double omega2,
                                                double theta3, double theta4, double theta_c, double omega3,
                                                double omega4, double omega_c);

/// ω3⁺, ω4⁺ and the impulses F (normal) and f (tangential, thesis sign) of eq. 5.4-2/5.4-3.
struct ThesisImpactSolution {
  double omega3_rad_s = 0, omega4_rad_s = 0, normal_impulse_Ns = 0, tangential_impulse_Ns = 0;
};

enum class ThesisContactCase { smooth, slip, stick };

/// `sigma` (slip case) is the sign of the tangential slip before impact (eq. 5.3.3-4).
ThesisImpactSolution thesis_impact(const Rig& rig, double clearance_m, ThesisContactCase c, double restitution,
                                   double friction, double sigma, double theta2, double theta3, double theta4,
                                   double eta, double omega2, double omega3, double omega4);

}  // namespace fourbar
