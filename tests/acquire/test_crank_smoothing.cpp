// Smoothing across turns (crank_smoothing = "spline"): the jitter estimate,
// what period the spline keeps, the guard against runs that are not steady
// (analytic pulse times, tacho_signal.hpp's speed laws), and virtual rig →
// acquire against the rig's own CrankDrive: a steady run with pulse jitter
// is closer to the truth smoothed than through every pulse; a run that is
// not steady is refused naming the key.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include "acquire/acquisition.hpp"
#include "acquire/crank_smoothing.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/statistics.hpp"
#include "tacho_signal.hpp"
#include "virtual_recording.hpp"
#include "wheel_setup.hpp"

namespace fourbar {
namespace {

using testing::SpeedLaw;
using testing::Crank;
using testing::VirtualSetup;

std::vector<double> turn_phases(std::size_t n) {
  std::vector<double> p(n);
  for (std::size_t k = 0; k < n; ++k) p[k] = units::kTwoPi * static_cast<double>(k);
  return p;
}

std::vector<double> with_jitter(std::vector<double> t, double sigma_s, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0, sigma_s);
  for (double& x : t) x += n(rng);
  return t;
}

/// Once-per-turn pulse times of a speed law (all passes of whole turns).
std::vector<double> pulses_of(const SpeedLaw& law) { return testing::pass_times(law, 0.0, 0.0, law.end_s()); }

TEST(CrankSmoothing, JitterEstimateIsTheDrawnJitterAndZeroForACubic) {
  // t(x) a cubic in the turn number: no jitter at all.
  std::vector<double> cubic;
  for (int k = 0; k < 400; ++k) cubic.push_back(0.1 * k + 2e-5 * k * k - 3e-8 * k * k * k);
  EXPECT_LT(edge_timing_jitter(cubic, turn_phases(cubic.size())), 1e-12);
  // Unequal angles (a wheel with a gap): still exact for a cubic.
  std::vector<double> phase, t;
  for (int k = 0; k < 400; ++k)
    if (k % 60 < 58) phase.push_back(0.1 * k), t.push_back(0.01 * k + 1e-6 * k * k + 1e-9 * k * k * k);
  EXPECT_LT(edge_timing_jitter(t, phase), 1e-12);
  // 20 µs Gaussian jitter on a run-up: 20 µs within the estimate's spread.
  const SpeedLaw runup{{0, 60}, {5, 20}};
  const std::vector<double> clean = pulses_of(runup);
  const double sigma = edge_timing_jitter(with_jitter(clean, 20e-6, 7), turn_phases(clean.size()));
  std::printf("  jitter drawn 20 us, estimated %.2f us from %zu pulses\n", sigma * 1e6, clean.size());
  EXPECT_NEAR(sigma, 20e-6, 2e-6);
}

/// Amplitude of the fitted relative speed change at period `period_turns`
/// (interior turns only), for a drawn change of amplitude `eps`.
double kept_fraction(double period_turns, double smoothing_turns) {
  const double eps = 0.01, T0 = 0.1;
  const std::size_t n = 400;
  std::vector<double> t(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double x = static_cast<double>(k);  // t′(x) = T0·(1 + ε sin 2πx/P)
    t[k] = T0 * (x - eps * period_turns / units::kTwoPi * (std::cos(units::kTwoPi * x / period_turns) - 1));
  }
  const SmoothedSegment s = smooth_segment(t, turn_phases(n), smoothing_knot_spacing(smoothing_turns, 1), 0);
  // ω/ω0 − 1 ≈ −ε sin 2πx/P: project on sin and cos away from the ends.
  double ss = 0, sc = 0, cc = 0, ys = 0, yc = 0;
  for (std::size_t k = 50; k + 50 < n; ++k) {
    const double x = units::kTwoPi * static_cast<double>(k) / period_turns;
    const double y = s.track->knot(k).speed_rad_s * T0 / units::kTwoPi - 1;
    ss += std::sin(x) * std::sin(x), sc += std::sin(x) * std::cos(x), cc += std::cos(x) * std::cos(x);
    ys += y * std::sin(x), yc += y * std::cos(x);
  }
  const double det = ss * cc - sc * sc;
  const double a = (ys * cc - yc * sc) / det, b = (yc * ss - ys * sc) / det;
  return std::hypot(a, b) / eps;
}

// The key's meaning: a speed change with a period of smoothing_period_turns
// is kept, a third of it is not.
TEST(CrankSmoothing, KeepsTheShortestPeriodAskedAndRemovesFasterChanges) {
  for (double K : {6.0, 10.0, 30.0}) {
    const double at_k = kept_fraction(K, K), at_2k = kept_fraction(2 * K, K), at_third = kept_fraction(K / 3, K);
    std::printf("  smoothing %4.0f turns: speed change kept %.4f at %g turns, %.4f at %g", K, at_2k, 2 * K, at_k, K);
    if (K / 3 > 2) std::printf(", %.4f at %.3g", at_third, K / 3);
    std::printf("\n");
    EXPECT_GT(at_k, 0.95) << K;
    EXPECT_GT(at_2k, 0.99) << K;
    if (K / 3 > 2) EXPECT_LT(at_third, 0.5) << K;  // one pulse per turn shows periods above 2 turns only
  }
}

// The guard: a speed step leaves edges far from the spline and is found
// where it is; the same run without the step, and a smooth run-up, pass.
TEST(CrankSmoothing, GuardFindsASpeedStepButNotASteadyRunOrASmoothRunUp) {
  const double jitter = 20e-6;
  const SpeedLaw steady{{0, 30}, {10, 10.1}};
  const SpeedLaw runup{{0, 30}, {5, 20}};
  const SpeedLaw step{{0, 15, 15.02, 30}, {10, 10, 11, 11}};  // 600 → 660 rpm in 20 ms at 15 s
  auto fit = [&](const SpeedLaw& law) {
    const std::vector<double> t = with_jitter(pulses_of(law), jitter, 3);
    return smooth_segment(t, turn_phases(t.size()), smoothing_knot_spacing(10, 1), 0).fit;
  };
  const SmoothingFit a = fit(steady), b = fit(runup), c = fit(step);
  for (const auto* f : {&a, &b, &c})
    std::printf("  jitter %.2f us, residual %.2f us RMS, worst block %.2f us (%.4f deg, %.2fx) at %.2f-%.2f s\n",
                f->jitter_s * 1e6, f->residual_rms_s * 1e6, f->worst_rms_s * 1e6, f->worst_rms_deg, f->worst_ratio,
                f->worst_from_s, f->worst_to_s);
  EXPECT_FALSE(a.misfit());
  EXPECT_FALSE(b.misfit());
  EXPECT_LT(a.worst_ratio, 1.5);
  EXPECT_LT(b.worst_ratio, 1.5);
  ASSERT_TRUE(c.misfit());
  EXPECT_LE(c.worst_from_s, 15.02);
  EXPECT_GE(c.worst_to_s, 15.0);
  EXPECT_NEAR(c.jitter_s, jitter, 0.2 * jitter);  // the step does not fool the jitter estimate
}

// A piece of pulse train between gaps too short to show its jitter (here 6
// pulses of a run-up) is left unsmoothed rather than refused or forced
// straight; the long piece is smoothed.
TEST(CrankSmoothing, ShortPieceBetweenGapsGoesThroughEveryPulse) {
  PulseTrain train;
  const std::vector<double> steady = with_jitter(pulses_of(SpeedLaw{{0, 8}, {10, 10}}), 20e-6, 5);
  const std::vector<double> runup = pulses_of(SpeedLaw{{0, 0.6}, {5, 15}});
  train.segments.emplace_back();
  for (double t : steady) train.segments.back().push_back({t, false});
  train.segments.emplace_back();
  for (double t : runup) train.segments.back().push_back({t + 10, false});
  train.typical_period_s = 0.1;
  ASSERT_LT(train.segments[1].size(), kSmoothingMinBlockEdges);
  const RevolutionSchedule s = plan_revolutions(train, 1000, 0, 10);
  EXPECT_FALSE(s.smoothing.fit.misfit());
  ASSERT_EQ(s.plan.size(), steady.size() - 1 + runup.size() - 1);
  std::size_t k = 0;
  for (const RevolutionPlan& r : s.plan) {
    EXPECT_EQ(r.track != nullptr, r.segment == 0);
    if (r.segment == 1) EXPECT_EQ(r.t_start, runup[k++] + 10);  // through the pulse itself
  }
}

struct CrankErrors {
  AcquisitionReport report;
  double angle_deg = 0, speed_rel = 0, accel_rad_s2 = 0;
};

CrankErrors crank_errors(const VirtualSetup& v, const VirtualRigResult& vr) {
  AcquireOptions o;
  o.progress = false;
  OpenedRecording rec = open_with_manifest(vr.recording, {});
  CrankErrors e;
  Crank out;
  e.report = acquire(*rec.reader, rec.manifest, o, out);
  const CrankDrive drive = v.drive();
  std::vector<double> angle, speed, accel;
  for (std::size_t i = 0; i < out.time.size(); i += 11) {
    const CrankState t = drive.at(out.time[i]);
    angle.push_back(std::remainder(out.crank[i] - t.angle_rad, units::kTwoPi));
    speed.push_back((out.omega[i] - t.speed_rad_s) / drive.mean_speed_rad_s);
    accel.push_back(out.alpha[i] - t.accel_rad_s2);
  }
  e.angle_deg = units::rad_to_deg(rms(angle)), e.speed_rel = rms(speed), e.accel_rad_s2 = rms(accel);
  return e;
}

/// Puts `lines` in place of any smoothing keys after the crank pulse channel's role.
void smooth_in_manifest(const VirtualRigResult& vr, const std::string& lines) {
  std::ifstream in(vr.manifest);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const std::string role = "role = \"crank_pulse\"\n";
  auto at = text.find(role);
  ASSERT_NE(at, std::string::npos);
  at += role.size();
  while (text.compare(at, 15, "crank_smoothing") == 0 || text.compare(at, 15, "smoothing_perio") == 0)
    text.erase(at, text.find('\n', at) + 1 - at);  // a setting of an earlier call
  text.insert(at, lines);
  std::ofstream(vr.manifest) << text;
}

/// One pulse per turn at 350 rpm, 25.6 kHz, 20 µs pulse jitter.
VirtualSetup jittery_pulse(double revolutions, double fluctuation, double period_turns) {
  VirtualSetup v;
  v.spec.revolutions = revolutions;
  v.spec.sample_format = "float";
  v.spec.pulse.jitter_s = 20e-6;
  v.spec.speed_fluctuation = fluctuation;
  v.spec.speed_fluctuation_period_s = period_turns * 60.0 / 350.0;
  v.spec.sensors.resize(1);
  return v;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

// A steady run (1 % slow speed change over 40 turns) with 20 µs pulse
// jitter. Smoothed over 10 turns the crank angle, speed and acceleration are
// closer to the truth than through every pulse. Over 20 turns the spline
// starts to cut into the 40-turn change: the angle is no better any more and
// acquire says so (a warning naming the key). Over 30 turns it misses the
// change by ten times the jitter: refused.
TEST(CrankSmoothing, SteadyRunWithJitterIsCloserToTheTruth) {
  const VirtualSetup v = jittery_pulse(80, 0.01, 40);
  const VirtualRigResult vr = v.write("steady.wav", false);
  const CrankErrors plain = crank_errors(v, vr);
  std::printf("  through every pulse: angle %.4f deg, speed %.4f %%, accel %.4f rad/s^2 RMS\n", plain.angle_deg,
              100 * plain.speed_rel, plain.accel_rad_s2);
  EXPECT_EQ(plain.report.smoothing.period_turns, 0.0);
  for (double K : {10.0, 20.0}) {
    smooth_in_manifest(vr, "crank_smoothing = \"spline\"\nsmoothing_period_turns = " + format_number(K) + "\n");
    const CrankErrors smooth = crank_errors(v, vr);
    const CrankSmoothingReport& sm = smooth.report.smoothing;
    std::printf("  smoothed, %2.0f turns: angle %.4f deg, speed %.4f %%, accel %.4f rad/s^2 RMS (edge jitter %.2f us, "
                "residual %.2f us RMS, shift %.2fx what the jitter explains, worst block %.2fx)\n",
                K, smooth.angle_deg, 100 * smooth.speed_rel, smooth.accel_rad_s2, sm.fit.jitter_s * 1e6,
                sm.residual_rms_s * 1e6, sm.shift_ratio, sm.fit.worst_ratio);
    EXPECT_EQ(sm.period_turns, K);
    EXPECT_NEAR(sm.fit.jitter_s, 20e-6, 4e-6);
    EXPECT_FALSE(sm.fit.misfit());
    EXPECT_EQ(smooth.report.revolutions, plain.report.revolutions);
    const bool warned = joined(smooth.report.warnings).find("smoothing_period_turns = " + format_number(K)) != std::string::npos;
    if (K == 10) {
      EXPECT_LT(smooth.angle_deg, 0.75 * plain.angle_deg);
      EXPECT_LT(smooth.speed_rel, 0.3 * plain.speed_rel);
      EXPECT_LT(smooth.accel_rad_s2, 0.15 * plain.accel_rad_s2);
      EXPECT_FALSE(warned) << joined(smooth.report.warnings);
    } else {
      EXPECT_GT(smooth.angle_deg, 0.95 * plain.angle_deg);  // what the warning says
      EXPECT_TRUE(warned) << joined(smooth.report.warnings);
    }
  }
  smooth_in_manifest(vr, "crank_smoothing = \"spline\"\nsmoothing_period_turns = 30\n");
  try {
    crank_errors(v, vr);
    ADD_FAILURE() << "a 30-turn smoothing of a 40-turn speed change was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("smoothing_period_turns = 30"), std::string::npos) << e.what();
  }
}

// Not steady on the scale asked: a 2 % speed change every 12 turns under a
// 30-turn smoothing. Refused, naming the key and the fix; a period that
// keeps the change (6 turns) accepts the same recording.
TEST(CrankSmoothing, RunThatIsNotSteadyIsRefusedNamingTheKey) {
  const VirtualSetup v = jittery_pulse(60, 0.02, 12);
  const VirtualRigResult vr = v.write("unsteady.wav", false);
  smooth_in_manifest(vr, "crank_smoothing = \"spline\"\nsmoothing_period_turns = 30\n");
  std::string message;
  try {
    crank_errors(v, vr);
  } catch (const InputError& e) {
    message = e.what();
  }
  std::printf("  %s\n", message.c_str());
  EXPECT_NE(message.find("smoothing_period_turns = 30"), std::string::npos) << message;
  EXPECT_NE(message.find("channel 'crank_pulse'"), std::string::npos) << message;
  EXPECT_NE(message.find("Lower smoothing_period_turns"), std::string::npos) << message;
  EXPECT_NE(message.find("crank_smoothing = \"none\""), std::string::npos) << message;
  const VirtualRigResult again = v.write("kept.wav", false);
  smooth_in_manifest(again, "crank_smoothing = \"spline\"\nsmoothing_period_turns = 6\n");
  EXPECT_NO_THROW(crank_errors(v, again));
}

// A 60-2 wheel (30 dB SNR on the wheel channel, 1 % speed change over 40
// turns). On a steady crank a 6-turn smoothing beats the 30° knots of the
// unsmoothed track in angle, speed and acceleration. A 10-turn one still
// gives better speed and acceleration, but its bias on the 40-turn change
// exceeds the wheel's small jitter, so the angle is no better: a warning
// says so. With the loaded crank's once- and twice-per-turn speed change
// (the lab case) a smoothing across turns would erase what the wheel is
// there to see: refused.
TEST(CrankSmoothing, ToothWheelSteadyRunAndInTurnSpeedChange) {
  auto wheel = [](bool in_turn) {
    VirtualSetup v;
    v.spec.revolutions = 30;
    v.spec.sensors.resize(1);
    testing::in_turn_speed_change(v);
    v.spec.speed_fluctuation_period_s = 40 * 60.0 / 350.0;
    if (!in_turn) v.spec.speed_harmonics.clear();
    testing::fit_wheel(v, testing::WheelKind::missing_teeth);
    return v;
  };
  const VirtualSetup steady = wheel(false);
  const VirtualRigResult vr = steady.write("steady_wheel.wav", false);
  const CrankErrors plain = crank_errors(steady, vr);
  for (double K : {6.0, 10.0}) {
    smooth_in_manifest(vr, "crank_smoothing = \"spline\"\nsmoothing_period_turns = " + format_number(K) + "\n");
    const CrankErrors smooth = crank_errors(steady, vr);
    std::printf("  60-2 wheel, steady, %2.0f turns: angle %.5f -> %.5f deg, speed %.5f -> %.5f %%, accel %.4f -> %.4f "
                "rad/s^2 RMS (jitter %.3f us, shift %.3fx)\n",
                K, plain.angle_deg, smooth.angle_deg, 100 * plain.speed_rel, 100 * smooth.speed_rel, plain.accel_rad_s2,
                smooth.accel_rad_s2, smooth.report.smoothing.fit.jitter_s * 1e6, smooth.report.smoothing.shift_ratio);
    EXPECT_LT(smooth.speed_rel, 0.2 * plain.speed_rel);
    EXPECT_LT(smooth.accel_rad_s2, 0.02 * plain.accel_rad_s2);
    const bool warned = joined(smooth.report.warnings).find("smoothing_period_turns = " + format_number(K)) != std::string::npos;
    if (K == 6) {
      EXPECT_LT(smooth.angle_deg, 0.5 * plain.angle_deg);
      EXPECT_FALSE(warned) << joined(smooth.report.warnings);
    } else {  // the spline cuts into the 40-turn change by more than the wheel's jitter
      EXPECT_GT(smooth.angle_deg, 0.95 * plain.angle_deg);
      EXPECT_TRUE(warned) << joined(smooth.report.warnings);
    }
  }

  const VirtualSetup loaded = wheel(true);
  const VirtualRigResult lr = loaded.write("loaded_wheel.wav", false);
  smooth_in_manifest(lr, "crank_smoothing = \"spline\"\nsmoothing_period_turns = 10\n");
  std::string message;
  try {
    crank_errors(loaded, lr);
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("smoothing_period_turns = 10"), std::string::npos) << message;
}

}  // namespace
}  // namespace fourbar
