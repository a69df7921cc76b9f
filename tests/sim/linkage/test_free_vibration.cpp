// Free vibration of an elastic link in the linkage model: the crank held,
// every pin ideal (θ3, θ4 then stay at the nominal pose), no gravity, one mode
// of the coupler or rocker started displaced. The frame does not move, so the
// mode is a damped oscillator: η(t) = η0·e^(−ζωt)·(cos ω_d t + ζ/√(1−ζ²)·sin ω_d t),
// ω_d = ω√(1−ζ²), with ω the Euler–Bernoulli pinned–pinned frequency
// (kπ/L)²·√(EI/μ) of the rig's section (the links given the uniform bar's
// mass, centre and inertia) and ζ the rig's damping ratio; the
// other modes stay at rest (the sines are orthogonal in mass and stiffness).

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "common/error.hpp"
#include "sim/drive/crank_motion.hpp"
#include "sim/linkage/linkage_simulator.hpp"

namespace fourbar {
namespace {

struct VibrationCase {
  int body = 1;  ///< coupler 1, rocker 2
  int mode = 0;  ///< 0-based
  int modes = 1;
};

void check_free_vibration(const VibrationCase& k) {
  Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  rig.gravity_m_s2 = 0;
  // The closed form is the uniform bar's: give the link the bar's own mass,
  // centre and inertia (a measured rigid inertia makes μ linear, sim/flex).
  for (auto [link, el] : {std::pair{&rig.coupler, &rig.coupler_elastic}, std::pair{&rig.rocker, &rig.rocker_elastic}}) {
    link->mass_kg = *(*el)->density_kg_m3 * *(*el)->area_m2 * link->length_m;
    link->mass_centre_m = link->length_m / 2;
    link->inertia_cg_kg_m2 = link->mass_kg * link->length_m * link->length_m / 12;
  }
  LinkageSpec s;
  s.law = {1e10, 1.5, DampingLaw::calibrated, 0.5};
  s.tolerance = 1e-11;
  s.elastic = {false, k.body == 1, k.body == 2};
  s.elastic_modes = k.modes;
  const LinkageModel model = build_linkage(rig, s);
  ASSERT_TRUE(model.all_ideal());
  // Euler–Bernoulli from the rig's section (25 × 4 mm steel bar).
  const LinkElasticity& e = *(k.body == 1 ? rig.coupler_elastic : rig.rocker_elastic);
  const double L = (k.body == 1 ? rig.coupler : rig.rocker).length_m;
  const double mu = *e.density_kg_m3 * *e.area_m2, EI = *e.youngs_modulus_Pa * *e.second_moment_m4;
  const double kpi = (k.mode + 1) * M_PI / L;
  const double omega = kpi * kpi * std::sqrt(EI / mu);
  const double zeta = e.damping_ratios[static_cast<std::size_t>(std::min<int>(k.mode, static_cast<int>(e.damping_ratios.size()) - 1))];
  const double wd = omega * std::sqrt(1 - zeta * zeta);

  const ConstantSpeedCrank held(1.0, 0.0);
  LinkageSimulator sim(model, held);
  const double period = 2 * M_PI / wd, t_end = 6 * period;
  std::vector<double> times;
  for (int i = 0; i <= 600; ++i) times.push_back(t_end * i / 600.0);
  sim.set_sample_times(times);
  LinkageStart start;  // angles and rates: the nominal pose at rest
  const double eta0 = 1e-5;
  start.modal_m[static_cast<std::size_t>(k.body - 1)][static_cast<std::size_t>(k.mode)] = eta0;
  sim.start(0.0, start);
  sim.advance_to(t_end);
  double worst = 0, others = 0;
  for (const LinkageSample& x : sim.samples()) {
    const double t = x.time_s;
    const double expected =
        eta0 * std::exp(-zeta * omega * t) * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
    const auto& eta = x.modal_m[static_cast<std::size_t>(k.body - 1)];
    worst = std::max(worst, std::abs(eta[static_cast<std::size_t>(k.mode)] - expected));
    for (int j = 0; j < k.modes; ++j)
      if (j != k.mode) others = std::max(others, std::abs(eta[static_cast<std::size_t>(j)]));
    EXPECT_EQ(x.crank_torque_Nm, x.crank_torque_Nm);  // not NaN
  }
  EXPECT_LT(worst / eta0, 1e-6) << "body " << k.body << " mode " << k.mode + 1 << " of " << k.modes;
  EXPECT_LT(others / eta0, 1e-6);
  // Books: the crank does no work; the modal damping takes what the mode lost.
  const LinkageDiagnostics d = sim.diagnostics();
  EXPECT_EQ(d.crank_work_J, 0.0);
  EXPECT_GT(d.modal_damping_loss_J, 0.5 * d.energy_start_J);
  // Against the run's energy scale (the stress grid's bound); a held crank on
  // a flat rig has none, and the scale is then 1 J, the loss quadrature's unit.
  EXPECT_LT(std::abs(d.energy_residual_J), 1e-8 * d.energy_scale_J);
}

TEST(LinkageFreeVibration, CouplerFirstModeRingsAtEulerBernoulliAndDecaysAtItsDampingRatio) {
  check_free_vibration({1, 0, 1});
}

TEST(LinkageFreeVibration, EachModeOfAFourModeCouplerRingsAlone) {
  for (int mode = 0; mode < 4; ++mode) check_free_vibration({1, mode, 4});
}

TEST(LinkageFreeVibration, RockerSecondModeRingsAtEulerBernoulli) { check_free_vibration({2, 1, 2}); }

TEST(LinkageFreeVibration, StartRefusesModesOnARigidLinkOrPastTheModes) {
  const Rig rig = load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml");
  LinkageSpec s;
  s.clearance_m = {0, 0.254e-3, 0};
  s.law = {1e10, 1.5, DampingLaw::calibrated, 0.5};
  s.elastic = {false, true, false};
  s.elastic_modes = 2;
  const LinkageModel model = build_linkage(rig, s);
  const ConstantSpeedCrank held(1.0, 0.0);
  LinkageSimulator sim(model, held);
  LinkageStart start;
  start.modal_m[1][0] = 1e-6;  // the rocker is rigid
  EXPECT_THROW(sim.start(0.0, start), InputError);
  start = {};
  start.modal_m[0][2] = 1e-6;  // the coupler has 2 modes
  EXPECT_THROW(sim.start(0.0, start), InputError);
  start = {};
  start.modal_rate_m_s[0][0] = std::nan("");
  EXPECT_THROW(sim.start(0.0, start), InputError);
}

TEST(LinkageFreeVibration, ARigidAllIdealLinkageIsStillRefused) {
  LinkageSpec s;
  s.law = {1e10, 1.5, DampingLaw::calibrated, 0.5};
  EXPECT_THROW(build_linkage(load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis_elastic.toml"), s), InputError);
}

}  // namespace
}  // namespace fourbar
