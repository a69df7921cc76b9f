// Throughput of the analyze chain on a synthetic 3-channel 25.6 kHz record
// (thesis rig at 350 rpm, coupler tangential + normal, rocker tangential,
// AC-coupled, 30 dB SNR, 60 Hz hum): restore → convert → Kaiser band-pass
// with mains comb → crank-angle grid → periodic integration → average.
// Frames = samples per channel. Run:
//   build/bench/bench_analyze --benchmark_min_time=1
// Record length in seconds: FOURBAR_BENCH_SECONDS (default 60).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>

#include "analyze/link_analysis.hpp"
#include "analyze/spectrum.hpp"
#include "synthetic_recording.hpp"  // tests/analyze: the synthetic recording generator

namespace {

using namespace fourbar;

double record_seconds() {
  const char* s = std::getenv("FOURBAR_BENCH_SECONDS");
  return s ? std::atof(s) : 60.0;
}

struct Fixture {
  testing::SyntheticRig rig;
  testing::SyntheticRecording rec;
  AccelerometerMount coupler_t, rocker_t, coupler_n;
  ChannelOptions band, low;
};

const Fixture& fixture() {
  static const std::unique_ptr<Fixture> f = [] {
    auto x = std::make_unique<Fixture>();
    x->rig.duration_s = record_seconds();
    const testing::HousingMounts m = testing::housing_mounts();
    x->coupler_t = m.coupler_t, x->coupler_n = m.coupler_n, x->rocker_t = m.rocker_t;
    x->rec = testing::make_recording(x->rig, {x->coupler_t, x->rocker_t, x->coupler_n});
    x->band.filter = testing::band_pass_with_mains_comb();
    x->low = x->band;
    x->low.filter.band = BandType::lowpass;
    return x;
  }();
  return *f;
}

// Peak resident memory of the process (kB), from /proc.
double peak_rss_mb() {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) / 1024.0;
  return 0;
}

void BM_AnalyzeChain3Channels(benchmark::State& state) {
  const Fixture& f = fixture();
  const CrankTrack crank = f.rec.crank();
  const double fs = f.rig.sample_rate_hz;
  for (auto _ : state) {
    RecordAnalyzer analyzer(f.rig.rig, crank, fs, AngleGridSpec{});
    const LinkAnalysis c = analyzer.tangential(f.coupler_t, f.rec.channels[0].recorded, f.band);
    const LinkAnalysis r = analyzer.tangential(f.rocker_t, f.rec.channels[1].recorded, f.band);
    const NormalChannelAnalysis n = analyzer.normal(f.coupler_n, f.rec.channels[2].recorded, c.alpha_rad_s2, f.low);
    benchmark::DoNotOptimize(c.omega.mean.data());
    benchmark::DoNotOptimize(r.omega.mean.data());
    benchmark::DoNotOptimize(n.omega_sq.mean.data());
  }
  state.SetItemsProcessed(state.iterations() * f.rec.angle.size());
  state.counters["frames"] = static_cast<double>(f.rec.angle.size());
  state.counters["peak_rss_MB"] = peak_rss_mb();
}
BENCHMARK(BM_AnalyzeChain3Channels)->Unit(benchmark::kMillisecond);

// Parts, one channel each.
void BM_ConvertTangentialExactTrack(benchmark::State& state) {
  const Fixture& f = fixture();
  std::vector<double> out(f.rec.angle.size());
  for (auto _ : state) {
    // The exact nominal link track (one closed-form solution per sample),
    // the AC restore and the conversion, in two passes.
    const std::vector<SensedLinkMotion> track = nominal_link_track(f.rig.rig, SensedLink::coupler, f.rec.crank());
    restore_dc_coupled_reading(f.rig.rig, f.coupler_t, track, f.rig.sample_rate_hz, f.rec.channels[0].recorded, out);
    angular_acceleration_from_tangential(f.rig.rig, f.coupler_t, track, out, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * out.size());
}
BENCHMARK(BM_ConvertTangentialExactTrack)->Unit(benchmark::kMillisecond);

void BM_ConvertTangentialTable(benchmark::State& state) {
  const Fixture& f = fixture();
  const LinkTable table(f.rig.rig, SensedLink::coupler);  // once per rig
  std::vector<double> out(f.rec.angle.size());
  for (auto _ : state) {
    // The same in one pass, the nominal motion read from the table.
    convert_reading(f.rig.rig, f.coupler_t, table, f.rec.crank(), f.rig.sample_rate_hz, f.rec.channels[0].recorded, {},
                    out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * out.size());
}
BENCHMARK(BM_ConvertTangentialTable)->Unit(benchmark::kMillisecond);

void BM_FftFilterWholeRecord(benchmark::State& state) {
  const Fixture& f = fixture();
  const auto& x = f.rec.channels[0].recorded;
  FftFilter filter(f.band.filter, f.rig.sample_rate_hz, x.size());  // plan made once
  std::vector<double> out(x.size());
  for (auto _ : state) {
    filter.apply(x, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * x.size());
}
BENCHMARK(BM_FftFilterWholeRecord)->Unit(benchmark::kMillisecond);

void BM_OverlapSaveStreaming(benchmark::State& state) {
  const Fixture& f = fixture();
  const auto& x = f.rec.channels[0].recorded;
  OverlapSaveFilter filter(f.band.filter, f.rig.sample_rate_hz);
  std::vector<double> out;
  out.reserve(filter.fft_size());
  double sink = 0;
  for (auto _ : state) {
    // 65536-sample chunks, output consumed and dropped: bounded memory.
    for (std::size_t at = 0; at < x.size(); at += 65536) {
      filter.push(std::span(x).subspan(at, std::min<std::size_t>(65536, x.size() - at)), out);
      if (!out.empty()) sink += out.back();
      out.clear();
    }
    filter.finish(out);
    out.clear();
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations() * x.size());
  state.counters["fft_block"] = static_cast<double>(filter.fft_size());
}
BENCHMARK(BM_OverlapSaveStreaming)->Unit(benchmark::kMillisecond);

void BM_WelchPsd(benchmark::State& state) {
  const Fixture& f = fixture();
  const auto& x = f.rec.channels[0].recorded;
  for (auto _ : state) benchmark::DoNotOptimize(welch_psd(x, f.rig.sample_rate_hz, {8192, 4096, {WindowType::hann, 0}}));
  state.SetItemsProcessed(state.iterations() * x.size());
}
BENCHMARK(BM_WelchPsd)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
