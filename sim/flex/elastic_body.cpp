#include "sim/flex/elastic_body.hpp"

namespace fourbar {

namespace {

Vec2 to_vec(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }
Eigen::Vector2d turn(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }  // E·v

Eigen::Matrix2d rotation(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix2d a;
  a << c, -s, s, c;
  return a;
}

using ShapeMatrix = Eigen::Matrix<double, 2, Eigen::Dynamic, 0, 2, kMaxModes>;

/// Φ(s) as a 2×n matrix.
ShapeMatrix shape_matrix(const ElasticLink& link, double s_m) {
  ShapeMatrix phi(2, link.modes());
  const double xi = s_m / link.length_m;
  for (int k = 0; k < link.modes(); ++k) {
    const ShapeValue v = evaluate(link.shapes[static_cast<std::size_t>(k)], xi);
    phi(0, k) = v.x;
    phi(1, k) = v.y;
  }
  return phi;
}

}  // namespace

ModalState zero_modal_state(const ElasticLink& link) {
  const ModalVector z = ModalVector::Zero(link.modes());
  return {z, z, z};
}

Vec2 deflection(const ElasticLink& link, double s_m, const ModalVector& eta) {
  return to_vec(shape_matrix(link, s_m) * eta);
}

double slope_rad(const ElasticLink& link, double s_m, const ModalVector& eta) {
  double slope = 0;
  const double xi = s_m / link.length_m;
  for (int k = 0; k < link.modes(); ++k)
    slope += evaluate(link.shapes[static_cast<std::size_t>(k)], xi).dy / link.length_m * eta(k);
  return slope;
}

Vec2 axis_tangent(const ElasticLink& link, double s_m, const FrameState& frame, const ModalState& modal) {
  Eigen::Vector2d d(1, 0);
  const double xi = s_m / link.length_m;
  for (int k = 0; k < link.modes(); ++k) {
    const ShapeValue v = evaluate(link.shapes[static_cast<std::size_t>(k)], xi);
    d += Eigen::Vector2d(v.dx, v.dy) * (modal.eta_m(k) / link.length_m);
  }
  return to_vec(rotation(frame.angle_rad) * d.normalized());
}

Vec2 point_position(const ElasticLink& link, double s_m, const FrameState& frame, const ModalState& modal) {
  const Eigen::Vector2d u = Eigen::Vector2d(s_m, 0) + shape_matrix(link, s_m) * modal.eta_m;
  return frame.origin_m + to_vec(rotation(frame.angle_rad) * u);
}

Vec2 point_velocity(const ElasticLink& link, double s_m, const FrameState& frame, const ModalState& modal) {
  const ShapeMatrix phi = shape_matrix(link, s_m);
  const Eigen::Vector2d u = Eigen::Vector2d(s_m, 0) + phi * modal.eta_m;
  const Eigen::Vector2d local = frame.angular_velocity_rad_s * turn(u) + phi * modal.eta_dot_m_s;
  return frame.velocity_m_s + to_vec(rotation(frame.angle_rad) * local);
}

Vec2 point_acceleration(const ElasticLink& link, double s_m, const FrameState& frame, const ModalState& modal) {
  const ShapeMatrix phi = shape_matrix(link, s_m);
  const Eigen::Vector2d u = Eigen::Vector2d(s_m, 0) + phi * modal.eta_m;
  const double w = frame.angular_velocity_rad_s;
  const Eigen::Vector2d local = frame.angular_acceleration_rad_s2 * turn(u) - w * w * u +
                                2 * w * turn(phi * modal.eta_dot_m_s) + phi * modal.eta_ddot_m_s2;
  return frame.acceleration_m_s2 + to_vec(rotation(frame.angle_rad) * local);
}

ElasticBodyData::ElasticBodyData(const ElasticLink& link)
    : mass(BodyMatrix::Zero(3 + link.modes(), 3 + link.modes())),
      quadratic_force(BodyVector::Zero(3 + link.modes())),
      stiffness_force(BodyVector::Zero(3 + link.modes())),
      damping_force(BodyVector::Zero(3 + link.modes())),
      point_jacobian(Eigen::Matrix<double, 2, Eigen::Dynamic, 0, 2, 3 + kMaxModes>::Zero(2, 3 + link.modes())) {}

void body_terms(const ElasticLink& link, ElasticBodyData& data, const FrameState& frame, const ModalState& modal) {
  const int n = link.modes();
  const ModalVector& eta = modal.eta_m;
  const ModalVector& eta_dot = modal.eta_dot_m_s;
  const Eigen::Matrix2d a = rotation(frame.angle_rad);
  // Coefficient-wise (lazy) products: for n ≤ 16 Eigen's general matrix–vector
  // kernel costs more in dispatch than the product itself.
  const Eigen::Vector2d s = link.first_moment_kg_m + link.shape_moment.lazyProduct(eta);
  ModalVector m_eta(n), v(n);  // fixed capacity, products written in place (noalias): no heap
  m_eta.noalias() = link.modal_mass.lazyProduct(eta);
  const double w = frame.angular_velocity_rad_s;

  BodyMatrix& m = data.mass;
  m.setZero();
  m(0, 0) = m(1, 1) = link.mass_kg;
  m.block<2, 1>(0, 2) = a * turn(s);
  m.block(0, 3, 2, n).noalias() = a * link.shape_moment;
  m(2, 2) = link.inertia_origin_kg_m2 + 2 * link.axial_coupling.dot(eta) + eta.dot(m_eta);
  v.noalias() = link.gyroscopic.transpose().lazyProduct(eta);
  m.block(2, 3, 1, n) = (link.bending_coupling + v).transpose();
  m.block(3, 3, n, n) = link.modal_mass;
  m.triangularView<Eigen::StrictlyLower>() = m.transpose();

  BodyVector& q = data.quadratic_force;
  const Eigen::Vector2d s_dot = link.shape_moment.lazyProduct(eta_dot);
  q.head<2>() = a * (w * w * s - 2 * w * turn(s_dot));
  q(2) = -2 * w * (link.axial_coupling.dot(eta_dot) + eta_dot.dot(m_eta));
  v.noalias() = link.gyroscopic.lazyProduct(eta_dot);
  q.tail(n) = w * w * (link.axial_coupling + m_eta) + 2 * w * v;

  data.stiffness_force.head<3>().setZero();
  data.stiffness_force.tail(n).noalias() = -link.modal_stiffness.lazyProduct(eta);
  data.damping_force.head<3>().setZero();
  data.damping_force.tail(n).noalias() = -link.modal_damping.lazyProduct(eta_dot);
}

void point_jacobian(const ElasticLink& link, ElasticBodyData& data, double s_m, const FrameState& frame,
                    const ModalState& modal) {
  const ShapeMatrix phi = shape_matrix(link, s_m);
  const Eigen::Vector2d u = Eigen::Vector2d(s_m, 0) + phi * modal.eta_m;
  const Eigen::Matrix2d a = rotation(frame.angle_rad);
  data.point_jacobian.leftCols<2>().setIdentity();
  data.point_jacobian.col(2) = a * turn(u);
  data.point_jacobian.rightCols(link.modes()) = a * phi;
}

double kinetic_energy(const ElasticLink& link, ElasticBodyData& data, const FrameState& frame,
                      const ModalState& modal) {
  body_terms(link, data, frame, modal);
  BodyVector zdot(3 + link.modes());
  zdot << frame.velocity_m_s.x, frame.velocity_m_s.y, frame.angular_velocity_rad_s, modal.eta_dot_m_s;
  return 0.5 * zdot.dot(data.mass * zdot);
}

double strain_energy(const ElasticLink& link, const ModalState& modal) {
  return 0.5 * modal.eta_m.dot(link.modal_stiffness * modal.eta_m);
}

}  // namespace fourbar
