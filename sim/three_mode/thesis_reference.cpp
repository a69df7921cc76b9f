#include "sim/three_mode/thesis_reference.hpp"

#include <cmath>

#include <Eigen/Dense>

namespace fourbar {

ThesisFollowingSolution thesis_following_system(const Rig& rig, double C, double t2, double w2, double t3, double t4,
                                                double tc, double w3, double w4, double wc) {
  const double l2 = rig.crank.length_m, l3 = rig.coupler.length_m, l4 = rig.rocker.length_m;
  const double m2 = rig.crank.mass_kg, m3 = rig.coupler.mass_kg, m4 = rig.rocker.mass_kg;
  const double S2 = rig.crank.mass_centre_m, S3 = rig.coupler.mass_centre_m, S4 = rig.rocker.mass_centre_m;
  const double g = rig.gravity_m_s2;
  const double IA3 = rig.coupler.inertia_about_joint(), IO4 = rig.rocker.inertia_about_joint();
  const double beta = t2 - t3;
  using std::cos;
  using std::sin;
  Eigen::Matrix<double, 6, 6> A;
  // eq. 3.3-8a, with A(1,3) = l2·sin θ2 and A(2,2) = −l3·cos θ3 (errata)
  A << -1, -l2 * cos(t2), l2 * sin(t2), 0, m3 * l2 * S3 * cos(beta), 0,  //
      0, -l3 * cos(t3), l3 * sin(t3), 0, IA3, 0,                          //
      0, -C * cos(tc), C * sin(tc), 0, 0, 0,                              //
      0, l4 * cos(t4), -l4 * sin(t4), IO4, 0, 0,                          //
      0, 0, 0, -l4 * sin(t4), l3 * sin(t3), C * sin(tc),                  //
      0, 0, 0, -l4 * cos(t4), l3 * cos(t3), C * cos(tc);
  Eigen::Matrix<double, 6, 1> B;
  // eq. 3.3-8c (errata: B1, B2, B5, B6)
  B << -m2 * g * S2 * cos(t2) - m3 * g * l2 * cos(t2) - m3 * l2 * S3 * sin(t2 - t3) * w3 * w3,
      -m3 * g * S3 * cos(t3) + m3 * l2 * S3 * sin(t2 - t3) * w2 * w2,  //
      0,                                                              //
      -m4 * g * S4 * cos(t4),                                         //
      l4 * cos(t4) * w4 * w4 - l3 * cos(t3) * w3 * w3 - C * cos(tc) * wc * wc - l2 * cos(t2) * w2 * w2,
      l2 * sin(t2) * w2 * w2 + l3 * sin(t3) * w3 * w3 + C * sin(tc) * wc * wc - l4 * sin(t4) * w4 * w4;
  const Eigen::Matrix<double, 6, 1> X = A.fullPivLu().solve(B);
  return {X(0), X(1), X(2), X(3), X(4), X(5)};
}

ThesisImpactSolution thesis_impact(const Rig& rig, double xi, ThesisContactCase c, double e, double mu0,
                                   double sigma, double t2, double t3, double t4, double eta, double w2, double w3,
                                   double w4) {
  const double l2 = rig.crank.length_m, l3 = rig.coupler.length_m, l4 = rig.rocker.length_m;
  const double IA3 = rig.coupler.inertia_about_joint(), IO4 = rig.rocker.inertia_about_joint();
  using std::cos;
  using std::sin;
  // ρ and α of the triangle O4–C–B4 (eq. 5.2-11, 5.2-12; γ = θ4 − α per errata).
  const double rho = std::sqrt(l4 * l4 + xi * xi + 2 * l4 * xi * cos(eta - t4));
  const double gamma = std::atan2(l4 * sin(t4) + xi * sin(eta), l4 * cos(t4) + xi * cos(eta));
  const double alpha = t4 - gamma;
  // eq. 5.3-1 (errata: μ8 = l4·cos(η−θ4) + ξ, μ9 = l2·cos(η−θ2))
  const double mu3 = l3 * sin(eta - t3), mu4 = l4 * sin(eta - t4), mu5 = l2 * sin(eta - t2);
  const double mu6 = rho * sin(eta - t4 + alpha), mu7 = l3 * cos(eta - t3), mu8 = l4 * cos(eta - t4) + xi;
  const double mu9 = l2 * cos(eta - t2), mu10 = rho * cos(eta - t4 + alpha);
  ThesisImpactSolution s;
  if (c == ThesisContactCase::stick) {  // eq. 5.4-3
    const double D2 = mu3 * mu10 - mu6 * mu7, D3 = mu4 * mu7 - mu3 * mu8;
    s.omega3_rad_s = (e * mu10 * (mu6 * w4 - mu3 * w3) + (mu6 * mu9 - (1 + e) * mu5 * mu10) * w2) / D2;
    s.omega4_rad_s = (e * mu7 * (mu6 * w4 - mu3 * w3) + (mu3 * mu9 - (1 + e) * mu5 * mu7) * w2) / D2;
    s.normal_impulse_Ns = (IA3 * mu8 * (s.omega3_rad_s - w3) + IO4 * mu7 * (s.omega4_rad_s - w4)) / D3;
    s.tangential_impulse_Ns = -(IA3 * mu4 * (s.omega3_rad_s - w3) + IO4 * mu3 * (s.omega4_rad_s - w4)) / D3;
    return s;
  }
  const double sm = c == ThesisContactCase::slip ? sigma * mu0 : 0.0;
  const double mu11 = mu3 + sm * mu7, mu12 = mu4 + sm * mu8;  // "μ13" in the OCR is μ12
  const double D1 = IA3 * mu6 * mu12 + IO4 * mu3 * mu11;     // eq. 5.4-2e
  s.omega3_rad_s = ((IA3 * mu6 * mu12 - e * IO4 * mu3 * mu11) * w3 + (mu6 * w4 - mu5 * w2) * (1 + e) * IO4 * mu11) / D1;
  s.omega4_rad_s = ((IO4 * mu3 * mu11 - e * IA3 * mu6 * mu12) * w4 + (mu3 * w3 + mu5 * w2) * (1 + e) * IA3 * mu12) / D1;
  s.normal_impulse_Ns = IA3 * IO4 * (1 + e) * (mu3 * w3 - mu6 * w4 + mu5 * w2) / D1;
  s.tangential_impulse_Ns = sm * s.normal_impulse_Ns;
  return s;
}

}  // namespace fourbar
