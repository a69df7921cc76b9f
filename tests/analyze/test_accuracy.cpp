// The analyze chain against known truth without acquire: the thesis rig at
// 350 rpm (crank speed wandering ±1 %), AC-coupled accelerometers offset on
// the coupler and rocker housings, 30 dB SNR white noise and 60 Hz hum.
// Issue targets: averaged α RMS error ≤ 1 % of the α RMS, ω ≤ 0.5 %. The
// thesis method (rectangular window, plain trapezoid, constant speed, no
// gravity term, sensor taken at the joint, no AC correction) and the chain
// with one correction left out at a time are printed beside it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analyze/angle_resampler.hpp"
#include "analyze/link_analysis.hpp"
#include "synthetic_recording.hpp"

namespace fourbar {
namespace {

using testing::SyntheticRig;

struct Errors {
  double alpha = 0, omega = 0;          // RMS error of the average / RMS of the true average
  double alpha_rev = 0, omega_rev = 0;  // the same over every revolution before averaging
};

double rel_rms_error(const std::vector<double>& est, const std::vector<double>& truth) {
  double e = 0, t = 0;
  for (std::size_t k = 0; k < est.size(); ++k) {
    e += (est[k] - truth[k]) * (est[k] - truth[k]);
    t += truth[k] * truth[k];
  }
  return std::sqrt(e / t);
}

// Averaged nominal α, ω on the same grid revolutions as the analysis.
// Nominal α, ω on the same grid revolutions as the analysis, and averaged.
struct Truth {
  std::vector<double> alpha, omega;          // averaged
  std::vector<double> alpha_rev, omega_rev;  // revolutions × N
};
Truth grid_truth(const SyntheticRig& s, SensedLink link, const LinkAnalysis& a, double grid_start,
                 std::size_t guard = 0) {
  const std::size_t N = a.grid_points_per_rev, averaged = a.revolutions - 2 * guard;
  Truth t{std::vector<double>(N, 0.0), std::vector<double>(N, 0.0), {}, {}};
  for (std::size_t r = 0; r < a.revolutions; ++r)
    for (std::size_t k = 0; k < N; ++k) {
      const double angle = grid_start + units::kTwoPi * (double(a.first_revolution + long(r)) + double(k) / N);
      const testing::LinkTruth m = testing::truth_at_angle(s, link, angle);
      t.alpha_rev.push_back(m.alpha_rad_s2);
      t.omega_rev.push_back(m.omega_rad_s);
      if (r < guard || r >= a.revolutions - guard) continue;
      t.alpha[k] += m.alpha_rad_s2 / averaged;
      t.omega[k] += m.omega_rad_s / averaged;
    }
  return t;
}

// The chain on one channel, a fresh analyzer (rig or crank track may differ).
LinkAnalysis run_chain(const Rig& rig, const CrankTrack& crank, double fs, const AccelerometerMount& mount,
                       std::span<const double> reading, const ChannelOptions& o) {
  RecordAnalyzer analyzer(rig, crank, fs, AngleGridSpec{});
  return analyzer.tangential(mount, reading, o);
}

Errors errors_of(const LinkAnalysis& a, const Truth& t) {
  return {rel_rms_error(a.alpha.mean, t.alpha), rel_rms_error(a.omega.mean, t.omega),
          rel_rms_error(a.alpha_grid, t.alpha_rev), rel_rms_error(a.omega_grid, t.omega_rev)};
}

// The thesis method on the same record: eq. 7.2.1-6 / 7.2.2-1 at the
// nominal speed, ideal rectangular FFT band-pass, trapezoid in time from the
// nominal ω at the first sample; then the same resampling and averaging.
Errors thesis_method(const SyntheticRig& s, const testing::SyntheticRecording& rec, const testing::SyntheticChannel& ch,
                     const FilterSpec& band, const Truth& truth, std::size_t N) {
  const std::size_t n = ch.recorded.size();
  const double fs = s.sample_rate_hz, w0 = s.mean_speed_rad_s();
  std::vector<double> alpha(n), omega(n);
  thesis_angular_acceleration(s.rig, ch.mount.link, ch.mount.axis_sign, w0, rec.angle, ch.recorded, alpha);
  FilterSpec ideal = band;
  ideal.window = {};
  ideal.transition_hz = 0;
  FftFilter(ideal, fs, n).apply(alpha, alpha);
  const double omega0 = nominal_link_motion(s.rig, ch.mount.link, {rec.angle[0], w0, 0.0}).omega_rad_s;
  cumulative_trapezoid(alpha, 1.0 / fs, omega0, omega);
  const RevolutionResampler grid(rec.angle, N, 0.0);  // the same grid as the chain's
  const std::vector<double> alpha_grid = grid.resample(alpha), omega_grid = grid.resample(omega);
  const AngleAverage a = synchronous_average(alpha_grid, N), w = synchronous_average(omega_grid, N);
  return {rel_rms_error(a.mean, truth.alpha), rel_rms_error(w.mean, truth.omega),
          rel_rms_error(alpha_grid, truth.alpha_rev), rel_rms_error(omega_grid, truth.omega_rev)};
}

// Runs the chain on both channels; returns the errors of this chain per
// link and, when `compare`, prints the variants and the thesis method.
std::vector<Errors> run_case(SyntheticRig s, bool compare) {
  const double rev_s = units::kTwoPi / s.mean_speed_rad_s();
  s.duration_s = 51 * rev_s;

  // On the bearing housing, 20 mm inboard of the joint; the coupler sensor
  // points along −n3, the rocker one sits on the other side of its link.
  AccelerometerMount coupler = testing::housing_mounts().coupler_t;
  coupler.axis_sign = -1;
  AccelerometerMount rocker = testing::housing_mounts().rocker_t;
  rocker.offset_m = -0.010;
  const testing::SyntheticRecording rec = testing::make_recording(s, {coupler, rocker});

  const AngleGridSpec grid;
  ChannelOptions opt;
  opt.filter = testing::band_pass_with_mains_comb();

  std::printf("\n  SNR %.0f dB, hum %.0f %%: RMS error / RMS of truth, of the average over the revolutions and of\n"
              "  every revolution before averaging\n",
              s.snr_db, 100 * s.hum_rms_fraction);
  std::printf("  %-46s %10s %10s %10s %10s\n", "method", "alpha avg", "omega avg", "alpha rev", "omega rev");
  std::vector<Errors> result;
  for (std::size_t c = 0; c < 2; ++c) {
    const testing::SyntheticChannel& ch = rec.channels[c];
    const SensedLink link = ch.mount.link;
    const LinkAnalysis full = run_chain(s.rig, rec.crank(), s.sample_rate_hz, ch.mount, ch.recorded, opt);
    EXPECT_GE(full.revolutions, 49u);
    const Truth truth = grid_truth(s, link, full, grid.start_rad);
    const Errors ours = errors_of(full, truth);
    result.push_back(ours);
    auto row = [&](const std::string& name, Errors e) {
      std::printf("  %-46s %9.4f%% %9.4f%% %9.4f%% %9.4f%%\n", (std::string(to_string(link)) + ": " + name).c_str(),
                  100 * e.alpha, 100 * e.omega, 100 * e.alpha_rev, 100 * e.omega_rev);
    };
    row("this chain (" + std::to_string(full.revolutions) + " revolutions)", ours);
    if (!compare) continue;

    // One correction left out at a time (same record, same truth).
    auto variant = [&](const Rig& rig, const AccelerometerMount& mount, const CrankTrack& crank,
                       const ChannelOptions& o) {
      return errors_of(run_chain(rig, crank, s.sample_rate_hz, mount, ch.recorded, o), truth);
    };
    ChannelOptions ideal = opt;
    ideal.filter.window = {};
    ideal.filter.transition_hz = 0;
    row("  with the ideal rectangular filter", variant(s.rig, ch.mount, rec.crank(), ideal));
    ChannelOptions guarded = opt;
    guarded.guard_revolutions = 2;
    row("  with 2 guard revolutions at each end",
        errors_of(run_chain(s.rig, rec.crank(), s.sample_rate_hz, ch.mount, ch.recorded, guarded),
                  grid_truth(s, link, full, grid.start_rad, 2)));
    const std::vector<double> w0(rec.angle.size(), s.mean_speed_rad_s()), zero(rec.angle.size(), 0.0);
    row("  at constant crank speed", variant(s.rig, ch.mount, {rec.angle, w0, zero}, opt));
    Rig no_g = s.rig;
    no_g.gravity_m_s2 = 0;
    row("  without the gravity term", variant(no_g, ch.mount, rec.crank(), opt));
    AccelerometerMount dc = ch.mount;
    dc.high_pass_corner_hz = 0;
    row("  without the AC-coupling correction", variant(s.rig, dc, rec.crank(), opt));
    AccelerometerMount at_joint = ch.mount;
    at_joint.from = MeasuredFrom::first_joint;
    at_joint.distance_m = link_length_m(s.rig, link);
    at_joint.offset_m = 0;
    row("  sensor taken at the joint", variant(s.rig, at_joint, rec.crank(), opt));
    const Errors thesis = thesis_method(s, rec, ch, opt.filter, truth, grid.grid_points_per_rev);
    row("thesis method", thesis);
    EXPECT_GT(thesis.alpha, 3 * ours.alpha);
    EXPECT_GT(thesis.omega, 3 * ours.omega);
  }
  return result;
}

TEST(AnalyzeAccuracy, ThesisRigAt350RpmNoiseAndHum) {
  SyntheticRig s;
  s.seed = 2024;
  for (const Errors& e : run_case(s, true)) {
    EXPECT_LE(e.alpha, 0.01);
    EXPECT_LE(e.omega, 0.005);
  }
}

// Without noise and hum what is left is the chain's own error (conversion,
// AC restore, filter edges, resampling, the periodic integration of a
// revolution whose crank speed drifts): far below the targets.
TEST(AnalyzeAccuracy, NoiseFreeSystematicErrorIsTiny) {
  SyntheticRig s;
  s.snr_db = 300;
  s.hum_rms_fraction = 0;
  for (const Errors& e : run_case(s, false)) {
    EXPECT_LE(e.alpha, 1e-4);
    EXPECT_LE(e.omega, 1e-4);
  }
}

}  // namespace
}  // namespace fourbar

namespace fourbar {
namespace {

// The coupler's normal (centripetal) channel, DC-coupled, on the same
// housing: its ω3² agrees with the square of the integrated ω3 and with the
// truth.
TEST(AnalyzeAccuracy, NormalChannelChecksTheIntegratedOmega) {
  SyntheticRig s;
  s.seed = 77;
  s.duration_s = 51 * units::kTwoPi / s.mean_speed_rad_s();
  const AccelerometerMount tangential = testing::housing_mounts().coupler_t;
  AccelerometerMount normal = testing::housing_mounts().coupler_n;
  normal.high_pass_corner_hz = 0;
  const testing::SyntheticRecording rec = testing::make_recording(s, {tangential, normal});

  ChannelOptions opt;
  opt.filter = testing::band_pass_with_mains_comb();
  RecordAnalyzer analyzer(s.rig, rec.crank(), s.sample_rate_hz, AngleGridSpec{});
  const LinkAnalysis t = analyzer.tangential(tangential, rec.channels[0].recorded, opt);
  ChannelOptions low = opt;
  low.filter.band = BandType::lowpass;
  const NormalChannelAnalysis n = analyzer.normal(normal, rec.channels[1].recorded, t.alpha_rad_s2, low);
  ASSERT_EQ(n.revolutions, t.revolutions);
  const std::size_t N = t.grid_points_per_rev;
  std::vector<double> from_integral(N), truth(N, 0.0);
  for (std::size_t k = 0; k < N; ++k) from_integral[k] = t.omega.mean[k] * t.omega.mean[k];
  for (std::size_t r = 0; r < t.revolutions; ++r)
    for (std::size_t k = 0; k < N; ++k) {
      const double angle = units::kTwoPi * (double(t.first_revolution + long(r)) + double(k) / N);
      const double w = testing::truth_at_angle(s, SensedLink::coupler, angle).omega_rad_s;
      truth[k] += w * w / t.revolutions;
    }
  const double vs_truth = rel_rms_error(n.omega_sq.mean, truth);
  const double vs_integral = rel_rms_error(n.omega_sq.mean, from_integral);
  std::printf("  coupler normal channel: averaged omega3^2 vs truth %.4f %%, vs integrated omega3 squared %.4f %%\n",
              100 * vs_truth, 100 * vs_integral);
  EXPECT_LT(vs_truth, 0.02);
  EXPECT_LT(vs_integral, 0.02);
}

}  // namespace
}  // namespace fourbar
