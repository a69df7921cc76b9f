#include "sim/flex/elastic_link.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "common/error.hpp"
#include "common/format.hpp"
#include "sim/flex/gauss_legendre.hpp"

namespace fourbar {

ElasticLinkSpec pinned_pinned_link(double length_m, const BeamSection& section, int modes,
                                   std::vector<double> damping_ratios) {
  ElasticLinkSpec spec;
  spec.length_m = length_m;
  spec.mass_per_length_kg_m = section.density_kg_m3 * section.area_m2;
  spec.bending_stiffness_N_m2 = section.youngs_modulus_Pa * section.second_moment_m4;
  spec.axial_stiffness_N = section.youngs_modulus_Pa * section.area_m2;
  spec.depth_m = section.depth_m;
  for (int k = 1; k <= modes; ++k) spec.shapes.push_back({ShapeKind::lateral_sine, k});
  spec.damping_ratios = std::move(damping_ratios);
  return spec;
}

namespace {

/// The share of a measured inertia about the first joint by which it may lie
/// below the linear mass per length's and be taken as rounding (build_elastic_link).
constexpr double kInertiaRounding = 1e-4;

[[noreturn]] void bad(const ElasticLinkSpec& spec, const std::string& what) {
  throw InputError("elastic link '" + spec.name + "': " + what);
}

void check_spec(const ElasticLinkSpec& spec) {
  auto positive = [&](double v, const char* what, const char* fix) {
    if (!(v > 0) || !std::isfinite(v)) bad(spec, std::string(what) + " = " + format_number(v) + " must be > 0; " + fix);
  };
  positive(spec.length_m, "length", "give the joint-to-joint length");
  positive(spec.mass_per_length_kg_m, "mass per length",
           "give the density and the section area (a section with no area has no mass)");
  if (spec.shapes.empty()) bad(spec, "has no mode shapes; give at least one mode (or make the link rigid)");
  bool lateral = false, axial = false;
  for (const ShapeFunction& f : spec.shapes) {
    (is_lateral(f) ? lateral : axial) = true;
    if ((f.kind == ShapeKind::lateral_sine || f.kind == ShapeKind::axial_sine) && f.index < 1)
      bad(spec, "shape index " + std::to_string(f.index) + " must be >= 1");
  }
  const bool measured = !spec.measured_frequencies_Hz.empty();
  if (lateral && !measured && !spec.modal_stiffness_override)
    positive(spec.bending_stiffness_N_m2, "bending stiffness EI",
             "give Young's modulus and the section's second moment (or measured mode frequencies)");
  if (axial && !spec.modal_stiffness_override)
    positive(spec.axial_stiffness_N, "axial stiffness EA", "give Young's modulus and the section area");
  if (measured) {
    if (axial) bad(spec, "measured frequencies describe bending modes only; drop the axial shapes");
    if (spec.measured_frequencies_Hz.size() != spec.shapes.size())
      bad(spec, std::to_string(spec.measured_frequencies_Hz.size()) + " measured frequencies for " +
                    std::to_string(spec.shapes.size()) + " modes; give one per mode");
    double previous = 0;
    for (double f : spec.measured_frequencies_Hz) {
      if (!(f > 0) || !std::isfinite(f))
        bad(spec, "measured frequency " + format_number(f) + " Hz must be > 0 (a tap test's peak, in Hz)");
      if (!(f > previous)) bad(spec, "measured frequencies must increase (lowest mode first)");
      previous = f;
    }
  }
  for (double z : spec.damping_ratios)
    if (!(z >= 0 && z < 1))
      bad(spec, "damping ratio " + format_number(z) +
                    " must lie in [0, 1): a link rings with ζ of about 0.001–0.05; ζ >= 1 does not ring");
  const auto n = static_cast<Eigen::Index>(spec.shapes.size());
  for (const auto* m : {&spec.modal_mass_override, &spec.modal_stiffness_override})
    if (*m && ((*m)->rows() != n || (*m)->cols() != n)) bad(spec, "a modal matrix override has the wrong size");
}

/// The mass per length the inertia integrals use, μ(s) = μ0 + μ1·s/L, and a
/// rotary inertia J that enters I0 alone. Without a measured rigid inertia,
/// the uniform beam (μ1 = 0, J = m·d²/12). With one, the linear μ that has
/// the measured mass and centre, and J the rest of the measured inertia: the
/// modal integrals (S̄, c, M_ff, B) must come from the same distribution as
/// m, S0 and I0, or the mass matrix is not that of any body and, once the
/// modes can represent a rigid motion (3 or more sines), it is indefinite.
struct MassDistribution {
  double mu0_kg_m = 0, mu1_kg_m = 0, rotary_kg_m2 = 0;
};

MassDistribution mass_distribution(const ElasticLinkSpec& spec) {
  const double L = spec.length_m, mu = spec.mass_per_length_kg_m;
  double mu0 = mu, mu1 = 0, rotary = mu * L * spec.depth_m * spec.depth_m / 12;
  if (spec.rigid) {
    const RigidInertia& r = *spec.rigid;
    if (!(r.mass_kg > 0) || !(r.inertia_origin_kg_m2 > 0))
      bad(spec, "its rigid mass and inertia must be > 0 (check the link's mass_kg and inertia_kg_mm2)");
    const double centre = r.mass_centre_m / L;
    mu1 = 12 * r.mass_kg * (centre - 0.5) / L;
    mu0 = r.mass_kg / L - mu1 / 2;
    if (mu0 < 0 || mu0 + mu1 < 0)
      bad(spec, "its mass centre at " + format_number(centre) +
                    " of the length lies outside the middle third, where no mass per length that grows or "
                    "falls linearly along the link has it; check mass_centre_mm or make the link rigid");
    rotary = r.inertia_origin_kg_m2 - L * L * L * (mu0 / 3 + mu1 / 4);
    // A uniform bar's own inertia written to 4–6 figures (m·L²/12 about the
    // centre, rounded down) sits a rounding below the linear μ's: the thesis
    // coupler as a uniform bar, 1940.6513 kg·mm² for 1940.65133, was refused.
    // A deficit up to kInertiaRounding of I0 is taken as J = 0 (the model's
    // I0 then exceeds the file's by at most that share); more is a link whose
    // mass lies nearer its centre than a linear μ can put it.
    if (rotary < -kInertiaRounding * r.inertia_origin_kg_m2)
      bad(spec, "its inertia about the first joint, " + format_number(r.inertia_origin_kg_m2) +
                    " kg·m², is below that of the mass per length with its mass and centre (" +
                    format_number(r.inertia_origin_kg_m2 - rotary) +
                    " kg·m²): no mass per length that grows or falls linearly along the link has these; check "
                    "inertia_kg_mm2 (about the mass centre) or make the link rigid");
    rotary = std::max(rotary, 0.0);
  }
  return {mu0, mu1, rotary};
}

/// The shapes' integrals over the link (S̄, c, b, M_ff, B, K_ff) by Gauss
/// quadrature, and the rigid part's m, S0, I0 of the same distribution.
void integrate_shapes(const ElasticLinkSpec& spec, const MassDistribution& d, ElasticLink& link) {
  const int n = link.modes();
  const double L = spec.length_m, mu0 = d.mu0_kg_m, mu1 = d.mu1_kg_m;
  link.shape_moment = Eigen::Matrix2Xd::Zero(2, n);
  link.axial_coupling = Eigen::VectorXd::Zero(n);
  link.bending_coupling = Eigen::VectorXd::Zero(n);
  link.modal_mass = Eigen::MatrixXd::Zero(n, n);
  link.gyroscopic = Eigen::MatrixXd::Zero(n, n);
  link.modal_stiffness = Eigen::MatrixXd::Zero(n, n);
  // Highest shape wavenumber decides the panels: 16 nodes per half-wave is
  // far beyond what a product of two sines needs for rounding accuracy.
  int highest = 1;
  for (const ShapeFunction& f : spec.shapes) highest = std::max(highest, 2 * f.index);
  const QuadratureRule rule = gauss_legendre_unit(20, highest);
  std::vector<ShapeValue> v(static_cast<std::size_t>(n));
  for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
    const double xi = rule.nodes[q], w = rule.weights[q] * L;  // ds = L·dξ
    const double s = xi * L, mu_s = mu0 + mu1 * xi;
    for (int k = 0; k < n; ++k) v[static_cast<std::size_t>(k)] = evaluate(spec.shapes[static_cast<std::size_t>(k)], xi);
    for (int k = 0; k < n; ++k) {
      const ShapeValue& a = v[static_cast<std::size_t>(k)];
      link.shape_moment(0, k) += w * mu_s * a.x;
      link.shape_moment(1, k) += w * mu_s * a.y;
      link.axial_coupling(k) += w * mu_s * s * a.x;
      link.bending_coupling(k) += w * mu_s * s * a.y;
      for (int j = 0; j < n; ++j) {
        const ShapeValue& b = v[static_cast<std::size_t>(j)];
        link.modal_mass(k, j) += w * mu_s * (a.x * b.x + a.y * b.y);
        link.gyroscopic(k, j) += w * mu_s * (a.x * b.y - a.y * b.x);
        // Φ'' in s is Φ''(ξ)/L², Φ' is Φ'(ξ)/L.
        link.modal_stiffness(k, j) += w * (spec.bending_stiffness_N_m2 * a.ddy * b.ddy / (L * L * L * L) +
                                           spec.axial_stiffness_N * a.dx * b.dx / (L * L));
      }
    }
  }
  if (spec.modal_mass_override) link.modal_mass = *spec.modal_mass_override;
  if (spec.modal_stiffness_override) link.modal_stiffness = *spec.modal_stiffness_override;

  // ∫μ ds, ∫μ s ds, ∫μ s² ds + J of the linear μ (for a rigid inertia: the measured m, m·x_c and I0).
  link.mass_kg = L * (mu0 + mu1 / 2);
  link.first_moment_kg_m = {L * L * (mu0 / 2 + mu1 / 3), 0.0};
  link.inertia_origin_kg_m2 = L * L * L * (mu0 / 3 + mu1 / 4) + d.rotary_kg_m2;
}

/// The mass matrix at η = 0 (elastic_body.hpp's M with A = I) must be
/// positive definite: a modal mass override can break it as a mismatched
/// rigid inertia did.
void check_mass_matrix(const ElasticLinkSpec& spec, const ElasticLink& link) {
  const int n = link.modes();
  Eigen::MatrixXd m0 = Eigen::MatrixXd::Zero(3 + n, 3 + n);
  m0(0, 0) = m0(1, 1) = link.mass_kg;
  m0(1, 2) = m0(2, 1) = link.first_moment_kg_m.x();
  m0(2, 2) = link.inertia_origin_kg_m2;
  m0.block(0, 3, 2, n) = link.shape_moment;
  m0.block(2, 3, 1, n) = link.bending_coupling.transpose();
  m0.block(3, 3, n, n) = link.modal_mass;
  if (Eigen::LLT<Eigen::MatrixXd>(m0.selfadjointView<Eigen::Upper>()).info() != Eigen::Success)
    bad(spec, "its mass matrix is not positive definite (the modal mass does not fit its mass and inertia); "
              "check the modal mass override against the link's mass, centre and inertia");
}

/// The modes: the stiffness from measured frequencies when given, the
/// frequencies and shapes of K·ψ = ω²·M·ψ, and the modal damping.
void set_modes(const ElasticLinkSpec& spec, ElasticLink& link) {
  const int n = link.modes();
  if (!spec.measured_frequencies_Hz.empty()) {
    // Mode k is shape k made M_ff-orthogonal to the shapes below it (Gram–
    // Schmidt: Ψ = L⁻ᵀ with M_ff = L·Lᵀ) and rings at f_k: K = L·diag(ω²)·Lᵀ
    // (for a uniform link M_ff is diagonal and K_kk = ω_k²·M_kk).
    const Eigen::LLT<Eigen::MatrixXd> chol(link.modal_mass);
    Eigen::VectorXd w2(n);
    for (int k = 0; k < n; ++k)
      w2(k) = std::pow(2 * std::numbers::pi * spec.measured_frequencies_Hz[static_cast<std::size_t>(k)], 2);
    const Eigen::MatrixXd l = chol.matrixL();
    link.modal_stiffness = l * w2.asDiagonal() * l.transpose();
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(link.modal_stiffness, link.modal_mass);
  if (eig.info() != Eigen::Success || !(eig.eigenvalues().minCoeff() > 0))
    bad(spec,
        "its modes have no stiffness (an eigenvalue of K·ψ = ω²·M·ψ is <= 0); check E, the second moment "
        "and the area, or the measured frequencies");
  link.frequencies_rad_s = eig.eigenvalues().cwiseSqrt();
  link.mode_vectors = eig.eigenvectors();

  link.damping_ratios = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < n && !spec.damping_ratios.empty(); ++k)
    link.damping_ratios(k) = spec.damping_ratios[std::min(static_cast<std::size_t>(k), spec.damping_ratios.size() - 1)];
  const Eigen::MatrixXd mpsi = link.modal_mass * link.mode_vectors;
  link.modal_damping =
      mpsi * (2 * link.damping_ratios.cwiseProduct(link.frequencies_rad_s)).asDiagonal() * mpsi.transpose();
}

}  // namespace

ElasticLink build_elastic_link(const ElasticLinkSpec& spec) {
  check_spec(spec);
  ElasticLink link;
  link.name = spec.name;
  link.length_m = spec.length_m;
  link.shapes = spec.shapes;
  integrate_shapes(spec, mass_distribution(spec), link);
  check_mass_matrix(spec, link);
  set_modes(spec, link);
  return link;
}

}  // namespace fourbar
