// The flexible slider-crank of the IVP test set (problem "crank", Simeon
// 1996; benchmarks/flexible-slider-crank.md), built through sim/flex: the
// connecting rod is an ElasticLink (two pinned–pinned bending sines, the test
// set's two quadratic axial shapes), the crank a rigid body driven at
// Ω = 150 rad/s, the slider a point mass on the x axis. The slider joint —
// the rod's deformed tip on the slider — is all this program adds.
//
// Coordinates q = (φ1, φ2, x3, η1 … η4), as the test set orders them. Each
// right-hand side solves the index-1 system
//   [ M(q)  Gᵀ ] [ q̈ ]   [ F(q, q̇) ]
//   [ G     0  ] [ λ ] = [ γ(q, q̇) ]
// with the test set's three constraints and their row scaling:
//   g1 = tip_y = 0,  g2 = x3 − tip_x = 0,  g3 = φ1 − Ω·t = 0,
// so λ compares one to one. M and F are Tᵀ·(rod's M, Q)·T plus the crank's
// and slider's inertia, T = ∂(R, θ, η)/∂q (the rod's frame origin is the crank
// pin R = l1·(cos φ1, sin φ1), its angle φ2). CVODE (BDF, dense Newton)
// integrates (q, q̇) from the test set's consistent start values to 0.1 s.
//
//   build/bench/flexible_slider_crank [--rtol X] [--adams] [--consistent-mass]
//
// prints one JSON object: phi2, x3, q1…q4, lambda1…lambda3 at t = 0.1 s, the
// rates phi2_dot and x3_dot, the constraint drift and `seconds` (CPU time of
// the integration). `--consistent-mass` uses the quadratic element's
// consistent axial mass instead of the test set's (see docs/flex.md).

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <iterator>
#include <string>

#include <Eigen/Dense>

#include "sim/flex/elastic_body.hpp"
#include "sim/flex/elastic_link.hpp"

using namespace fourbar;

namespace {

// Test set data (crank.f).
constexpr double kM2 = 0.151104, kM3 = 0.075552;
constexpr double kL1 = 0.15, kL2 = 0.30;
constexpr double kJ1 = 0.002727, kJ2 = 0.0045339259;
constexpr double kE = 0.20e12, kB = 0.008, kH = 0.008, kRho = 7870.0;
constexpr double kOmega = 150.0;
constexpr int kModes = 4, kNq = 3 + kModes, kNy = 2 * kNq;

ElasticLink rod_link(bool test_set_mass) {
  ElasticLinkSpec spec;
  spec.name = "connecting rod";
  spec.length_m = kL2;
  spec.mass_per_length_kg_m = kRho * kB * kH;
  spec.bending_stiffness_N_m2 = kE * kB * kH * kH * kH / 12;  // bending in the plane: b·h³/12
  spec.axial_stiffness_N = kE * kB * kH;
  spec.shapes = {{ShapeKind::lateral_sine, 1},
                 {ShapeKind::lateral_sine, 2},
                 {ShapeKind::axial_quadratic_mid, 0},
                 {ShapeKind::axial_quadratic_tip, 0}};
  // The test set's rod: m2 = ρ·b·h·L2, centre at L2/2, J2 about the crank pin
  // (m2·(L2²/3 + h²/12)).
  spec.rigid = RigidInertia{kM2, kL2 / 2, kJ2};
  if (test_set_mass) {
    // crank.f's MQ: the sines' ρAL/2, and for the axial pair ρAL·[8 1; 1 2],
    // 15× the quadratic element's consistent mass ρAL·[8 1; 1 2]/15.
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(kModes, kModes);
    const double facm = kRho * kB * kH * kL2;
    m(0, 0) = m(1, 1) = 0.5 * facm;
    m(2, 2) = 8 * facm;
    m(2, 3) = m(3, 2) = facm;
    m(3, 3) = 2 * facm;
    spec.modal_mass_override = m;
  }
  return build_elastic_link(spec);
}

struct SliderCrank {
  ElasticLink rod;
  ElasticBodyData body;
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(kNq + 3, kNq + 3);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(kNq + 3);
  Eigen::VectorXd solution = Eigen::VectorXd::Zero(kNq + 3);
  long rhs_calls = 0;

  explicit SliderCrank(bool test_set_mass) : rod(rod_link(test_set_mass)), body(rod) {}

  /// Frame and modal state of the rod from (q, q̇); accelerations zero (bias).
  void rod_state(const double* q, const double* qd, FrameState& frame, ModalState& modal) const {
    const double c1 = std::cos(q[0]), s1 = std::sin(q[0]);
    frame.origin_m = {kL1 * c1, kL1 * s1};
    frame.angle_rad = q[1];
    frame.velocity_m_s = {-kL1 * s1 * qd[0], kL1 * c1 * qd[0]};
    frame.angular_velocity_rad_s = qd[1];
    frame.acceleration_m_s2 = {-kL1 * c1 * qd[0] * qd[0], -kL1 * s1 * qd[0] * qd[0]};  // R̈ with φ̈1 = 0
    frame.angular_acceleration_rad_s2 = 0;
    modal.eta_m = Eigen::Map<const Eigen::VectorXd>(q + 3, kModes);
    modal.eta_dot_m_s = Eigen::Map<const Eigen::VectorXd>(qd + 3, kModes);
    modal.eta_ddot_m_s2 = Eigen::VectorXd::Zero(kModes);
  }

  /// Solves for q̈ and λ; fills `solution` = (q̈, λ).
  void accelerations(const double* q, const double* qd) {
    ++rhs_calls;
    FrameState frame;
    ModalState modal;
    rod_state(q, qd, frame, modal);
    body_terms(rod, body, frame, modal);
    // T = ∂z/∂q, z = (R_x, R_y, θ, η).
    Eigen::MatrixXd t = Eigen::MatrixXd::Zero(3 + kModes, kNq);
    t(0, 0) = -kL1 * std::sin(q[0]);
    t(1, 0) = kL1 * std::cos(q[0]);
    t(2, 1) = 1;
    for (int k = 0; k < kModes; ++k) t(3 + k, 3 + k) = 1;
    Eigen::VectorXd z_bias = Eigen::VectorXd::Zero(3 + kModes);
    z_bias.head<2>() << frame.acceleration_m_s2.x, frame.acceleration_m_s2.y;

    auto m = kkt.topLeftCorner(kNq, kNq);
    m = t.transpose() * body.mass * t;
    m(0, 0) += kJ1;  // crank about its pivot
    m(2, 2) += kM3;  // slider
    rhs.head(kNq) =
        t.transpose() * (body.quadratic_force + body.stiffness_force + body.damping_force - body.mass * z_bias);

    // The slider joint at the rod's deformed tip.
    point_jacobian(rod, body, kL2, frame, modal);
    const Eigen::Matrix2Xd g_tip = body.point_jacobian * t;
    const Vec2 tip_bias = point_acceleration(rod, kL2, frame, modal);
    Eigen::MatrixXd g = Eigen::MatrixXd::Zero(3, kNq);
    g.row(0) = g_tip.row(1);
    g.row(1) = -g_tip.row(0);
    g(1, 2) += 1;
    g(2, 0) = 1;
    kkt.bottomLeftCorner(3, kNq) = g;
    kkt.topRightCorner(kNq, 3) = g.transpose();
    rhs.tail(3) << -tip_bias.y, tip_bias.x, 0.0;
    solution = kkt.partialPivLu().solve(rhs);
  }

  /// Makes q̇ satisfy the velocity constraints G·q̇ = (0, 0, Ω) by the
  /// smallest impulse, q̇ += −M⁻¹Gᵀ(G·M⁻¹·Gᵀ)⁻¹·(G·q̇ − ġ): what an index-2
  /// DAE solver's first step does with the test set's 9-digit start values
  /// (their tip velocity is off by 1.2e-8 m/s, which would drift the tip by
  /// 1.2e-9 m and φ2 by 4e-9 rad in 0.1 s). Returns |G·q̇ − ġ| before.
  double make_velocities_consistent(const double* q, double* qd) {
    accelerations(q, qd);  // fills M and G in kkt
    const Eigen::MatrixXd m = kkt.topLeftCorner(kNq, kNq);
    const Eigen::MatrixXd g = kkt.bottomLeftCorner(3, kNq);
    Eigen::Map<Eigen::VectorXd> v(qd, kNq);
    const Eigen::Vector3d residual = g * v - Eigen::Vector3d(0, 0, kOmega);
    const Eigen::MatrixXd minv_gt = m.ldlt().solve(g.transpose());
    v -= minv_gt * (g * minv_gt).ldlt().solve(residual);
    return residual.norm();
  }

  /// Position constraint residuals g1, g2 (m).
  Eigen::Vector2d drift(double t_s, const double* q) const {
    FrameState frame;
    ModalState modal;
    const double zero[kNq] = {};
    rod_state(q, zero, frame, modal);
    const Vec2 tip = point_position(rod, kL2, frame, modal);
    (void)t_s;
    return {tip.y, q[2] - tip.x};
  }
};

int rhs_fn(sunrealtype, N_Vector y, N_Vector ydot, void* user) {
  auto* sys = static_cast<SliderCrank*>(user);
  const double* yv = N_VGetArrayPointer(y);
  double* d = N_VGetArrayPointer(ydot);
  sys->accelerations(yv, yv + kNq);
  for (int i = 0; i < kNq; ++i) {
    d[i] = yv[kNq + i];
    d[kNq + i] = sys->solution(i);
  }
  return 0;
}

void check(int flag, const char* what) {
  if (flag < 0) {
    std::fprintf(stderr, "flexible_slider_crank: CVODE %s failed (flag %d)\n", what, flag);
    std::exit(1);
  }
}

}  // namespace

int main(int argc, char** argv) {
  double rtol = 1e-11;
  bool adams = false, test_set_mass = true;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--rtol") && i + 1 < argc)
      rtol = std::stod(argv[++i]);
    else if (!std::strcmp(argv[i], "--adams"))
      adams = true;
    else if (!std::strcmp(argv[i], "--consistent-mass"))
      test_set_mass = false;
    else {
      std::fprintf(stderr, "usage: flexible_slider_crank [--rtol X] [--adams] [--consistent-mass]\n");
      return 2;
    }
  }
  SliderCrank sys(test_set_mass);

  // The test set's start values (crank.f, INIT): close to the smooth motion,
  // consistent for the linear stiffness without damping.
  const double y0[kNy] = {0.0,
                          0.0,
                          0.450016933,
                          0.0,
                          0.0,
                          0.103339863e-4,
                          0.169327969e-4,
                          150.0,
                          -74.9957670,
                          -0.268938672e-5,
                          0.444896105,
                          0.463434311e-2,
                          -0.178591076e-5,
                          -0.268938672e-5};

  double start[kNy];
  std::copy(std::begin(y0), std::end(y0), start);
  const double velocity_residual = sys.make_velocities_consistent(start, start + kNq);

  SUNContext ctx = nullptr;
  check(SUNContext_Create(nullptr, &ctx), "context");
  N_Vector y = N_VNew_Serial(kNy, ctx);
  for (int i = 0; i < kNy; ++i) N_VGetArrayPointer(y)[i] = start[i];
  void* mem = CVodeCreate(adams ? CV_ADAMS : CV_BDF, ctx);
  check(CVodeInit(mem, rhs_fn, 0.0, y), "init");
  // Absolute tolerances per component: angles and positions, elastic
  // coordinates (≈1e-5 m), their rates.
  N_Vector atol = N_VNew_Serial(kNy, ctx);
  double* a = N_VGetArrayPointer(atol);
  for (int i = 0; i < kNy; ++i) a[i] = rtol;
  for (int k = 0; k < kModes; ++k) {
    a[3 + k] = rtol * 1e-5;
    a[kNq + 3 + k] = rtol * 1e-2;
  }
  check(CVodeSVtolerances(mem, rtol, atol), "tolerances");
  SUNMatrix jac = SUNDenseMatrix(kNy, kNy, ctx);
  SUNLinearSolver ls = SUNLinSol_Dense(y, jac, ctx);
  check(CVodeSetLinearSolver(mem, ls, jac), "linear solver");
  check(CVodeSetUserData(mem, &sys), "user data");
  check(CVodeSetMaxNumSteps(mem, 10'000'000), "max steps");
  if (!adams) check(CVodeSetStabLimDet(mem, SUNTRUE), "stability limit detection");

  const std::clock_t c0 = std::clock();
  double t = 0;
  check(CVode(mem, 0.1, y, &t, CV_NORMAL), "integration to 0.1 s");
  const double seconds = double(std::clock() - c0) / CLOCKS_PER_SEC;

  const double* yv = N_VGetArrayPointer(y);
  sys.accelerations(yv, yv + kNq);
  const Eigen::Vector2d g = sys.drift(t, yv);
  long steps = 0;
  CVodeGetNumSteps(mem, &steps);
  std::printf(
      "{\"phi2\": %.16e, \"x3\": %.16e, \"q1\": %.16e, \"q2\": %.16e, \"q3\": %.16e, \"q4\": %.16e, "
      "\"lambda1\": %.16e, \"lambda2\": %.16e, \"lambda3\": %.16e, \"phi2_dot\": %.16e, \"x3_dot\": %.16e, "
      "\"drift_m\": %.3e, \"start_velocity_residual_m_s\": %.3e, \"rtol\": %.1e, \"method\": \"%s\", \"steps\": %ld, "
      "\"rhs_calls\": %ld, "
      "\"seconds\": %.4f}\n",
      yv[1], yv[2], yv[3], yv[4], yv[5], yv[6], sys.solution(kNq), sys.solution(kNq + 1), sys.solution(kNq + 2),
      yv[kNq + 1], yv[kNq + 2], g.norm(), velocity_residual, rtol, adams ? "adams" : "bdf", steps, sys.rhs_calls,
      seconds);

  CVodeFree(&mem);
  SUNLinSolFree(ls);
  SUNMatDestroy(jac);
  N_VDestroy(atol);
  N_VDestroy(y);
  SUNContext_Free(&ctx);
  return 0;
}
