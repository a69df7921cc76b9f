// The elastic link's constant integrals against closed forms: Euler–Bernoulli
// frequencies of a pinned–pinned uniform beam, the sine and quadratic shapes'
// integrals (the IVP test set's c1, c2, c12, c21, B, K), modal damping, and
// the checks on bad input.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "common/error.hpp"
#include "sim/flex/elastic_link.hpp"

namespace fourbar {
namespace {

constexpr double pi = std::numbers::pi;

// The thesis coupler: 25 × 4 mm steel bar, 309 mm between the pins.
BeamSection coupler_section() {
  BeamSection s;
  s.youngs_modulus_Pa = 210e9;
  s.density_kg_m3 = 7850;
  s.area_m2 = 25e-3 * 4e-3;
  s.second_moment_m4 = 4e-3 * std::pow(25e-3, 3) / 12;
  s.depth_m = 25e-3;
  return s;
}

TEST(ElasticLink, PinnedPinnedFrequenciesAreEulerBernoulli) {
  const BeamSection sec = coupler_section();
  const double L = 0.309;
  const ElasticLink link = build_elastic_link(pinned_pinned_link(L, sec, 4));
  const double ei = sec.youngs_modulus_Pa * sec.second_moment_m4, rho_a = sec.density_kg_m3 * sec.area_m2;
  for (int n = 1; n <= 4; ++n) {
    const double exact = std::pow(n * pi / L, 2) * std::sqrt(ei / rho_a);
    EXPECT_NEAR(link.frequencies_rad_s(n - 1) / exact, 1.0, 1e-12) << "mode " << n;
  }
  // About 600 Hz, as issue 25 says for this bar.
  EXPECT_NEAR(link.frequencies_rad_s(0) / (2 * pi), 614.5, 1.0);
}

TEST(ElasticLink, SineIntegralsMatchClosedForms) {
  ElasticLinkSpec spec = pinned_pinned_link(0.3, coupler_section(), 3);
  const ElasticLink link = build_elastic_link(spec);
  const double mu = spec.mass_per_length_kg_m, L = 0.3;
  EXPECT_NEAR(link.mass_kg, mu * L, 1e-15);
  for (int k = 1; k <= 3; ++k) {
    const int i = k - 1;
    EXPECT_NEAR(link.modal_mass(i, i), mu * L / 2, 1e-14);
    EXPECT_NEAR(link.shape_moment(1, i), mu * L * (1 - std::cos(k * pi)) / (k * pi), 1e-14);
    EXPECT_NEAR(link.shape_moment(0, i), 0.0, 1e-16);
    EXPECT_NEAR(link.bending_coupling(i), mu * L * L * -std::cos(k * pi) / (k * pi), 1e-14);
    for (int j = 0; j < 3; ++j)
      if (j != i) EXPECT_NEAR(link.modal_mass(i, j), 0.0, 1e-15);
  }
  EXPECT_NEAR((link.gyroscopic + link.gyroscopic.transpose()).norm(), 0.0, 1e-18);
}

// The IVP test set's flexible slider-crank rod: two sines, two quadratic
// axial shapes; its integrals in crank.f are written in closed form.
TEST(ElasticLink, QuadraticAxialIntegralsMatchTheTestSet) {
  ElasticLinkSpec spec;
  spec.name = "rod";
  spec.length_m = 0.3;
  const double rho = 7870, A = 64e-6, E = 2e11, I = 8e-3 * std::pow(8e-3, 3) / 12, L = 0.3;
  spec.mass_per_length_kg_m = rho * A;
  spec.bending_stiffness_N_m2 = E * I;
  spec.axial_stiffness_N = E * A;
  spec.shapes = {{ShapeKind::lateral_sine, 1},
                 {ShapeKind::lateral_sine, 2},
                 {ShapeKind::axial_quadratic_mid, 0},
                 {ShapeKind::axial_quadratic_tip, 0}};
  const ElasticLink link = build_elastic_link(spec);
  const double facb = A * L, fack = E * A / L;
  const double tol = 1e-13;
  EXPECT_NEAR(link.shape_moment(0, 2) / rho, facb * 2 / 3, tol);
  EXPECT_NEAR(link.shape_moment(0, 3) / rho, facb / 6, tol);
  EXPECT_NEAR(link.shape_moment(1, 0) / rho, facb * 2 / pi, tol);
  EXPECT_NEAR(link.axial_coupling(2) / rho, L * facb / 3, tol);
  EXPECT_NEAR(link.axial_coupling(3) / rho, L * facb / 6, tol);
  EXPECT_NEAR(link.bending_coupling(0) / rho, L * facb / pi, tol);
  EXPECT_NEAR(link.bending_coupling(1) / rho, -L * facb / (2 * pi), tol);
  EXPECT_NEAR(link.gyroscopic(2, 0) / rho, facb * 16 / std::pow(pi, 3), tol);
  EXPECT_NEAR(link.gyroscopic(3, 0) / rho, -facb * (8 / std::pow(pi, 3) - 1 / pi), tol);
  EXPECT_NEAR(link.gyroscopic(3, 1) / rho, -facb * 0.5 / pi, tol);
  EXPECT_NEAR(link.modal_stiffness(0, 0) / (fack * std::pow(pi, 4) / 24 * std::pow(8e-3 / L, 2)), 1.0, 1e-12);
  EXPECT_NEAR(link.modal_stiffness(1, 1) / (fack * std::pow(pi, 4) * 2 / 3 * std::pow(8e-3 / L, 2)), 1.0, 1e-12);
  EXPECT_NEAR(link.modal_stiffness(2, 2) / fack, 16.0 / 3, 1e-12);
  EXPECT_NEAR(link.modal_stiffness(2, 3) / fack, -8.0 / 3, 1e-12);
  EXPECT_NEAR(link.modal_stiffness(3, 3) / fack, 7.0 / 3, 1e-12);
  // The consistent mass of the quadratic element: ρAL·[8 1; 1 2]/15.
  EXPECT_NEAR(link.modal_mass(2, 2) / (rho * facb), 8.0 / 15, 1e-13);
  EXPECT_NEAR(link.modal_mass(2, 3) / (rho * facb), 1.0 / 15, 1e-13);
  EXPECT_NEAR(link.modal_mass(3, 3) / (rho * facb), 2.0 / 15, 1e-13);
}

TEST(ElasticLink, ModalDampingIsTwoZetaOmegaM) {
  const ElasticLink link = build_elastic_link(pinned_pinned_link(0.309, coupler_section(), 3, {0.01, 0.02}));
  for (int k = 0; k < 3; ++k) {
    const double zeta = k == 0 ? 0.01 : 0.02;  // the last ratio repeats
    EXPECT_NEAR(link.modal_damping(k, k) / (2 * zeta * link.frequencies_rad_s(k) * link.modal_mass(k, k)), 1.0, 1e-12);
  }
  EXPECT_NEAR(link.modal_damping(0, 1), 0.0, 1e-9);
}

TEST(ElasticLink, MeasuredFrequenciesSetTheStiffness) {
  ElasticLinkSpec spec = pinned_pinned_link(0.309, coupler_section(), 2, {0.02});
  spec.bending_stiffness_N_m2 = 0;
  spec.measured_frequencies_Hz = {580.0, 2400.0};
  const ElasticLink link = build_elastic_link(spec);
  EXPECT_NEAR(link.frequencies_rad_s(0) / (2 * pi), 580.0, 1e-9);
  EXPECT_NEAR(link.frequencies_rad_s(1) / (2 * pi), 2400.0, 1e-9);
}

TEST(ElasticLink, BadInputNamesTheQuantity) {
  auto message = [](ElasticLinkSpec spec) {
    try {
      build_elastic_link(spec);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  ElasticLinkSpec good = pinned_pinned_link(0.309, coupler_section(), 2);
  good.name = "coupler";
  ElasticLinkSpec s = good;
  s.bending_stiffness_N_m2 = 0;
  EXPECT_NE(message(s).find("bending stiffness"), std::string::npos) << message(s);
  s = good;
  s.damping_ratios = {1.0};
  EXPECT_NE(message(s).find("damping ratio 1"), std::string::npos) << message(s);
  s = good;
  s.measured_frequencies_Hz = {-5, 100};
  EXPECT_NE(message(s).find("must be > 0"), std::string::npos) << message(s);
  s = good;
  s.measured_frequencies_Hz = {500};
  EXPECT_NE(message(s).find("one per mode"), std::string::npos) << message(s);
  s = good;
  s.mass_per_length_kg_m = 0;
  EXPECT_NE(message(s).find("mass per length"), std::string::npos) << message(s);
  EXPECT_NE(message(s).find("'coupler'"), std::string::npos) << message(s);
}

// A uniform bar's measured inertia, m·L²/12 about its centre written to a few
// figures, may round below the linear mass per length's own: it is taken as
// that (no rotary part), while an inertia 1 % lower still names the key.
TEST(ElasticLink, AUniformBarsRoundedInertiaIsTakenAsItsOwn) {
  ElasticLinkSpec spec = pinned_pinned_link(0.309, coupler_section(), 2);
  spec.name = "coupler";
  const double m = 0.2439, L = 0.309, centre = L / 2;
  const double exact_about_centre_kg_mm2 = m * L * L / 12 * 1e6;  // 1940.65133…
  for (const double written : {1940.6513, 1940.65, 1940.6, exact_about_centre_kg_mm2}) {
    spec.rigid = RigidInertia{m, centre, written * 1e-6 + m * centre * centre};
    const ElasticLink link = build_elastic_link(spec);
    EXPECT_NEAR(link.inertia_origin_kg_m2, m * L * L / 3, 1e-4 * m * L * L / 3) << written;
    EXPECT_NEAR(link.mass_kg, m, 1e-15);
  }
  spec.rigid = RigidInertia{m, centre, 0.99 * exact_about_centre_kg_mm2 * 1e-6 + m * centre * centre};
  try {
    build_elastic_link(spec);
    ADD_FAILURE() << "an inertia 1 % below the uniform bar's was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("inertia_kg_mm2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fourbar

namespace fourbar {
namespace {

// Modal superposition of the thesis coupler's static deflection under its own
// weight converges to 5qL⁴/(384EI) as the odd terms 1/k⁵ (docs/flex.md table).
TEST(ElasticLink, StaticDeflectionConvergesWithTheModes) {
  const BeamSection sec = coupler_section();
  const double L = 0.309, ei = sec.youngs_modulus_Pa * sec.second_moment_m4, mu = sec.density_kg_m3 * sec.area_m2;
  const double exact = 5 * mu * 9.81 * std::pow(L, 4) / (384 * ei);
  double previous_error = 1;
  for (int n : {1, 4, 8}) {
    const ElasticLink link = build_elastic_link(pinned_pinned_link(L, sec, n));
    const Eigen::VectorXd eta = link.modal_stiffness.ldlt().solve(9.81 * link.shape_moment.row(1).transpose());
    double mid = 0;
    for (int k = 0; k < n; ++k) mid += eta(k) * std::sin((k + 1) * pi / 2);
    const double error = std::abs(mid / exact - 1);
    EXPECT_LT(error, previous_error / 10) << n << " modes";
    previous_error = error;
  }
  EXPECT_LT(previous_error, 2e-5);
}

}  // namespace
}  // namespace fourbar
