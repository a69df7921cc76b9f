// The compliant model with a lubricated bearing (film_force.hpp) on the
// thesis rig: energy balance with the film's work, finite and bounded
// motion through the singular film near the wall, the film keeping the pin
// off the wall, and the lubricant keys (rig and scene) with their bad input.

#include <gtest/gtest.h>

#include <cmath>

#include "common/error.hpp"
#include "common/units.hpp"
#include "sim/compliant/compliant_simulator.hpp"
#include "sim/scene.hpp"
#include "support/temp_dir.hpp"
#include "scene_error.hpp"

namespace fourbar {
namespace {

ClearanceSettings lubricated(double viscosity_Pa_s, FilmExtent extent) {
  ClearanceSettings s;
  s.model = ClearanceKind::compliant;
  s.restitution = 0.5;
  s.tolerance = 1e-10;
  s.compliant.stiffness_N_per_m_n = 1e10;
  s.compliant.film = {viscosity_Pa_s, 10e-3, 10e-3, 0.254e-3, extent, 0.95};
  return s;
}

struct LubRun {
  ClearanceDiagnostics d;
  double min_gap_m = 1, max_force_N = 0;
  bool finite = true;
};

LubRun simulate(const ClearanceSettings& s, int turns) {
  const ClearanceModel model(thesis_rig(), 0.254e-3);
  const double w = units::rpm_to_rad_s(350), T = units::kTwoPi / w;
  const ConstantSpeedCrank crank(0.0, w);
  CompliantSimulator sim(model, crank, s);
  std::vector<double> times;
  for (int i = 0; i <= 360 * turns; ++i) times.push_back(T * i / 360.0);
  sim.set_sample_times(times);
  sim.start_nominal(0.0);
  sim.advance_to(turns * T);
  LubRun r;
  r.d = sim.diagnostics();
  for (const ClearanceSample& x : sim.samples()) {
    for (double v : {x.alpha3_rad_s2, x.alpha4_rad_s2, x.bearing_force_N.x, x.bearing_force_N.y, x.gap_m,
                     x.crank_torque_Nm})
      r.finite = r.finite && std::isfinite(v);
    r.min_gap_m = std::min(r.min_gap_m, x.gap_m);
    r.max_force_N = std::max(r.max_force_N, std::hypot(x.bearing_force_N.x, x.bearing_force_N.y));
  }
  return r;
}

TEST(Lubricated, EnergyBalanceWithTheFilmAndBoundedMotionAt350Rpm) {
  // ΔE = crank work − contact damping − friction − the film's work on the
  // relative motion; three turns, each film extent, two viscosities.
  const LubRun dry = simulate(lubricated(0.0, FilmExtent::cavitated), 3);
  EXPECT_EQ(dry.d.film_loss_J, 0.0);
  for (FilmExtent extent : {FilmExtent::cavitated, FilmExtent::pinkus_sternlicht, FilmExtent::full})
    for (double mu : {0.01, 0.2}) {
      SCOPED_TRACE(std::string(to_string(extent)) + " mu " + std::to_string(mu));
      const LubRun r = simulate(lubricated(mu, extent), 3);
      EXPECT_TRUE(r.finite);
      EXPECT_LT(std::abs(r.d.energy_residual_J) / r.d.energy_scale_J, 1e-8);
      EXPECT_LT(r.d.max_energy_residual_J / r.d.energy_scale_J, 1e-8);
      EXPECT_GT(r.d.film_loss_J, 0.0);  // the film dissipates on balance
      EXPECT_LT(r.d.max_penetration, 0.1);
      // The bearing force stays of the order of the dry run's (no singular blow-up).
      EXPECT_LT(r.max_force_N, 3 * dry.max_force_N);
    }
  // A thick film keeps the pin off the wall more than a thin one.
  const LubRun thin = simulate(lubricated(0.01, FilmExtent::cavitated), 3);
  const LubRun thick = simulate(lubricated(0.2, FilmExtent::cavitated), 3);
  EXPECT_LT(thick.d.impacts + thick.d.touches, dry.d.impacts + dry.d.touches);
  EXPECT_LT(thick.d.time_following_s, thin.d.time_following_s);
}

TEST(Lubricated, ViscosityKeysAndBadInput) {
  testing::TempDir dir;
  const std::string rig = testing::thesis_rig_toml();
  auto with = [&](const std::string& extra) {
    std::string r = rig;
    const auto i = r.find("radial_mm");
    EXPECT_NE(i, std::string::npos);
    return r.insert(r.find('\n', i) + 1, extra);
  };
  const std::string bearing = "pin_radius_mm = 10\nbearing_length_mm = 12\n";
  const std::string scene = "rig = \"r.toml\"\nmodel = \"clearance\"\ncrank_speed_rpm = 350\noutputs = [\"time_s\"]\n[clearance]\n"
                            "model = \"compliant\"\nrestitution = 0.5\ncontact_stiffness_N_per_m_n = 1e10\n";
  dir.write("r.toml", with(bearing + "lubricant_viscosity_Pa_s = 0.04\n"));
  Scene s = load_scene(dir.write("s.toml", scene));
  const JournalFilm& f = s.clearance.compliant.film;
  EXPECT_EQ(f.viscosity_Pa_s, 0.04);
  EXPECT_DOUBLE_EQ(f.radius_m, 0.010);
  EXPECT_DOUBLE_EQ(f.length_m, 0.012);
  EXPECT_DOUBLE_EQ(f.clearance_m, 0.254e-3);
  EXPECT_EQ(f.extent, FilmExtent::cavitated);
  EXPECT_EQ(f.break_eccentricity, 0.95);
  // The scene's viscosity and film keys override the rig's.
  s = load_scene(dir.write("s.toml", scene + "lubricant_viscosity_Pa_s = 0.1\nfilm = \"full\"\n"
                                             "film_break_eccentricity = 0.9\n"));
  EXPECT_EQ(s.clearance.compliant.film.viscosity_Pa_s, 0.1);
  EXPECT_EQ(s.clearance.compliant.film.extent, FilmExtent::full);
  EXPECT_EQ(s.clearance.compliant.film.break_eccentricity, 0.9);
  // A dry rig stays dry.
  dir.write("r.toml", with(bearing));
  EXPECT_EQ(load_scene(dir.write("s.toml", scene)).clearance.compliant.film.viscosity_Pa_s, 0.0);

  auto error_of = [&](const std::string& rig_text, const std::string& scene_text) {
    return testing::scene_error(dir, rig_text, scene_text);
  };
  const auto has = testing::expect_names;
  // Rig file.
  const std::string no_length = error_of(with("pin_radius_mm = 10\nlubricant_viscosity_Pa_s = 0.05\n"), scene);
  has(no_length, "lubricant_viscosity_Pa_s");
  has(no_length, "add bearing_length_mm");
  has(error_of(with("bearing_length_mm = 10\nlubricant_viscosity_Pa_s = 0.05\n"), scene), "add pin_radius_mm");
  has(error_of(with(bearing + "lubricant_viscosity_Pa_s = 0\n"), scene), "lubricant_viscosity_Pa_s");
  has(error_of(with(bearing + "lubricant_viscosity_Pa_s = -0.05\n"), scene), "must be a positive dynamic viscosity");
  // Scene file.
  const std::string scene_no_length = error_of(rig, scene + "lubricant_viscosity_Pa_s = 0.05\n");
  has(scene_no_length, "lubricant_viscosity_Pa_s");
  has(scene_no_length, "bearing_length_mm");
  has(error_of(with(bearing), scene + "lubricant_viscosity_Pa_s = 0\n"), "must be a positive dynamic viscosity");
  has(error_of(with(bearing), scene + "film = \"full\"\n"), "the bearing is dry");
  has(error_of(with(bearing), scene + "film_break_eccentricity = 1.0\n"), "film_break_eccentricity");
  has(error_of(with(bearing), scene + "film = \"long\"\n"), "film");
  // The three-mode model has no film.
  std::string three = scene;
  three.replace(three.find("model = \"compliant\"\n"), 20, "");
  three.replace(three.find("contact_stiffness_N_per_m_n = 1e10\n"), 35, "");
  has(error_of(with(bearing + "lubricant_viscosity_Pa_s = 0.05\n"), three), "no lubricant film");
  has(error_of(with(bearing), three + "lubricant_viscosity_Pa_s = 0.05\n"), "lubricant_viscosity_Pa_s");
}

}  // namespace
}  // namespace fourbar
