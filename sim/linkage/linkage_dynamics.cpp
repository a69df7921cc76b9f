#include "sim/linkage/linkage_dynamics.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "common/error.hpp"
#include "sim/linkage/block_cholesky.hpp"

namespace fourbar {

namespace {

/// The mass matrix of a physical body is positive definite; a failed Cholesky
/// factor means the model's inertia data are not one body's (sim/flex refuses
/// such a link at build) or the deflection left the modes' range. Never go on
/// with the solve's garbage: the run stops with the state it reached.
[[noreturn]] void throw_indefinite_mass_matrix(const LinkageCoordinates& c) {
  throw RunError("the linkage's mass matrix is not positive definite at crank angle " +
                 std::to_string(c.crank.angle_rad * 180.0 / 3.14159265358979323846) +
                 " deg: the accelerations cannot be solved; check the elastic links' mass, "
                 "centre and inertia in the rig file and the modal deflection (elastic_modes)");
}

Vec2 rotate(Vec2 u, Vec2 local) { return local.x * u + local.y * u.perp(); }

/// Jacobian of a point r (world, from the origin) on a body: Jp + r⊥·Jw.
ZJac point_jacobian(const BodyFrame& b, Vec2 r) {
  ZJac J = b.Jp;
  J.row(0) += -r.y * b.Jw;
  J.row(1) += r.x * b.Jw;
  return J;
}

Vec2 point_bias(const BodyFrame& b, Vec2 r) { return b.a_bias + b.alpha_bias * r.perp() - b.omega * b.omega * r; }

BodyFrame ground_frame(int size) {
  BodyFrame g;
  g.u = {1, 0};
  g.Jw = ZRow::Zero(size);
  g.Jp = ZJac::Zero(2, size);
  return g;
}


/// The coordinates a body frame moves with: the columns where Jp or Jw is
/// not zero (an exact zero: the Jacobians are built from unit entries and
/// products with them).
struct Support {
  std::array<int, kMaxFull> index_{};
  int size = 0;
  int index(int a) const { return index_[static_cast<std::size_t>(a)]; }
};
Support support(const BodyFrame& b, int nz) {
  Support s;
  for (int c = 0; c < nz; ++c)
    if (b.Jp(0, c) != 0 || b.Jp(1, c) != 0 || b.Jw(c) != 0) s.index_[static_cast<std::size_t>(s.size++)] = c;
  return s;
}

/// M += Tᵀ·M_b·T and Q += Tᵀ·(Q_v − K·η − D·η̇ + gravity − M_b·bias) from
/// sim/flex's body terms, T = ∂(R, θ, η)/∂ż: its first three rows G are the
/// frame's Jp and Jw, the rest select the modal coordinates (from i0), so
/// Tᵀ·M_b·T = Gᵀ·M_rr·G + Gᵀ·M_rf (columns i0…) + M_fr·G (rows i0…) + M_ff
/// (block i0…), assembled without a general product. The modal damping's
/// power and the strain energy go to their own books.
void add_elastic_body(const LinkageModel& m, const LinkageCoordinates& c, const ElasticLink& link, int body,
                      LinkageWorkspace& w) {
  const int nz = m.coordinates() + 1, modes = link.modes(), i0 = m.modal_index(body);
  const BodyFrame& b = w.body[static_cast<std::size_t>(body)];
  const FrameState frame = frame_state(w, body, false);
  const ModalState modal = modal_state(m, c, w, body, false);
  ElasticBodyData data(link);
  body_terms(link, data, frame, modal);
  // G's non-zero columns: a frame moves with few coordinates (its own angle,
  // the crank's, a joint's offsets), so M and Q are assembled over those only.
  const Support cols = support(b, nz);
  Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxFull> G(3, cols.size);
  for (int a = 0; a < cols.size; ++a) {
    G(0, a) = b.Jp(0, cols.index(a));
    G(1, a) = b.Jp(1, cols.index(a));
    G(2, a) = b.Jw(cols.index(a));
  }
  const Eigen::Vector3d bias_r(b.a_bias.x, b.a_bias.y, b.alpha_bias);
  const auto& mb = data.mass;
  // Gravity's generalised force: ∫μ g·δr ds = gᵀ·(rows R of M_b)·δz; the
  // bias acceleration (modal part zero) enters as −M_b·(bias_r, 0).
  const double g = m.rig().gravity_m_s2;
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3 + 4, 1> qb =
      data.quadratic_force + data.stiffness_force + data.damping_force;
  for (int i = 0; i < 3 + modes; ++i) qb(i) += -g * mb(1, i) - mb.row(i).head<3>().dot(bias_r);
  const Eigen::Matrix3d mrr = mb.topLeftCorner<3, 3>();
  const Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxFull> mg = mrr * G;
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, kMaxFull> fr = mb.bottomLeftCorner(modes, 3) * G;
  const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxFull, 1> gq = G.transpose() * qb.head<3>();
  for (int a = 0; a < cols.size; ++a) {
    const int ia = cols.index(a);
    for (int c2 = 0; c2 < cols.size; ++c2) w.M(ia, cols.index(c2)) += G.col(a).dot(mg.col(c2));
    for (int k = 0; k < modes; ++k) {
      w.M(i0 + k, ia) += fr(k, a);
      w.M(ia, i0 + k) += fr(k, a);
    }
    w.Q(ia) += gq(a);
  }
  w.M.block(i0, i0, modes, modes) += mb.bottomRightCorner(modes, modes);
  w.Q.segment(i0, modes) += qb.tail(modes);
  // ½ηᵀKη from the stiffness force just formed (−K·η), not a second product.
  w.strain_energy_J += -0.5 * modal.eta_m.dot(data.stiffness_force.tail(modes));
  w.modal_damping_power_W += -modal.eta_dot_m_s.dot(data.damping_force.tail(modes));
}

}  // namespace

FrameState frame_state(const LinkageWorkspace& w, int body, bool with_accel) {
  const BodyFrame& b = w.body[static_cast<std::size_t>(body)];
  FrameState f;
  f.origin_m = b.p;
  f.angle_rad = std::atan2(b.u.y, b.u.x);
  const Eigen::Vector2d v = b.Jp * w.z_rate_cache;
  f.velocity_m_s = {v(0), v(1)};
  f.angular_velocity_rad_s = b.omega;
  if (with_accel) {
    const Eigen::Vector2d a = b.Jp * w.z_accel;
    f.acceleration_m_s2 = Vec2{a(0), a(1)} + b.a_bias;
    f.angular_acceleration_rad_s2 = b.Jw.dot(w.z_accel) + b.alpha_bias;
  }
  return f;
}

ModalState modal_state(const LinkageModel& m, const LinkageCoordinates& c, const LinkageWorkspace& w, int body,
                       bool with_accel) {
  const ElasticLink* link = m.elastic(body);
  const int modes = link ? link->modes() : 0, i0 = m.modal_index(body);
  ModalState s{ModalVector::Zero(modes), ModalVector::Zero(modes), ModalVector::Zero(modes)};
  for (int k = 0; k < modes; ++k) {
    s.eta_m(k) = c.q_offsets(i0 + k);
    s.eta_dot_m_s(k) = c.z_rate(i0 + k);
    if (with_accel) s.eta_ddot_m_s2(k) = w.z_accel(i0 + k);
  }
  return s;
}

namespace {
}  // namespace

Vec2 site_position(const LinkageWorkspace& w, const Site& s) {
  if (s.body == kGround) return s.local_m;
  const BodyFrame& b = w.body[static_cast<std::size_t>(s.body)];
  return b.p + rotate(b.u, s.local_m);
}

BodyPoses body_poses(const LinkageModel& m, const LinkageCoordinates& c) {
  BodyPoses poses;
  poses.u[0] = c.u2;  // the crank: origin O2, angle z[n]
  auto parent_pose = [&](int b) { return b == kGround ? std::pair{Vec2{1, 0}, Vec2{}} : std::pair{poses.u[static_cast<std::size_t>(b)], poses.p[static_cast<std::size_t>(b)]}; };
  for (const Placement& pl : m.placements()) {  // parents first
    const auto [parent_u, parent_p] = parent_pose(pl.parent.body);
    Vec2 q_pos = parent_p + rotate(parent_u, pl.parent.local_m);
    if (pl.offset_index >= 0) q_pos += Vec2{c.q_offsets(pl.offset_index), c.q_offsets(pl.offset_index + 1)};
    const auto b = static_cast<std::size_t>(pl.body);
    poses.u[b] = c.u[b - 1];
    poses.p[b] = q_pos - rotate(poses.u[b], pl.child.local_m);
  }
  return poses;
}

Vec2 pair_eccentricity(const LinkageModel& m, const LinkageCoordinates& c, const BodyPoses& poses, int joint) {
  for (const Placement& pl : m.placements())
    if (pl.joint == joint) return pl.offset_sign * Vec2{c.q_offsets(pl.offset_index), c.q_offsets(pl.offset_index + 1)};
  const JointData& jd = m.joint(joint);
  auto world = [&](const Site& s) {
    if (s.body == kGround) return s.local_m;
    const auto b = static_cast<std::size_t>(s.body);
    return poses.p[b] + rotate(poses.u[b], s.local_m);
  };
  const Vec2 pin_pos = world(jd.pin), bush_pos = world(jd.bushing);
  return {pin_pos.x - bush_pos.x, pin_pos.y - bush_pos.y};
}

std::array<double, kJoints> pair_penetrations(const LinkageModel& m, const LinkageCoordinates& c) {
  const BodyPoses poses = body_poses(m, c);
  std::array<double, kJoints> pen{};
  for (int j : m.clearance_joints()) {
    const Vec2 e = pair_eccentricity(m, c, poses, j);
    pen[static_cast<std::size_t>(j)] = -(m.joint(j).clearance_m - std::sqrt(dot(e, e)));
  }
  return pen;
}

namespace {

/// The pair's eccentricity, gap, penetration and normal (shared by both
/// kinematics passes, so they give the same bits).
void set_pair_geometry(const LinkageModel& m, const LinkageCoordinates& c, const BodyPoses& poses, int j,
                       PairState& ps) {
  ps.joint = j;
  const Vec2 e = pair_eccentricity(m, c, poses, j);
  ps.eccentricity_m = e;
  const double r = std::sqrt(dot(e, e));
  ps.gap_m = m.joint(j).clearance_m - r;
  ps.penetration_m = -ps.gap_m;
  ps.normal = r > 0 ? e * (1.0 / r) : Vec2{1.0, 0.0};
}

}  // namespace

void pair_kinematics(const LinkageModel& m, const LinkageCoordinates& c, LinkageWorkspace& w) {
  const BodyPoses poses = body_poses(m, c);
  // Origin velocities and angular velocities, parents first (the crank's
  // origin O2 is fixed): v_q = v_parent + ω_parent·r⊥ + the offsets' rates,
  // v_body = v_q − ω_body·r_c⊥ (the Jacobians' rows of forward_kinematics times ż).
  std::array<Vec2, kBodies> v{};
  std::array<double, kBodies> omega{};
  omega[0] = c.crank.speed_rad_s;
  auto origin = [&](int b) { return b == kGround ? std::pair{Vec2{}, 0.0} : std::pair{v[static_cast<std::size_t>(b)], omega[static_cast<std::size_t>(b)]}; };
  auto pose_u = [&](int b) { return b == kGround ? Vec2{1, 0} : poses.u[static_cast<std::size_t>(b)]; };
  auto pose_p = [&](int b) { return b == kGround ? Vec2{} : poses.p[static_cast<std::size_t>(b)]; };
  for (const Placement& pl : m.placements()) {
    const auto [vp, wp] = origin(pl.parent.body);
    Vec2 vq = vp + wp * rotate(pose_u(pl.parent.body), pl.parent.local_m).perp();
    if (pl.offset_index >= 0) vq += Vec2{c.z_rate(pl.offset_index), c.z_rate(pl.offset_index + 1)};
    const auto b = static_cast<std::size_t>(pl.body);
    omega[b] = c.z_rate(pl.angle_index);
    v[b] = vq - omega[b] * rotate(poses.u[b], pl.child.local_m).perp();
  }
  for (int j : m.clearance_joints()) {
    const JointData& jd = m.joint(j);
    PairState& ps = w.pair[static_cast<std::size_t>(j)];
    set_pair_geometry(m, c, poses, j, ps);
    const auto [v_pin, w_pin] = origin(jd.pin.body);
    const auto [v_bush, w_bush] = origin(jd.bushing.body);
    const Vec2 r_pin = rotate(pose_u(jd.pin.body), jd.pin.local_m);
    const Vec2 r_bp = (pose_p(jd.pin.body) + r_pin) - pose_p(jd.bushing.body);
    const Vec2 vv = (v_pin + w_pin * r_pin.perp()) - (v_bush + w_bush * r_bp.perp());
    ps.normal_speed_m_s = dot(vv, ps.normal);
    ps.tangential_speed_m_s = dot(vv, ps.normal.perp());
    ps.omega_pin_rad_s = w_pin;
    ps.omega_bushing_rad_s = w_bush;
  }
}

void forward_kinematics(const LinkageModel& m, const LinkageCoordinates& c, LinkageWorkspace& w) {
  const int n = m.coordinates(), nz = n + 1;
  w.z_rate_cache = c.z_rate;
  const BodyPoses poses = body_poses(m, c);
  const BodyFrame ground = ground_frame(nz);
  auto frame = [&](int b) -> const BodyFrame& { return b == kGround ? ground : w.body[static_cast<std::size_t>(b)]; };
  // The crank: origin O2, angle z[n].
  BodyFrame& cr = w.body[0];
  cr = ground;
  cr.u = c.u2;
  cr.omega = c.crank.speed_rad_s;
  cr.Jw(n) = 1.0;
  // Placed bodies, parents first: positions from body_poses, Jacobians and biases here.
  for (const Placement& pl : m.placements()) {
    const BodyFrame& parent = frame(pl.parent.body);
    const Vec2 rp = rotate(parent.u, pl.parent.local_m);
    ZJac Jq = point_jacobian(parent, rp);
    const Vec2 aq = point_bias(parent, rp);
    if (pl.offset_index >= 0) {
      const auto k = pl.offset_index;
      Jq(0, k) += 1.0;
      Jq(1, k + 1) += 1.0;
    }
    BodyFrame& b = w.body[static_cast<std::size_t>(pl.body)];
    b.u = poses.u[static_cast<std::size_t>(pl.body)];
    b.p = poses.p[static_cast<std::size_t>(pl.body)];
    b.Jw = ZRow::Zero(nz);
    b.Jw(pl.angle_index) = 1.0;
    b.omega = c.z_rate(pl.angle_index);
    b.alpha_bias = 0;
    const Vec2 rc = rotate(b.u, pl.child.local_m);
    b.Jp = Jq;
    b.Jp.row(0) -= -rc.y * b.Jw;
    b.Jp.row(1) -= rc.x * b.Jw;
    b.a_bias = aq + b.omega * b.omega * rc;
  }
  // Pairs.
  for (int j : m.clearance_joints()) {
    const JointData& jd = m.joint(j);
    PairState& ps = w.pair[static_cast<std::size_t>(j)];
    const BodyFrame &pin = frame(jd.pin.body), &bush = frame(jd.bushing.body);
    const Vec2 r_pin = rotate(pin.u, jd.pin.local_m);
    set_pair_geometry(m, c, poses, j, ps);
    // The bushing's material point at the pin: bushing origin to pin centre.
    const Vec2 r_bp = (pin.p + r_pin) - bush.p;
    ps.J_rel = point_jacobian(pin, r_pin) - point_jacobian(bush, r_bp);
    const Eigen::Vector2d v = ps.J_rel * c.z_rate;
    const Vec2 vv{v(0), v(1)};
    ps.normal_speed_m_s = dot(vv, ps.normal);
    ps.tangential_speed_m_s = dot(vv, ps.normal.perp());
    ps.omega_pin_rad_s = pin.omega;
    ps.omega_bushing_rad_s = bush.omega;
  }
}

void pair_forces(const LinkageModel& m, const std::array<double, kJoints>& chi, LinkageWorkspace& w) {
  const LinkageSpec& s = m.spec();
  for (int j : m.clearance_joints()) {
    const JointData& jd = m.joint(j);
    PairState& ps = w.pair[static_cast<std::size_t>(j)];
    ps.normal_force_N = ps.friction_force_N = 0;
    ps.film = {};
    ps.damping_power_W = ps.friction_power_W = ps.film_power_W = ps.elastic_energy_J = 0;
    if (ps.penetration_m > 0) {
      ps.normal_force_N = normal_force_N(s.law, ps.penetration_m, ps.normal_speed_m_s, chi[static_cast<std::size_t>(j)]);
      ps.friction_force_N = friction_force_N(s.friction, ps.normal_force_N, ps.tangential_speed_m_s);
      ps.damping_power_W = (ps.normal_force_N - elastic_force_N(s.law, ps.penetration_m)) * ps.normal_speed_m_s;
      ps.elastic_energy_J = elastic_energy_J(s.law, ps.penetration_m);
    }
    ps.friction_power_W = -ps.friction_force_N * ps.tangential_speed_m_s;
    if (jd.film.viscosity_Pa_s > 0) {
      const double xi = jd.clearance_m;
      const double eps = (xi - ps.gap_m) / xi;
      const double whirl =
          eps * (ps.omega_pin_rad_s - ps.omega_bushing_rad_s) - 2.0 * ps.tangential_speed_m_s / xi;
      ps.film = film_force(jd.film, eps, ps.normal_speed_m_s / xi, whirl);
      ps.film_power_W = -(ps.film.radial_N * ps.normal_speed_m_s + ps.film.tangential_N * ps.tangential_speed_m_s);
    }
    ps.pin_force_N = (ps.film.radial_N - ps.normal_force_N) * ps.normal +
                     (ps.friction_force_N + ps.film.tangential_N) * ps.normal.perp();
  }
}

void solve_accelerations(const LinkageModel& m, const LinkageCoordinates& c, LinkageWorkspace& w) {
  const int n = m.coordinates(), nz = n + 1;
  w.M = ZMat::Zero(nz, nz);
  w.Q = ZVec::Zero(nz);
  const double g = m.rig().gravity_m_s2;
  w.strain_energy_J = w.modal_damping_power_W = 0;
  for (int k = 0; k < kBodies; ++k) {
    const BodyData& bd = m.body(k);
    const BodyFrame& b = w.body[static_cast<std::size_t>(k)];
    if (const ElasticLink* link = m.elastic(k)) {
      add_elastic_body(m, c, *link, k, w);
      continue;
    }
    const Vec2 rc = rotate(b.u, bd.centre_m);
    const ZJac Jc = point_jacobian(b, rc);
    const Vec2 ac = point_bias(b, rc);
    const Support cols = support(b, nz);  // Jc's columns are among the frame's
    const Eigen::Vector2d f{-bd.mass_kg * ac.x, bd.mass_kg * (-g - ac.y)};
    for (int a = 0; a < cols.size; ++a) {
      const int ia = cols.index(a);
      for (int c2 = 0; c2 < cols.size; ++c2) {
        const int ib = cols.index(c2);
        w.M(ia, ib) += bd.mass_kg * (Jc(0, ia) * Jc(0, ib) + Jc(1, ia) * Jc(1, ib)) +
                       bd.inertia_cg_kg_m2 * b.Jw(ia) * b.Jw(ib);
      }
      w.Q(ia) += Jc(0, ia) * f(0) + Jc(1, ia) * f(1) - bd.inertia_cg_kg_m2 * b.alpha_bias * b.Jw(ia);
    }
  }
  for (int j : m.clearance_joints()) {
    const PairState& ps = w.pair[static_cast<std::size_t>(j)];
    w.Q.noalias() += ps.J_rel.transpose() * Eigen::Vector2d{ps.pin_force_N.x, ps.pin_force_N.y};
  }
  w.z_accel = ZVec::Zero(nz);
  w.z_accel(n) = c.crank.accel_rad_s2;
  if (m.all_ideal()) {
    // θ3, θ4 prescribed (c.prescribed): solve the modal rows; the motor
    // torque by virtual work through the velocity ratios (θ3', θ4', 1).
    w.z_accel(0) = c.prescribed.alpha3_rad_s2;
    w.z_accel(1) = c.prescribed.alpha4_rad_s2;
    const int f = n - 2;
    const ZVec rhs = w.Q.segment(2, f) - w.M.block(2, 0, f, 2) * w.z_accel.head(2) - w.M.block(2, n, f, 1) * w.z_accel(n);
    ZVec x = rhs;
    if (!block_cholesky_solve(w.M, 2, f, x, w.mass_profile)) throw_indefinite_mass_matrix(c);
    w.z_accel.segment(2, f) = x;
    const ZVec residual = w.M * w.z_accel - w.Q;
    w.crank_torque_Nm = residual(n) + residual(0) * c.prescribed.ratio3 + residual(1) * c.prescribed.ratio4;
    return;
  }
  const ZVec rhs = w.Q.head(n) - w.M.block(0, n, n, 1) * c.crank.accel_rad_s2;
  ZVec x = rhs;
  if (!block_cholesky_solve(w.M, 0, n, x, w.mass_profile)) throw_indefinite_mass_matrix(c);
  w.z_accel.head(n) = x;
  w.crank_torque_Nm = w.M.row(n).dot(w.z_accel) - w.Q(n);
}

double kinetic_energy_J(const LinkageWorkspace& w, const LinkageCoordinates& c) {
  return 0.5 * c.z_rate.dot(w.M * c.z_rate);
}

double potential_energy_J(const LinkageModel& m, const LinkageWorkspace& w, const LinkageCoordinates& c) {
  double v = 0;
  for (int k = 0; k < kBodies; ++k) {
    const BodyFrame& b = w.body[static_cast<std::size_t>(k)];
    if (const ElasticLink* link = m.elastic(k)) {
      // m·R_y + (A·(S0 + S̄·η))_y
      const Eigen::Vector2d s = link->first_moment_kg_m + link->shape_moment * modal_state(m, c, w, k, false).eta_m;
      v += link->mass_kg * b.p.y + rotate(b.u, {s(0), s(1)}).y;
      continue;
    }
    v += m.body(k).mass_kg * (b.p + rotate(b.u, m.body(k).centre_m)).y;
  }
  return m.rig().gravity_m_s2 * v;
}

}  // namespace fourbar
