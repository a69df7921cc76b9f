// The elastic body's mass matrix and quadratic-velocity forces against the
// principle of virtual work done by brute force: ∫μ·(∂r/∂z)ᵀ·r̈ ds over the
// link, with r̈ from point_acceleration at 400 points. And the point
// functions against finite differences of point_position.

#include <gtest/gtest.h>

#include <random>

#include "sim/flex/elastic_body.hpp"
#include "sim/flex/gauss_legendre.hpp"

namespace fourbar {
namespace {

ElasticLink test_link() {
  ElasticLinkSpec spec;
  spec.name = "rod";
  spec.length_m = 0.3;
  spec.mass_per_length_kg_m = 0.5;
  spec.bending_stiffness_N_m2 = 60;
  spec.axial_stiffness_N = 1e7;
  spec.shapes = {{ShapeKind::lateral_sine, 1},
                 {ShapeKind::lateral_sine, 2},
                 {ShapeKind::axial_quadratic_mid, 0},
                 {ShapeKind::axial_quadratic_tip, 0},
                 {ShapeKind::axial_sine, 1}};
  return build_elastic_link(spec);
}

struct RandomState {
  FrameState frame;
  ModalState modal;
};

RandomState random_state(const ElasticLink& link, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  RandomState st;
  st.frame = {{u(rng), u(rng)}, 3 * u(rng), {u(rng), u(rng)}, 50 * u(rng), {100 * u(rng), 100 * u(rng)}, 1e4 * u(rng)};
  const int n = link.modes();
  st.modal.eta_m = 1e-3 * Eigen::VectorXd::NullaryExpr(n, [&] { return u(rng); });
  st.modal.eta_dot_m_s = 0.1 * Eigen::VectorXd::NullaryExpr(n, [&] { return u(rng); });
  st.modal.eta_ddot_m_s2 = 100 * Eigen::VectorXd::NullaryExpr(n, [&] { return u(rng); });
  return st;
}

TEST(ElasticBody, MassMatrixAndQuadraticForcesAreVirtualWork) {
  const ElasticLink link = test_link();
  ElasticBodyData data(link);
  std::mt19937 rng(7);
  const QuadratureRule rule = gauss_legendre_unit(20, 20);
  const int nz = 3 + link.modes();
  for (int trial = 0; trial < 20; ++trial) {
    const RandomState st = random_state(link, rng);
    body_terms(link, data, st.frame, st.modal);
    Eigen::VectorXd zddot(nz);
    zddot << st.frame.acceleration_m_s2.x, st.frame.acceleration_m_s2.y, st.frame.angular_acceleration_rad_s2,
        st.modal.eta_ddot_m_s2;
    const Eigen::VectorXd model = data.mass * zddot - data.quadratic_force;
    Eigen::VectorXd brute = Eigen::VectorXd::Zero(nz);
    for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
      const double s = rule.nodes[q] * link.length_m;
      const Vec2 a = point_acceleration(link, s, st.frame, st.modal);
      point_jacobian(link, data, s, st.frame, st.modal);
      brute += rule.weights[q] * link.length_m * 0.5 * data.point_jacobian.transpose() * Eigen::Vector2d(a.x, a.y);
    }
    EXPECT_LT((model - brute).norm(), 1e-11 * brute.norm()) << "trial " << trial << "\n" << model << "\n" << brute;
  }
}

TEST(ElasticBody, PointRatesAreDerivativesOfPosition) {
  const ElasticLink link = test_link();
  std::mt19937 rng(3);
  const RandomState st = random_state(link, rng);
  const double h = 1e-6;
  auto at = [&](double t) {
    RandomState s = st;
    const FrameState& f = st.frame;
    s.frame.origin_m = f.origin_m + t * f.velocity_m_s + 0.5 * t * t * f.acceleration_m_s2;
    s.frame.angle_rad = f.angle_rad + t * f.angular_velocity_rad_s + 0.5 * t * t * f.angular_acceleration_rad_s2;
    s.modal.eta_m = st.modal.eta_m + t * st.modal.eta_dot_m_s + 0.5 * t * t * st.modal.eta_ddot_m_s2;
    return point_position(link, 0.21, s.frame, s.modal);
  };
  const Vec2 v = point_velocity(link, 0.21, st.frame, st.modal);
  const Vec2 a = point_acceleration(link, 0.21, st.frame, st.modal);
  const Vec2 fd_v = (at(h) - at(-h)) * (1 / (2 * h));
  const Vec2 fd_a = (at(h) - at(0) * 2 + at(-h)) * (1 / (h * h));
  EXPECT_LT((v - fd_v).norm(), 1e-7 * v.norm());
  EXPECT_LT((a - fd_a).norm(), 1e-4 * a.norm());
}

TEST(ElasticBody, PinnedEndsDoNotMoveInTheFrame) {
  ElasticLinkSpec spec;
  spec.length_m = 0.309;
  spec.mass_per_length_kg_m = 0.785;
  spec.bending_stiffness_N_m2 = 1094;
  for (int k = 1; k <= 8; ++k) spec.shapes.push_back({ShapeKind::lateral_sine, k});
  const ElasticLink link = build_elastic_link(spec);
  const Eigen::VectorXd eta = Eigen::VectorXd::Constant(8, 1e-3);
  EXPECT_LT(deflection(link, 0.0, eta).norm(), 1e-18);
  EXPECT_LT(deflection(link, 0.309, eta).norm(), 1e-16);
  EXPECT_NEAR(deflection(link, 0.309 / 2, eta).y, 1e-3 * (1 - 1 + 1 - 1), 1e-16);       // sin(kπ/2): 1,0,−1,0,…
  EXPECT_NEAR(slope_rad(link, 0.0, eta), 1e-3 * std::numbers::pi * 36 / 0.309, 1e-12);  // Σk = 36
}

}  // namespace
}  // namespace fourbar
