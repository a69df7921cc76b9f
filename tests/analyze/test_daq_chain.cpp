// The DAQ chain's known timing against the virtual rig's truth: a
// multiplexed ADC samples channel i i·skew after channel 0 (skew
// 1/(fs·channels) at 12.8 kHz, 4 channels: 19.5 µs). Analysed with the
// manifest's `sampling`/`skew_us` keys the error is that of simultaneous
// sampling; with the keys removed (what a lab that does not know gets) the
// channels sit at the wrong crank angles and the averaged α3/ω3 error grows.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "acquire/manifest.hpp"
#include "common/error.hpp"
#include "virtual_session.hpp"

namespace fourbar {
namespace {

using testing::rel_rms_error;
using testing::row_mean;
using testing::VirtualSetup;

struct DaqErrors {
  double alpha3 = 0, omega3 = 0, alpha4 = 0, omega4 = 0;
  double phase3_order4_deg = 0, phase3_order8_deg = 0;  // arg(estimate/truth) of α3's crank order
};

/// arg(est/truth) of crank order k of two revolution averages (degrees).
double order_phase_deg(const std::vector<double>& est, const std::vector<double>& truth, int k) {
  std::complex<double> e = 0, t = 0;
  const std::size_t N = est.size();
  for (std::size_t i = 0; i < N; ++i) {
    const std::complex<double> w = std::polar(1.0, -2 * std::numbers::pi * k * static_cast<double>(i) / N);
    e += est[i] * w, t += truth[i] * w;
  }
  return std::arg(e / t) * 180 / std::numbers::pi;
}

DaqErrors run(const VirtualSetup& v, const VirtualRigResult& written, const std::filesystem::path& manifest) {
  AnalyzeOptions o;
  o.keep_revolutions = true;
  o.progress = false;
  // Two guard revolutions at each end: the correction's wrap-around at the
  // record ends (a few samples) stays out of the average.
  o.guard_revolutions = 2;
  const RecordingAnalysis a = analyze_recording(written.recording, manifest, o);
  const testing::GridTruth t = testing::grid_truth(v, written, a, a.revolution_numbers);
  const std::size_t N = a.grid_points_per_rev;
  const std::vector<double> alpha3 = row_mean(t.alpha3, N);
  return {rel_rms_error(a.coupler->alpha_rad_s2.mean, alpha3),
          rel_rms_error(a.coupler->omega_rad_s.mean, row_mean(t.omega3, N)),
          rel_rms_error(a.rocker->alpha_rad_s2.mean, row_mean(t.alpha4, N)),
          rel_rms_error(a.rocker->omega_rad_s.mean, row_mean(t.omega4, N)),
          order_phase_deg(a.coupler->alpha_rad_s2.mean, alpha3, 4),
          order_phase_deg(a.coupler->alpha_rad_s2.mean, alpha3, 8)};
}

/// The manifest without the lines starting with any of `keys`.
std::filesystem::path without_keys(const std::filesystem::path& manifest, std::initializer_list<std::string> keys,
                                   const std::string& name) {
  std::ifstream in(manifest);
  std::ostringstream out;
  std::string line;
  bool found = false;
  while (std::getline(in, line)) {
    bool drop = false;
    for (const auto& k : keys) drop = drop || line.rfind(k + " ", 0) == 0;
    found = found || drop;
    if (!drop) out << line << "\n";
  }
  EXPECT_TRUE(found) << "the virtual rig wrote none of the keys into " << manifest;
  const auto p = manifest.parent_path() / name;
  std::ofstream(p) << out.str();
  return p;
}

void print(const char* what, const DaqErrors& e) {
  std::printf("  %-44s %8.4f%% %8.4f%% %8.4f%% %8.4f%% %8.3f %8.3f\n", what, 100 * e.alpha3, 100 * e.omega3,
              100 * e.alpha4, 100 * e.omega4, e.phase3_order4_deg, e.phase3_order8_deg);
}

/// The thesis rig at 350 rpm sampled at 12.8 kHz, no noise: 24 revolutions.
VirtualSetup lab_setup() {
  VirtualSetup v;
  v.spec.sample_rate_hz = 12800;
  v.spec.pulse.rise_s = 4.0 / v.spec.sample_rate_hz;
  v.spec.revolutions = 24;
  return v;
}

struct Effect {
  DaqErrors known, unknown;
};

/// One DAQ effect recorded by the virtual rig, analysed with the manifest it
/// wrote (the keys present) and with `keys` removed.
Effect measure(const VirtualSetup& v, const std::string& name, std::initializer_list<std::string> keys) {
  const VirtualRigResult w = v.write(name + ".wav", false);
  Effect e;
  e.known = run(v, w, {});
  e.unknown = run(v, w, without_keys(w.manifest, keys, name + "_no_keys.toml"));
  return e;
}

void print(const char* what, const Effect& e) {
  const std::string a = std::string(what) + ", keys present", b = std::string(what) + ", keys absent";
  print(a.c_str(), e.known);
  print(b.c_str(), e.unknown);
}

// Skew 1/(n·fs) at 12.8 kHz: the coupler channel (index 0) is sampled
// 3·19.53 µs before the crank channel (index 3), the rocker's 1·19.53 µs.
// The stated skew is removed; without it the error grows.
TEST(DaqChain, MultiplexedSkewIsRemovedWhenTheManifestStatesIt) {
  VirtualSetup v = lab_setup();
  const DaqErrors ref = run(v, v.write("simultaneous.wav", false), {});
  v.spec.multiplexed = true;  // skew 1/(fs·4 channels) = 19.53 µs
  const VirtualRigResult w = v.write("probe.wav", false);
  EXPECT_NEAR(load_manifest(w.manifest).channel_skew_s, 1.0 / (12800.0 * 4), 1e-12);
  const Effect e = measure(v, "multiplexed", {"sampling", "skew_us"});
  std::printf("\n  averaged RMS error / RMS of truth, thesis rig 350 rpm, 12.8 kHz, no noise; phase error of a3 orders 4, 8 (deg)\n"
              "  %-44s %9s %9s %9s %9s %8s %8s\n",
              "recording / manifest", "a3", "w3", "a4", "w4", "ph4", "ph8");
  print("simultaneous sampling", ref);
  print("multiplexed (skew 19.53 us)", e);

  EXPECT_GT(e.unknown.alpha3, 5 * e.known.alpha3);
  EXPECT_GT(e.unknown.alpha4, 3 * e.known.alpha4);
  // The coupler channel leads the crank channel by 3 skews (58.6 µs): order
  // k at 350 rpm is shifted by 360°·k·(350/60 Hz)·58.6 µs (0.49° at k = 4,
  // 0.98° at 8) without the keys, and back to the reference with them.
  const double lead_s = 3.0 / (12800.0 * 4), order_hz = 350.0 / 60;
  EXPECT_NEAR(std::abs(e.unknown.phase3_order8_deg), 360 * 8 * order_hz * lead_s, 0.1);
  EXPECT_NEAR(std::abs(e.unknown.phase3_order4_deg), 360 * 4 * order_hz * lead_s, 0.05);
  EXPECT_LT(std::abs(e.known.phase3_order8_deg - ref.phase3_order8_deg), 0.01);
  EXPECT_LT(std::abs(e.known.phase3_order4_deg - ref.phase3_order4_deg), 0.01);
  EXPECT_LT(e.known.alpha3, ref.alpha3 + 2e-4);
  EXPECT_LT(e.known.alpha4, ref.alpha4 + 2e-4);
  EXPECT_LT(e.known.omega3, ref.omega3 + 2e-4);
}

// A 6th-order Butterworth anti-alias filter at 2 kHz on the accelerometer
// channels: its phase (about 0.24 ms of group delay in band) moves the
// channels against the unfiltered crank pulse; dividing its response out in
// band removes that.
TEST(DaqChain, ButterworthFilterPhaseIsRemovedWhenTheManifestStatesIt) {
  VirtualSetup v = lab_setup();
  const DaqErrors ref = run(v, v.write("plain.wav", false), {});
  v.spec.daq_filter = {"butterworth", 6, 2000.0, 0.0};
  const Effect e = measure(v, "butterworth", {"daq_filter", "daq_filter_order", "daq_filter_cutoff_Hz"});
  print("no filter", ref);
  print("Butterworth 6th order, 2 kHz", e);
  EXPECT_GT(e.unknown.alpha3, 10 * e.known.alpha3);
  EXPECT_GT(e.unknown.alpha4, 10 * e.known.alpha4);
  EXPECT_LT(e.known.alpha3, ref.alpha3 + 2e-4);
  EXPECT_LT(e.known.alpha4, ref.alpha4 + 2e-4);
  EXPECT_GT(std::abs(e.unknown.phase3_order8_deg), 2.0);
  EXPECT_LT(std::abs(e.known.phase3_order8_deg - ref.phase3_order8_deg), 0.05);
}

// A linear-phase FIR of 0.5 ms group delay: a delay of the accelerometer
// channels against the crank pulse, removed when stated.
TEST(DaqChain, LinearPhaseFilterDelayIsRemovedWhenTheManifestStatesIt) {
  VirtualSetup v = lab_setup();
  const DaqErrors ref = run(v, v.write("plain.wav", false), {});
  v.spec.daq_filter = {"linear_phase", 0, 0.0, 500e-6};
  const Effect e = measure(v, "fir", {"daq_filter", "daq_filter_delay_us"});
  print("linear-phase FIR, 500 us delay", e);
  EXPECT_GT(e.unknown.alpha3, 10 * e.known.alpha3);
  EXPECT_LT(e.known.alpha3, ref.alpha3 + 2e-4);
  EXPECT_LT(e.known.alpha4, ref.alpha4 + 2e-4);
  EXPECT_GT(std::abs(e.unknown.phase3_order8_deg), 2.0);
  EXPECT_LT(std::abs(e.known.phase3_order8_deg - ref.phase3_order8_deg), 0.05);
}

// A mounted resonance at 1 kHz, Q = 10 (a soft mount) on every sensor: its
// gain below f_r (1 + (f/f_r)² at low f) and phase lift the high orders;
// dividing it out removes them.
TEST(DaqChain, SensorResonanceIsRemovedWhenTheManifestStatesIt) {
  VirtualSetup v = lab_setup();
  const DaqErrors ref = run(v, v.write("plain.wav", false), {});
  for (ChannelSpec& c : v.spec.sensors) c.sensor_resonance_hz = 1000, c.sensor_resonance_q = 10;
  const Effect e = measure(v, "resonance", {"sensor_resonance_Hz", "sensor_resonance_Q"});
  print("sensor resonance 1 kHz, Q 10", e);
  EXPECT_GT(e.unknown.alpha3, 2 * e.known.alpha3);
  EXPECT_LT(e.known.alpha3, ref.alpha3 + 2e-4);
  EXPECT_LT(e.known.alpha4, ref.alpha4 + 2e-4);
}

TEST(DaqChain, ManifestKeysAreCheckedAtTheBoundary) {
  VirtualSetup v;
  const VirtualRigResult w = v.write("plain.wav", false);
  const auto add = [&](const std::string& extra, const std::string& name) {
    std::ifstream in(w.manifest);
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    s.insert(s.find("\n[[channel]]"), "\n" + extra);
    const auto p = w.manifest.parent_path() / name;
    std::ofstream(p) << s;
    return p;
  };
  const auto message = [](const std::filesystem::path& p) -> std::string {
    try {
      load_manifest(p);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message(add("skew_us = 10", "a.toml")).find("skew_us"), std::string::npos);
  EXPECT_NE(message(add("sampling = \"multiplexed\"", "b.toml")).find("skew_us"), std::string::npos);
  EXPECT_NE(message(add("sampling = \"interleaved\"", "c.toml")).find("sampling"), std::string::npos);
  EXPECT_EQ(message(add("sampling = \"multiplexed\"\nskew_us = 10", "d.toml")), "");
  EXPECT_NEAR(load_manifest(add("sampling = \"multiplexed\"\nskew_us = 10", "e.toml")).channel_skew_s, 10e-6, 1e-15);
  // The anti-alias filter: an unknown type lists the known ones; keys of
  // another type or a missing order/cutoff name the key.
  const std::string unknown = message(add("daq_filter = \"chebyshev\"", "f.toml"));
  EXPECT_NE(unknown.find("daq_filter"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("butterworth"), std::string::npos) << unknown;
  EXPECT_NE(message(add("daq_filter = \"butterworth\"\ndaq_filter_order = 4", "g.toml")).find("daq_filter_cutoff_Hz"),
            std::string::npos);
  EXPECT_NE(message(add("daq_filter_delay_us = 300", "h.toml")).find("daq_filter_delay_us"), std::string::npos);
  const Manifest bw = load_manifest(add("daq_filter = \"butterworth\"\ndaq_filter_order = 5\ndaq_filter_cutoff_Hz = 4000", "i.toml"));
  EXPECT_EQ(bw.daq_filter.order, 5);
  EXPECT_EQ(daq_filter_sections(bw.daq_filter).size(), 3u);
  // Written back and read again: the same filter.
  EXPECT_EQ(load_manifest(add(daq_filter_toml(bw.daq_filter), "j.toml")).daq_filter.cutoff_hz, 4000.0);
  // A resonance needs both keys, within range.
  const auto with_channel_key = [&](const std::string& key, const std::string& name) {
    std::ifstream in(w.manifest);
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    const auto at = s.find("role = \"coupler_tangential\"");
    s.insert(s.find('\n', at) + 1, key + "\n");
    const auto p = w.manifest.parent_path() / name;
    std::ofstream(p) << s;
    return p;
  };
  EXPECT_NE(message(with_channel_key("sensor_resonance_Hz = 20000", "k.toml")).find("sensor_resonance_Q"),
            std::string::npos);
  EXPECT_NE(message(with_channel_key("sensor_resonance_Hz = 20000\nsensor_resonance_Q = 0.1", "l.toml"))
                .find("sensor_resonance_Q"),
            std::string::npos);
  const Manifest r = load_manifest(with_channel_key("sensor_resonance_Hz = 20000\nsensor_resonance_Q = 25", "m.toml"));
  EXPECT_EQ(r.channel_with(ChannelRole::coupler_tangential)->sensor_resonance_hz, 20000.0);
}

}  // namespace
}  // namespace fourbar
