// The lubricated bearing's short-bearing film force (film_force.hpp) against
// a second formulation: the pressure p(θ, z) integrated numerically over the
// bearing (Gauss–Legendre in z, adaptive Gauss–Kronrod in θ over the arcs
// where the film is taken to exist, found by sampling the pressure's sign),
// the squeeze-film load of textbook short-bearing theory, Flores et al.'s
// π-film formulas, and the continuity of the handover to dry contact.

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <vector>

#include "common/units.hpp"
#include "sim/contact/film_force.hpp"

namespace fourbar {
namespace {

constexpr double kPi = units::kPi;

JournalFilm film(FilmExtent extent) {
  JournalFilm f;
  f.viscosity_Pa_s = 0.05;
  f.radius_m = 10e-3;
  f.length_m = 10e-3;
  f.clearance_m = 0.254e-3;
  f.extent = extent;
  return f;
}

/// p(θ, z) of short-bearing theory (film_force.hpp) written out directly.
double pressure_Pa(const JournalFilm& f, double eps, double eps_rate, double eps_whirl, double theta, double z) {
  const double h = f.clearance_m * (1.0 - eps * std::cos(theta));
  return 3.0 * f.viscosity_Pa_s * f.clearance_m / (h * h * h) * (0.25 * f.length_m * f.length_m - z * z) *
         (2.0 * eps_rate * std::cos(theta) - eps_whirl * std::sin(theta));
}

/// F = −∫∫ p·(cos θ, sin θ)·R dθ dz over the film, numerically.
FilmForce integrated(const JournalFilm& f, double eps, double eps_rate, double eps_whirl) {
  const double half = 0.5 * f.length_m;
  auto axial = [&](double theta) {  // ∫ p dz, 5-point Gauss–Legendre
    return boost::math::quadrature::gauss<double, 5>::integrate(
        [&](double z) { return pressure_Pa(f, eps, eps_rate, eps_whirl, theta, z); }, -half, half);
  };
  // The film's arcs in θ ∈ [−π, π] (or [−3π/2, 3π/2] unwrapped: simply the
  // whole circle cut where the pressure changes sign).
  std::vector<std::pair<double, double>> arcs;
  if (f.extent == FilmExtent::full) {
    arcs.push_back({-kPi, kPi});
  } else if (f.extent == FilmExtent::pinkus_sternlicht) {
    arcs.push_back({-kPi, 0.0});
  } else {
    auto q = [&](double th) { return 2.0 * eps_rate * std::cos(th) - eps_whirl * std::sin(th); };
    const int n = 2000;
    std::vector<double> cuts{-kPi};
    for (int i = 0; i < n; ++i) {
      double a = -kPi + 2 * kPi * i / n, b = -kPi + 2 * kPi * (i + 1) / n;
      if ((q(a) > 0) == (q(b) > 0)) continue;
      for (int it = 0; it < 200 && b - a > 1e-15; ++it) {
        const double m = 0.5 * (a + b);
        ((q(m) > 0) == (q(a) > 0) ? a : b) = m;
      }
      cuts.push_back(0.5 * (a + b));
    }
    cuts.push_back(kPi);
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
      if (q(0.5 * (cuts[i] + cuts[i + 1])) > 0) arcs.push_back({cuts[i], cuts[i + 1]});
  }
  FilmForce out;
  for (const auto& [a, b] : arcs) {
    using GK = boost::math::quadrature::gauss_kronrod<double, 61>;
    out.radial_N -= f.radius_m * GK::integrate([&](double th) { return axial(th) * std::cos(th); }, a, b, 15, 1e-11);
    out.tangential_N -=
        f.radius_m * GK::integrate([&](double th) { return axial(th) * std::sin(th); }, a, b, 15, 1e-11);
  }
  return out;
}

TEST(FilmForce, ClosedFormMatchesTheIntegratedPressure) {
  for (FilmExtent extent : {FilmExtent::cavitated, FilmExtent::pinkus_sternlicht, FilmExtent::full}) {
    const JournalFilm f = film(extent);
    for (double eps : {0.0, 0.1, 0.5, 0.8, 0.95})
      for (const auto& [rate, whirl] : {std::pair{0.0, 30.0}, std::pair{0.0, -30.0}, std::pair{5.0, 0.0},
                                        std::pair{-5.0, 0.0}, std::pair{3.0, 40.0}, std::pair{-3.0, 40.0},
                                        std::pair{7.0, -2.0}, std::pair{-0.4, -25.0}}) {
        SCOPED_TRACE(std::string(to_string(extent)) + " eps " + std::to_string(eps) + " rate " +
                     std::to_string(rate) + " whirl " + std::to_string(whirl));
        const FilmForce c = short_bearing_force(f, eps, rate, eps * whirl);
        const FilmForce n = integrated(f, eps, rate, eps * whirl);
        const double scale = std::hypot(n.radial_N, n.tangential_N);
        if (eps == 0 && rate == 0) {  // no film force at all: the centred journal only turning
          EXPECT_EQ(c.radial_N, 0.0);
          EXPECT_EQ(c.tangential_N, 0.0);
          continue;
        }
        ASSERT_GT(scale, 0.0);
        EXPECT_NEAR(c.radial_N, n.radial_N, 1e-8 * scale);
        EXPECT_NEAR(c.tangential_N, n.tangential_N, 1e-8 * scale);
      }
  }
}

TEST(FilmForce, SqueezeFilmLoadOfShortBearingTheory) {
  // Pure radial approach, no rotation, along −n only. Full film: the
  // short-bearing squeeze load W = π·μ·R·L³·ε̇·(1 + 2ε²)/(c²·(1 − ε²)^(5/2))
  // (e.g. Hamrock, Fundamentals of Fluid Film Lubrication); at ε = 0 the
  // hand integral π·μ·R·L³·ε̇/c². The fixed π-film (θ ∈ [−π, 0]) carries
  // exactly half of it (cos²θ/(1 − ε cos θ)³ is even in θ). The cavitated
  // film keeps the positive pressure only, |θ| < π/2, which carries more:
  // W·[(π/2 + asin ε)·(1 + 2ε²) + 3ε·√(1 − ε²)]/(π·(1 + 2ε²)), from
  // ∫cos²θ/(1 − ε cos θ)³ dθ over |θ| < π/2 worked by hand.
  for (double eps : {0.0, 0.3, 0.6, 0.9, 0.95}) {
    const double rate = 2.5;
    const JournalFilm f = film(FilmExtent::full);
    const double w = kPi * f.viscosity_Pa_s * f.radius_m * std::pow(f.length_m, 3) * rate * (1 + 2 * eps * eps) /
                     (f.clearance_m * f.clearance_m * std::pow(1 - eps * eps, 2.5));
    SCOPED_TRACE(eps);
    const FilmForce full = short_bearing_force(f, eps, rate, 0.0);
    EXPECT_NEAR(full.radial_N, -w, 1e-12 * w);
    EXPECT_NEAR(full.tangential_N, 0.0, 1e-12 * w);
    const FilmForce ps = short_bearing_force(film(FilmExtent::pinkus_sternlicht), eps, rate, 0.0);
    EXPECT_NEAR(ps.radial_N, -0.5 * w, 1e-12 * w);
    const FilmForce cav = short_bearing_force(film(FilmExtent::cavitated), eps, rate, 0.0);
    const double share = ((0.5 * kPi + std::asin(eps)) * (1 + 2 * eps * eps) + 3 * eps * std::sqrt(1 - eps * eps)) /
                         (kPi * (1 + 2 * eps * eps));
    EXPECT_NEAR(cav.radial_N, -share * w, 1e-12 * w);
    EXPECT_NEAR(cav.tangential_N, 0.0, 1e-12 * w);
  }
}

TEST(FilmForce, PinkusSternlichtFormulasOfFloresEtAl) {
  const JournalFilm f = film(FilmExtent::pinkus_sternlicht);
  const double g = f.viscosity_Pa_s * f.radius_m * std::pow(f.length_m, 3) / (2 * f.clearance_m * f.clearance_m);
  for (double eps : {0.2, 0.7, 0.93})
    for (const auto& [rate, wbar] : {std::pair{1.5, 20.0}, std::pair{-4.0, 60.0}}) {
      const double q = 1 - eps * eps;
      const double fr = -g * (2 * eps * eps * wbar / (q * q) + kPi * rate * (1 + 2 * eps * eps) / std::pow(q, 2.5));
      const double ft = g * (kPi * eps * wbar / (2 * std::pow(q, 1.5)) + 4 * eps * rate / (q * q));
      const FilmForce c = short_bearing_force(f, eps, rate, eps * wbar);
      EXPECT_NEAR(c.radial_N, fr, 1e-12 * std::abs(fr));
      EXPECT_NEAR(c.tangential_N, ft, 1e-12 * std::abs(ft));
      // The cavitated film is the same when ε̇ = 0.
      const FilmForce pure = short_bearing_force(film(FilmExtent::cavitated), eps, 0.0, eps * wbar);
      const FilmForce ps = short_bearing_force(f, eps, 0.0, eps * wbar);
      EXPECT_NEAR(pure.radial_N, ps.radial_N, 1e-12 * std::abs(ps.radial_N));
      EXPECT_NEAR(pure.tangential_N, ps.tangential_N, 1e-12 * std::abs(ps.tangential_N));
    }
}

TEST(FilmForce, ContinuousWhereTheWhirlChangesSign) {
  // ω̄ through zero with ε̇ ≠ 0: both films continuous. (A π-film mirrored
  // with the sign of ω̄ would jump here by 8·G·ε·ε̇/(1 − ε²)².) Flores et
  // al.'s fixed π-film with ω̄ < 0 lies on the diverging side: its rotation
  // term pulls the pin outwards, where the cavitated film pushes it back.
  const double eps = 0.8, rate = 3.0, tiny = 1e-9;
  for (FilmExtent extent : {FilmExtent::cavitated, FilmExtent::pinkus_sternlicht}) {
    const FilmForce c0 = short_bearing_force(film(extent), eps, rate, -tiny);
    const FilmForce c1 = short_bearing_force(film(extent), eps, rate, tiny);
    const double scale = std::abs(c0.radial_N);
    EXPECT_LT(std::abs(c1.radial_N - c0.radial_N), 1e-7 * scale);
    EXPECT_LT(std::abs(c1.tangential_N - c0.tangential_N), 1e-7 * scale);
  }
  EXPECT_GT(short_bearing_force(film(FilmExtent::pinkus_sternlicht), eps, 0.0, -eps * 30).radial_N, 0.0);
  EXPECT_LT(short_bearing_force(film(FilmExtent::cavitated), eps, 0.0, -eps * 30).radial_N, 0.0);
  const double scale = std::abs(short_bearing_force(film(FilmExtent::cavitated), eps, rate, 0).radial_N);
  // ... and at rest (both rates → 0) it tends to zero.
  const FilmForce r = short_bearing_force(film(FilmExtent::cavitated), eps, 1e-12, -1e-12);
  EXPECT_LT(std::hypot(r.radial_N, r.tangential_N), 1e-9 * scale);
}

TEST(FilmForce, HandoverToDryContactIsContinuousAndBounded) {
  JournalFilm f = film(FilmExtent::cavitated);
  f.break_eccentricity = 0.95;
  const double rate = 4.0, whirl = 30.0;
  auto at = [&](double eps) { return film_force(f, eps, rate, eps * whirl); };
  const FilmForce below = at(0.95 - 1e-12), above = at(0.95 + 1e-12);
  const double scale = std::hypot(below.radial_N, below.tangential_N);
  EXPECT_LT(std::abs(above.radial_N - below.radial_N), 1e-9 * scale);
  EXPECT_LT(std::abs(above.tangential_N - below.tangential_N), 1e-9 * scale);
  // Fades to nothing at the wall (where the dry contact force starts from 0),
  // monotone in weight, and never larger than the film at ε_t.
  const FilmForce wall = at(1.0 - 1e-9);
  EXPECT_LT(std::hypot(wall.radial_N, wall.tangential_N), 1e-14 * scale);
  EXPECT_EQ(at(1.0).radial_N, 0.0);
  EXPECT_EQ(at(1.2).tangential_N, 0.0);
  double last = 1.0;
  for (double eps = 0.95; eps <= 1.0; eps += 0.001) {
    const double w = film_weight(f, eps);
    EXPECT_LE(w, last);
    last = w;
    const FilmForce g = at(eps);
    EXPECT_LE(std::hypot(g.radial_N, g.tangential_N), scale * (1 + 1e-9));
  }
  // The short-bearing force itself grows without bound towards the wall.
  const FilmForce near_wall = short_bearing_force(f, 0.999, rate, 0.999 * whirl);
  EXPECT_GT(std::abs(near_wall.radial_N), 1e3 * scale);
  // A dry bearing has no film.
  f.viscosity_Pa_s = 0;
  EXPECT_EQ(film_force(f, 0.5, rate, whirl).radial_N, 0.0);
}

}  // namespace
}  // namespace fourbar
