// The C++ side of the numpy/scipy comparison (bench/compare_analyze_scipy.py,
// run both with bench/run_analyze_vs_scipy.sh): writes the synthetic 3-channel
// 25.6 kHz record of bench_analyze to DIR/record.f64 (+ record.json), runs the
// analyze chain on it (best of 3 runs, generation and I/O excluded) and writes
// the per-revolution grids to DIR/cpp_result.f64 and the time to
// DIR/cpp_result.json.
//   bench_analyze_export DIR [SECONDS]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "analyze/link_analysis.hpp"
#include "synthetic_recording.hpp"  // tests/analyze

using namespace fourbar;

namespace {

void write_f64(std::ofstream& out, const std::vector<double>& v) {
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(double)));
}

nlohmann::json mount_json(const AccelerometerMount& m, const Rig& rig) {
  const ResolvedMount r = resolve_mount(rig, m);
  return {{"channel", m.channel},
          {"link", to_string(m.link)},
          {"axis", to_string(m.axis)},
          {"r_m", r.r_m},
          {"h_m", r.h_m},
          {"sign", r.sign},
          {"high_pass_corner_hz", r.high_pass_corner_hz}};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_analyze_export DIR [SECONDS]\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  testing::SyntheticRig s;
  s.duration_s = argc > 2 ? std::atof(argv[2]) : 60.0;
  const testing::HousingMounts mounts = testing::housing_mounts();
  const AccelerometerMount &ct = mounts.coupler_t, &rt = mounts.rocker_t, &cn = mounts.coupler_n;
  const testing::SyntheticRecording rec = testing::make_recording(s, {ct, rt, cn});
  const AngleGridSpec grid;
  ChannelOptions band;
  band.filter = testing::band_pass_with_mains_comb();
  ChannelOptions low = band;
  low.filter.band = BandType::lowpass;

  {
    std::ofstream out(dir / "record.f64", std::ios::binary);
    for (const auto* v : {&rec.angle, &rec.speed, &rec.accel, &rec.channels[0].recorded, &rec.channels[1].recorded,
                          &rec.channels[2].recorded})
      write_f64(out, *v);
    const Rig& g = s.rig;
    nlohmann::json j = {
        {"frames", rec.angle.size()},
        {"sample_rate_hz", s.sample_rate_hz},
        {"columns", {"crank_angle_rad", "crank_speed_rad_s", "crank_accel_rad_s2", "coupler_t", "rocker_t", "coupler_n"}},
        {"rig",
         {{"l1", g.ground_length_m}, {"l2", g.crank.length_m}, {"l3", g.coupler.length_m}, {"l4", g.rocker.length_m},
          {"g", g.gravity_m_s2}, {"branch", g.assembly_sign()}}},
        {"mounts", {mount_json(ct, g), mount_json(rt, g), mount_json(cn, g)}},
        {"filter", {{"low_hz", 2.9}, {"high_hz", 300}, {"mains_hz", 60}, {"mains_width_hz", 1.0}, {"kaiser_beta", 8.0},
                    {"transition_hz", 0.8}}},
        {"points_per_rev", grid.grid_points_per_rev},
        {"grid_start_rad", grid.start_rad}};
    std::ofstream(dir / "record.json") << j.dump(2) << '\n';
  }

  const CrankTrack crank = rec.crank();
  double best = 1e300, first = 0;
  LinkAnalysis c, r;
  NormalChannelAnalysis n;
  for (int run = 0; run < 3; ++run) {
    const auto t0 = std::chrono::steady_clock::now();
    RecordAnalyzer analyzer(s.rig, crank, s.sample_rate_hz, grid);
    c = analyzer.tangential(ct, rec.channels[0].recorded, band);
    r = analyzer.tangential(rt, rec.channels[1].recorded, band);
    n = analyzer.normal(cn, rec.channels[2].recorded, c.alpha_rad_s2, low);
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (run == 0) first = took;  // FFTW planning and the nominal-motion tables included
    best = std::min(best, took);
  }
  std::ofstream out(dir / "cpp_result.f64", std::ios::binary);
  for (const auto* v : {&c.alpha_grid, &c.omega_grid, &r.alpha_grid, &r.omega_grid, &n.omega_sq_grid}) write_f64(out, *v);
  nlohmann::json j = {{"seconds", best},
                      {"first_run_seconds", first},
                      {"frames", rec.angle.size()},
                      {"revolutions", c.revolutions},
                      {"first_revolution", c.first_revolution},
                      {"arrays", {"coupler_alpha", "coupler_omega", "rocker_alpha", "rocker_omega", "coupler_omega_sq"}}};
  std::ofstream(dir / "cpp_result.json") << j.dump(2) << '\n';
  std::printf("C++ chain: %zu frames x 3 channels in %.3f s (%.3g frames/s; best of 3, the first run %.3f s)\n",
              rec.angle.size(), best, rec.angle.size() / best, first);
  return 0;
}
