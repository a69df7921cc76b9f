// Round trips virtual rig → acquire against the virtual rig's truth: pulse
// times, crank angle per sample, calibrated accelerations, revolutions on the
// crank-angle grid; every format; repaired pulse trains; bad recordings.

#include <gtest/gtest.h>

#include <cmath>

#include "acquire/acquisition.hpp"
#include "common/csv_writer.hpp"
#include "common/error.hpp"
#include "common/statistics.hpp"
#include "virtual_rig/recording_writer.hpp"
#include "virtual_rig/sensor_signal.hpp"
#include "virtual_recording.hpp"

namespace fourbar {
namespace {

using testing::CsvTable;
using testing::read_csv_table;
using testing::VirtualSetup;

/// Keeps everything acquire produces.
struct Collect : AcquisitionSink {
  std::vector<double> time, crank, omega, alpha;
  std::vector<std::int64_t> revolution;
  std::vector<std::vector<double>> channels;
  std::vector<Revolution> revolutions;
  void on_samples(const SampleBlock& b) override {
    channels.resize(b.channels_m_s2.size());
    time.insert(time.end(), b.time_s.begin(), b.time_s.end());
    crank.insert(crank.end(), b.crank_rad.begin(), b.crank_rad.end());
    omega.insert(omega.end(), b.omega2_rad_s.begin(), b.omega2_rad_s.end());
    alpha.insert(alpha.end(), b.alpha2_rad_s2.begin(), b.alpha2_rad_s2.end());
    revolution.insert(revolution.end(), b.revolution.begin(), b.revolution.end());
    for (std::size_t c = 0; c < channels.size(); ++c)
      channels[c].insert(channels[c].end(), b.channels_m_s2[c].begin(), b.channels_m_s2[c].end());
  }
  void on_revolution(const Revolution& r) override { revolutions.push_back(r); }
};

struct Acquired {
  AcquisitionReport report;
  Collect out;
};

Acquired run_acquire(const std::filesystem::path& recording, AcquireOptions options = {}) {
  options.progress = false;
  OpenedRecording o = open_with_manifest(recording, {});
  Acquired r;
  r.report = acquire(*o.reader, o.manifest, options, r.out);
  return r;
}

/// Angle difference brought into (−π, π].
double wrap(double a) { return std::remainder(a, units::kTwoPi); }

/// The accepted pulse times of all segments.
std::vector<double> pulse_times(const AcquisitionReport& r) {
  std::vector<double> t;
  for (const auto& s : r.pulses.segments)
    for (const auto& p : s) t.push_back(p.time_s);
  return t;
}

/// Pulse-time errors against the truth, matched to the nearest true pulse.
std::vector<double> pulse_errors(const std::vector<double>& got, const std::vector<double>& truth) {
  std::vector<double> e;
  for (double t : got) {
    auto it = std::lower_bound(truth.begin(), truth.end(), t);
    double best = INFINITY;
    if (it != truth.end()) best = *it - t;
    if (it != truth.begin() && std::abs(*(it - 1) - t) < std::abs(best)) best = *(it - 1) - t;
    e.push_back(best);
  }
  return e;
}

// Clean 24-bit data: pulse times to < 1e-3 of a sample period RMS, the crank
// angle of every sample, and calibrated accelerations equal to the truth
// within half a quantisation step.
TEST(AcquireRoundTrip, CleanRecordingRecoversTheTruth) {
  VirtualSetup v;
  const VirtualRigResult vr = v.write("clean.wav");
  const Acquired run = run_acquire(vr.recording);
  const AcquisitionReport& rep = run.report;
  const double fs = v.spec.sample_rate_hz;

  ASSERT_EQ(rep.pulses.segments.size(), 1u);
  EXPECT_EQ(pulse_times(rep).size(), vr.pulse_times_s.size());
  const double pulse_rms_samples = rms(pulse_errors(pulse_times(rep), vr.pulse_times_s)) * fs;
  EXPECT_LT(pulse_rms_samples, 1e-3);
  RecordProperty("pulse_rms_samples", format_double(pulse_rms_samples));
  EXPECT_TRUE(rep.pulses.removed_s.empty());
  EXPECT_TRUE(rep.pulses.inserted_s.empty());
  EXPECT_EQ(rep.revolutions, vr.pulse_times_s.size() - 1);
  EXPECT_NEAR(rep.speed.mean_rpm, 350, 1e-3);
  EXPECT_LT(rep.speed.std_rpm, 1e-3);
  EXPECT_TRUE(rep.warnings.empty()) << rep.warnings.front();

  const CsvTable truth = read_csv_table(vr.truth);
  const auto& theta2 = truth["theta2_rad"];
  const auto& omega2 = truth["omega2_rad_s"];
  const double lsb_m_s2 = v.spec.full_scale_V * std::ldexp(1.0, -23) / 0.01;
  std::vector<double> angle_err, speed_err;
  double worst = 0;
  ASSERT_GT(run.out.time.size(), 10000u);
  for (std::size_t i = 0; i < run.out.time.size(); ++i) {
    const auto n = static_cast<std::size_t>(std::llround(run.out.time[i] * fs));
    angle_err.push_back(wrap(run.out.crank[i] - theta2[n]));
    speed_err.push_back(run.out.omega[i] - omega2[n]);
    for (std::size_t c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(run.out.channels[c][i] - truth[v.spec.sensors[c].name + "_m_s2"][n]));
  }
  EXPECT_LT(units::rad_to_deg(rms(angle_err)), 1e-4);
  RecordProperty("clean_angle_rms_deg", format_double(units::rad_to_deg(rms(angle_err))));
  EXPECT_LT(rms(speed_err), 1e-5 * 36.65);
  EXPECT_LE(worst, 0.5 * lsb_m_s2 * (1 + 1e-6));
  EXPECT_GT(worst, 0.1 * lsb_m_s2);  // it is quantised, not bit-identical by accident
}

// ±2 % sinusoidal speed fluctuation (period: ten revolutions): crank angle per
// sample within 0.05° RMS; constant speed per revolution would be ~1° off.
TEST(AcquireRoundTrip, CrankAngleFollowsSpeedFluctuation) {
  VirtualSetup v;
  v.spec.revolutions = 30;
  v.spec.speed_fluctuation = 0.02;
  v.spec.sample_format = "pcm16";
  const VirtualRigResult vr = v.write("fluct.wav");
  const Acquired run = run_acquire(vr.recording);
  const CrankDrive drive = v.drive();
  std::vector<double> angle_err, speed_err, accel_err;
  for (std::size_t i = 0; i < run.out.time.size(); i += 7) {
    const CrankState truth = drive.at(run.out.time[i]);
    angle_err.push_back(wrap(run.out.crank[i] - truth.angle_rad));
    speed_err.push_back(run.out.omega[i] - truth.speed_rad_s);
    accel_err.push_back(run.out.alpha[i] - truth.accel_rad_s2);
  }
  const double angle_rms_deg = units::rad_to_deg(rms(angle_err));
  EXPECT_LT(angle_rms_deg, 0.05);
  RecordProperty("angle_rms_deg", format_double(angle_rms_deg));
  EXPECT_LT(rms(speed_err), 0.002 * 36.65);
  // α2 peaks at ε·ω0·2π/T = 0.02·36.65·2π/1.714 s = 2.7 rad/s².
  EXPECT_LT(rms(accel_err), 0.3);
  EXPECT_GT(run.report.speed.max_rpm - run.report.speed.min_rpm, 0.02 * 350);
}

// The crank-angle grid: each revolution's N points at the right times, with
// channel values equal to the truth at those times.
TEST(AcquireRoundTrip, RevolutionsOnTheCrankAngleGrid) {
  VirtualSetup v;
  v.spec.speed_fluctuation = 0.01;
  v.spec.sample_format = "float";
  const VirtualRigResult vr = v.write("grid.w64", false);
  AcquireOptions o;
  o.grid_points_per_rev = 720;
  const Acquired run = run_acquire(vr.recording, o);
  ASSERT_EQ(run.out.revolutions.size(), run.report.revolutions);
  const CrankDrive drive = v.drive();
  const NominalMotionSource motion(v.scene.rig, drive);
  std::vector<double> angle_err, channel_err, channel_ref;
  for (const Revolution& r : run.out.revolutions) {
    ASSERT_EQ(r.crank_rad.size(), 720u);
    EXPECT_DOUBLE_EQ(r.time_s[0], r.start_time_s);
    EXPECT_NEAR(r.crank_rad[1] - r.crank_rad[0], units::kTwoPi / 720, 1e-12);
    for (std::size_t j = 0; j < 720; j += 3) {
      const LinkState st = motion.at(r.time_s[j]);
      angle_err.push_back(wrap(r.crank_rad[j] - st.crank.angle_rad));
      for (std::size_t c = 0; c < 3; ++c) {
        const ChannelSpec& s = v.spec.sensors[c];
        const double f = specific_force(*v.scene.rig, st, s.role, s.position_m, s.offset_m);
        channel_err.push_back(r.channels_m_s2[c][j] - f);
        channel_ref.push_back(f);
      }
    }
  }
  EXPECT_LT(units::rad_to_deg(rms(angle_err)), 0.01);
  // 4-point interpolation between float samples: < 1e-5 of the signal RMS.
  EXPECT_LT(rms(channel_err), 1e-5 * rms(channel_ref));
  RecordProperty("grid_angle_rms_deg", format_double(units::rad_to_deg(rms(angle_err))));
  RecordProperty("grid_channel_rms_relative", format_double(rms(channel_err) / rms(channel_ref)));
}

// The same recording in every container, sample format and as CSV gives the
// same revolutions (to the quantisation of the coarsest format, 24 bits).
TEST(AcquireRoundTrip, EveryFormatReadsTheSameData) {
  VirtualSetup v;
  v.spec.revolutions = 4;
  v.spec.sample_format = "pcm24";
  const Acquired ref = run_acquire(v.write("ref.wav", false).recording);
  const double lsb = v.spec.full_scale_V * std::ldexp(1.0, -23) / 0.01;
  struct Case {
    std::string file, format;
  };
  const std::vector<Case> cases{{"a.w64", "pcm24"}, {"a.rf64", "pcm24"}, {"a.flac", "pcm24"}, {"a.caf", "pcm24"},
                                {"a.aiff", "pcm24"}, {"b.wav", "float"}, {"b.caf", "double"}, {"b.rf64", "pcm32"},
                                {"c.csv", ""}};
  for (const auto& c : cases) {
    v.spec.sample_format = c.format.empty() ? std::optional<std::string>() : c.format;
    const Acquired got = run_acquire(v.write(c.file, false).recording);
    ASSERT_EQ(got.out.revolutions.size(), ref.out.revolutions.size()) << c.file;
    const auto tp = pulse_times(got.report), tr = pulse_times(ref.report);
    for (std::size_t k = 0; k < tp.size(); ++k) EXPECT_NEAR(tp[k], tr[k], 1e-3 / v.spec.sample_rate_hz) << c.file;
    double worst = 0;
    for (std::size_t r = 0; r < ref.out.revolutions.size(); ++r)
      for (std::size_t ch = 0; ch < 3; ++ch)
        for (std::size_t j = 0; j < ref.out.revolutions[r].channels_m_s2[ch].size(); ++j)
          worst = std::max(worst, std::abs(got.out.revolutions[r].channels_m_s2[ch][j] -
                                           ref.out.revolutions[r].channels_m_s2[ch][j]));
    EXPECT_LT(worst, 2 * lsb) << c.file;
    EXPECT_EQ(got.report.recording.format, c.file.ends_with(".csv") ? "CSV" : got.report.recording.format);
  }
}

// AC-coupled sensors: acquire returns what the high-pass let through.
TEST(AcquireRoundTrip, AcCoupledChannelsAreAsRecorded) {
  VirtualSetup v;
  v.spec.revolutions = 4;
  for (auto& s : v.spec.sensors) s.ac_coupled = true, s.highpass_hz = 2.0;
  const VirtualRigResult vr = v.write("ac.rf64");
  const Acquired run = run_acquire(vr.recording);
  const CsvTable truth = read_csv_table(vr.truth);
  const double lsb = v.spec.full_scale_V * std::ldexp(1.0, -23) / 0.01;
  double worst = 0, dc_shift = 0;
  for (std::size_t i = 0; i < run.out.time.size(); ++i) {
    const auto n = static_cast<std::size_t>(std::llround(run.out.time[i] * v.spec.sample_rate_hz));
    for (std::size_t c = 0; c < 3; ++c) {
      const std::string name = v.spec.sensors[c].name;
      worst = std::max(worst, std::abs(run.out.channels[c][i] - truth[name + "_hp_m_s2"][n]));
      dc_shift = std::max(dc_shift, std::abs(truth[name + "_hp_m_s2"][n] - truth[name + "_m_s2"][n]));
    }
  }
  EXPECT_LE(worst, 0.5 * lsb * (1 + 1e-6));
  EXPECT_GT(dc_shift, 1.0);  // the high-pass really changed the signal (gravity's mean, centripetal mean)
  for (const auto& c : run.report.channels) EXPECT_TRUE(c.ac_coupled && c.highpass_hz == 2.0);
}

// Clockwise crank, falling pulse polarity, a pulse angle offset.
TEST(AcquireRoundTrip, ClockwiseCrankAndFallingPulses) {
  VirtualSetup v(-300.0);
  v.spec.revolutions = 6;
  v.spec.pulse.polarity = PulsePolarity::falling;
  v.spec.pulse.angle_rad = units::deg_to_rad(75);
  const VirtualRigResult vr = v.write("cw.aiff");
  const Acquired run = run_acquire(vr.recording);
  EXPECT_EQ(run.report.revolutions, vr.pulse_times_s.size() - 1);
  EXPECT_LT(rms(pulse_errors(pulse_times(run.report), vr.pulse_times_s)) * v.spec.sample_rate_hz, 1e-3);
  const CrankDrive drive = v.drive();
  std::vector<double> err;
  for (std::size_t i = 0; i < run.out.time.size(); i += 5) {
    err.push_back(wrap(run.out.crank[i] - drive.at(run.out.time[i]).angle_rad));
    EXPECT_LT(run.out.omega[i], 0);
  }
  EXPECT_LT(units::rad_to_deg(rms(err)), 1e-3);
  EXPECT_NEAR(run.out.revolutions[0].crank_rad[0], units::deg_to_rad(75), 1e-12);
  EXPECT_LT(run.out.revolutions[0].crank_rad[1], run.out.revolutions[0].crank_rad[0]);
  EXPECT_TRUE(run.report.warnings.empty());

  // The manifest's polarity set wrong: the trailing edges are timed, and a
  // warning says so.
  const auto m = vr.manifest;
  std::string text = testing::read_file(m);
  const std::string falling = "polarity = \"falling\"";
  text.replace(text.find(falling), falling.size(), "polarity = \"rising\"");
  std::ofstream(m) << text;
  const Acquired wrong = run_acquire(vr.recording);
  ASSERT_EQ(wrong.report.warnings.size(), 1u);
  EXPECT_NE(wrong.report.warnings[0].find("times their trailing edge"), std::string::npos) << wrong.report.warnings[0];
}

// Missing pulses, echoes and a noisy tacho: found, reported, repaired.
TEST(AcquireRoundTrip, MissingAndEchoPulsesAreRepairedAndReported) {
  VirtualSetup v;
  v.spec.revolutions = 20;
  v.spec.sample_format = "pcm16";
  v.spec.noise_snr_db = 40;
  v.spec.hum_V = 0.005;
  v.spec.hum_harmonics = {1.0, 0.3, 0.1};
  v.spec.pulse.noise_V = 0.3;  // noisy tacho: 6 % of the swing
  v.spec.pulse.jitter_s = 2e-6;
  v.spec.pulse.missing = {3, 7, 8};
  v.spec.pulse.echo = {5, 12};
  v.spec.pulse.echo_delay_s = 0.01;  // after the 4.8 ms pulse: a separate edge
  const VirtualRigResult vr = v.write("faults.flac");
  const Acquired run = run_acquire(vr.recording);
  const AcquisitionReport& rep = run.report;
  ASSERT_EQ(rep.pulses.segments.size(), 1u);
  ASSERT_EQ(rep.pulses.inserted_s.size(), 3u);
  ASSERT_EQ(rep.pulses.removed_s.size(), 2u);
  // Inserted pulses sit where the crank passes the pulse angle. The detected
  // pulses around them carry timing noise: 2 µs jitter and 0.3 V noise on a
  // ramp of 1.25 V per sample (σ ≈ 0.3/1.25/√3 samples ≈ 5 µs), i.e. about
  // 2e-4 rad at 36.65 rad/s; a cubic through them passes it on.
  const CrankDrive drive = v.drive();
  for (double t : rep.pulses.inserted_s) {
    const double turned = std::remainder(drive.at(t).angle_rad, units::kTwoPi);
    EXPECT_LT(std::abs(turned), 1e-3) << t;
  }
  EXPECT_NEAR(rep.pulses.removed_s[0], vr.pulse_times_s[4] + 0.01, 1e-4);  // echo of pulse 5 (4 after two missing)
  EXPECT_EQ(rep.revolutions, vr.pulse_times_s.size() + 3 - 1);
  EXPECT_EQ(rep.revolutions_repaired, 5u);
  std::size_t repaired = 0;
  for (const auto& r : run.out.revolutions) repaired += r.repaired;
  EXPECT_EQ(repaired, 5u);
  bool warned_inserted = false, warned_removed = false;
  for (const auto& w : rep.warnings) {
    warned_inserted |= w.find("3 missing pulses inserted") != std::string::npos;
    warned_removed |= w.find("2 spurious pulse edges removed") != std::string::npos;
  }
  EXPECT_TRUE(warned_inserted && warned_removed);
  // The crank angle stays right through the repaired revolutions (to the
  // ~2e-4 rad = 0.011° timing noise of the pulses, see above).
  std::vector<double> err;
  for (std::size_t i = 0; i < run.out.time.size(); i += 5)
    err.push_back(wrap(run.out.crank[i] - drive.at(run.out.time[i]).angle_rad));
  EXPECT_LT(units::rad_to_deg(rms(err)), 0.02);
}

// A doubled sync mark: a second pulse 8 ms after every pulse (a second bolt
// head, or an echo on the cable). The first of each pair is kept.
TEST(AcquireRoundTrip, DoubledSyncPulsesKeepTheFirst) {
  VirtualSetup v;
  v.spec.revolutions = 10;
  for (long long k = 0; k < 12; ++k) v.spec.pulse.echo.push_back(k);
  v.spec.pulse.echo_delay_s = 0.008;
  const VirtualRigResult vr = v.write("doubled.wav", false);
  const Acquired run = run_acquire(vr.recording);
  EXPECT_EQ(run.report.pulses.edges, 2 * vr.pulse_times_s.size());
  EXPECT_EQ(run.report.pulses.removed_s.size(), vr.pulse_times_s.size());
  EXPECT_EQ(run.report.revolutions, vr.pulse_times_s.size() - 1);
  EXPECT_LT(rms(pulse_errors(pulse_times(run.report), vr.pulse_times_s)) * v.spec.sample_rate_hz, 1e-3);
}

// A tacho with noise of 12 % of its swing: a plain threshold at mid-level
// counts extra pulses at the edges; the automatic hysteresis counts each once.
TEST(AcquireRoundTrip, NoisyTachoCountsEveryPulseOnce) {
  VirtualSetup v;
  v.spec.revolutions = 15;
  v.spec.pulse.noise_V = 0.6;
  const VirtualRigResult vr = v.write("noisy_tacho.wav", false);
  // What a single threshold at 2.5 V sees.
  auto reader = open_recording(vr.recording);
  std::vector<double> x(reader->info().frames * 4);
  reader->read(x);
  std::size_t naive = 0;
  for (std::size_t i = 1; i < x.size() / 4; ++i) naive += x[(i - 1) * 4 + 3] * 10 < 2.5 && x[i * 4 + 3] * 10 >= 2.5;
  EXPECT_GT(naive, vr.pulse_times_s.size() + 2);
  const Acquired run = run_acquire(vr.recording);
  EXPECT_EQ(run.report.pulses.edges, vr.pulse_times_s.size());
  EXPECT_TRUE(run.report.pulses.removed_s.empty());
  EXPECT_EQ(run.report.revolutions, vr.pulse_times_s.size() - 1);
  // Timing: with noise of half the ramp's step per sample (0.6 V against
  // 1.25 V per sample) each pulse is still placed within one sample period.
  EXPECT_LT(rms(pulse_errors(pulse_times(run.report), vr.pulse_times_s)) * v.spec.sample_rate_hz, 1.0);
}

TEST(AcquireRoundTrip, ClippingIsCountedAndMarked) {
  VirtualSetup v;
  v.spec.revolutions = 4;
  v.spec.sensors[2].volts_per_m_s2 = 0.12;  // rocker: ~110 m/s² peaks → 13 V on a ±10 V range
  const VirtualRigResult vr = v.write("clip.wav", false);
  EXPECT_GT(vr.clipped_samples, 0u);
  const Acquired run = run_acquire(vr.recording);
  EXPECT_TRUE(run.report.clipping_checked);
  EXPECT_EQ(run.report.channel_stats[0].clipped_samples, 0u);
  EXPECT_GT(run.report.channel_stats[2].clipped_samples, 0u);
  EXPECT_LE(run.report.channel_stats[2].clipped_samples, vr.clipped_samples);
  EXPECT_GT(run.report.revolutions_clipped, 0u);
}

// A sink that resamples on a grid of its own (analyze) asks for none: the
// revolutions then come with empty grids but the same times, periods and
// clipping flags, and the samples are tagged exactly as with a grid.
TEST(AcquireRoundTrip, SinkWithoutGridGetsTheSameRevolutionsAndSamples) {
  VirtualSetup v;
  v.spec.revolutions = 4;
  v.spec.sensors[2].volts_per_m_s2 = 0.12;  // clipped in some revolutions, as above
  const VirtualRigResult vr = v.write("nogrid.wav", false);
  const Acquired with_grid = run_acquire(vr.recording);
  struct NoGrid : Collect {
    bool wants_grid() const override { return false; }
  };
  OpenedRecording o = open_with_manifest(vr.recording, {});
  NoGrid out;
  AcquireOptions options;
  options.progress = false;
  const AcquisitionReport report = acquire(*o.reader, o.manifest, options, out);
  EXPECT_GT(with_grid.report.grid_points_per_rev, 0);
  EXPECT_EQ(report.grid_points_per_rev, 0);
  EXPECT_GT(report.revolutions_clipped, 0u);
  EXPECT_EQ(report.revolutions_clipped, with_grid.report.revolutions_clipped);
  ASSERT_EQ(out.revolutions.size(), with_grid.out.revolutions.size());
  for (std::size_t k = 0; k < out.revolutions.size(); ++k) {
    const Revolution &a = out.revolutions[k], &b = with_grid.out.revolutions[k];
    EXPECT_TRUE(a.crank_rad.empty());
    EXPECT_EQ(a.start_time_s, b.start_time_s);
    EXPECT_EQ(a.period_s, b.period_s);
    EXPECT_EQ(a.clipped, b.clipped) << "revolution " << k;
  }
  EXPECT_EQ(out.time, with_grid.out.time);
  EXPECT_EQ(out.crank, with_grid.out.crank);
  EXPECT_EQ(out.revolution, with_grid.out.revolution);
  EXPECT_EQ(out.channels, with_grid.out.channels);
}

TEST(AcquireBadInput, FewerThanTwoRevolutions) {
  VirtualSetup v;
  v.spec.revolutions = 1.8;  // pulses at 320° and 680°: one complete revolution
  const VirtualRigResult vr = v.write("short.wav", false);
  try {
    run_acquire(vr.recording);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("need at least 2"), std::string::npos) << e.what();
  }
}

TEST(AcquireBadInput, NonFiniteSampleInAFloatFile) {
  VirtualSetup v;
  v.spec.revolutions = 3;
  v.spec.sample_format = "float";
  const VirtualRigResult vr = v.write("nan.wav", false);
  // Rewrite the recording with one NaN, keeping the manifest.
  std::vector<double> x(vr.frames * 4);
  open_recording(vr.recording)->read(x);
  x[1000 * 4 + 1] = std::nan("");
  {
    auto w = open_recording_writer(vr.recording, 4, v.spec.sample_rate_hz, {"a", "b", "c", "d"}, "float", {});
    w->write(x);
    w->commit();
  }
  try {
    run_acquire(vr.recording);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("channel 1 holds a non-finite value at frame 1000"), std::string::npos)
        << e.what();
  }
}

TEST(AcquireBadInput, NoPulses) {
  VirtualSetup v;
  v.spec.revolutions = 4;
  v.spec.pulse.missing = {0, 1, 2, 3, 4};
  const VirtualRigResult vr = v.write("none.caf", false);
  try {
    run_acquire(vr.recording);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no crank pulses"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("crank_pulse"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fourbar
