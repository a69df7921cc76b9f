// The elastic body's mass matrix and quadratic-velocity forces against the
// principle of virtual work done by brute force: ∫μ·(∂r/∂z)ᵀ·r̈ ds over the
// link, with r̈ from point_acceleration at 400 points. And the point
// functions against finite differences of point_position.

#include <gtest/gtest.h>

#include <numbers>
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

TEST(ElasticBody, AxisTangentIsTheDerivativeAlongTheLink) {
  const ElasticLink link = test_link();
  std::mt19937 rng(11);
  const RandomState st = random_state(link, rng);
  for (double s : {0.0, 0.07, 0.15, 0.3}) {
    const double h = 1e-6;
    const double a = std::max(0.0, s - h), b = std::min(link.length_m, s + h);
    const Vec2 d = (point_position(link, b, st.frame, st.modal) - point_position(link, a, st.frame, st.modal));
    const Vec2 t = axis_tangent(link, s, st.frame, st.modal);
    EXPECT_NEAR(t.norm(), 1.0, 1e-15);
    EXPECT_NEAR(cross(t, d * (1 / d.norm())), 0.0, 2e-6) << "s = " << s;
    EXPECT_GT(dot(t, d), 0);
  }
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

namespace fourbar {
namespace {

// A free, undamped elastic body tumbling in the plane keeps its energy
// (kinetic + strain) and its linear momentum: M(η)·z̈ = Q_v − K·η integrated
// with classic RK4 at a step 1/100 of the highest mode's period. Measured:
// the energy drifts by 5.6e-9 (1.8e-7 at twice the step: 2⁵, RK4's own error,
// so the mass matrix and the quadratic forces are consistent).
TEST(ElasticBody, AFreeBodyKeepsItsEnergyAndMomentum) {
  ElasticLinkSpec spec;
  spec.name = "free";
  spec.length_m = 0.3;
  spec.mass_per_length_kg_m = 0.5;
  spec.bending_stiffness_N_m2 = 2;
  spec.axial_stiffness_N = 2e3;
  spec.shapes = {{ShapeKind::lateral_sine, 1}, {ShapeKind::lateral_sine, 2}, {ShapeKind::axial_sine, 1}};
  const ElasticLink link = build_elastic_link(spec);
  ElasticBodyData data(link);
  const int n = link.modes(), nz = 3 + n;
  auto unpack = [&](const Eigen::VectorXd& y, FrameState& f, ModalState& m) {
    f.origin_m = {y(0), y(1)};
    f.angle_rad = y(2);
    f.velocity_m_s = {y(nz), y(nz + 1)};
    f.angular_velocity_rad_s = y(nz + 2);
    m.eta_m = y.segment(3, n);
    m.eta_dot_m_s = y.segment(nz + 3, n);
    m.eta_ddot_m_s2 = Eigen::VectorXd::Zero(n);
  };
  auto rhs = [&](const Eigen::VectorXd& y) {
    FrameState f;
    ModalState m;
    unpack(y, f, m);
    body_terms(link, data, f, m);
    Eigen::VectorXd d(2 * nz);
    d.head(nz) = y.tail(nz);
    d.tail(nz) = data.mass.ldlt().solve(data.quadratic_force + data.stiffness_force);
    return d;
  };
  auto energy = [&](const Eigen::VectorXd& y) {
    FrameState f;
    ModalState m;
    unpack(y, f, m);
    return kinetic_energy(link, data, f, m) + strain_energy(link, m);
  };
  auto momentum = [&](const Eigen::VectorXd& y) {  // ∫μ ṙ ds = m·Ṙ + Ȧ·s(η) + A·S̄·η̇
    FrameState f;
    ModalState m;
    unpack(y, f, m);
    body_terms(link, data, f, m);
    Eigen::VectorXd zdot = y.tail(nz);
    return Eigen::Vector2d((data.mass.topRows(2) * zdot));
  };
  Eigen::VectorXd y = Eigen::VectorXd::Zero(2 * nz);
  y(2) = 0.4;
  y(nz) = 0.3;
  y(nz + 1) = -0.2;
  y(nz + 2) = 25;  // rad/s: the centrifugal load stretches and bends it
  y(3) = 2e-3;
  y(nz + 4) = 0.05;
  const double e0 = energy(y);
  const Eigen::Vector2d p0 = momentum(y);
  const double h = 2 * std::numbers::pi / link.frequencies_rad_s.maxCoeff() / 100;
  for (int step = 0; step < 8000; ++step) {
    const Eigen::VectorXd k1 = rhs(y), k2 = rhs(y + h / 2 * k1), k3 = rhs(y + h / 2 * k2), k4 = rhs(y + h * k3);
    y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  EXPECT_NEAR(energy(y) / e0, 1.0, 2e-8) << "after " << 8000 * h << " s";
  EXPECT_LT((momentum(y) - p0).norm(), 1e-9 * p0.norm());
  EXPECT_GT(std::abs(y(3) - 2e-3), 1e-5);  // the modes did move
}

}  // namespace
}  // namespace fourbar
