// The whole analyze chain (acquire + analyze_recording) on a long recording:
// by default the one-hour, 3-channel (two accelerometers + crank pulse),
// 25.6 kHz float WAV of bench_acquire (same generator and settings, so the
// same file is shared). Frames per second, peak resident memory, and the
// drift check: ω3 and α3 of single revolutions against the virtual rig's
// nominal truth at the start and at the end of the record.
//
//   build/bench/bench_analyze_pipeline [SECONDS=3600] [FILE=/tmp/fourbar_bench_<SECONDS>s.wav] [--thesis]
//
// Generation and analysis each run in a child process, so the peak resident
// memory reported (getrusage of the child) is the analysis's alone.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "analyze/pipeline.hpp"
#include "long_recording.hpp"

namespace {

using namespace fourbar;
using bench::ChildResult;
using bench::in_child;

/// Per-revolution errors against the nominal truth, for the revolutions in
/// the first and the last `window` of the record.
class DriftCheck final : public RevolutionObserver {
 public:
  DriftCheck(const bench::LongRecording& s, std::size_t window, std::size_t total)
      : drive_(s.drive()), motion_(s.scene.rig, drive_), window_(window), total_(total) {}
  void on_start(const RecordingAnalysis& a) override {
    n_ = a.grid_points_per_rev;
    // Revolution 0 starts at acquire's first pulse: how many turns after the start.
    const double t = a.acquisition.pulses.segments.front().front().time_s;
    offset_turns_ = std::lround((drive_.at(t).angle_rad - drive_.start_angle_rad) / units::kTwoPi);
  }
  void on_revolution(const AnalyzedRevolution& r) override {
    ++seen_;
    const bool early = r.number < window_, late = r.number + window_ + 2 >= total_;
    if (!early && !late) return;
    double e_w = 0, t_w = 0, e_a = 0, t_a = 0;
    for (std::size_t k = 0; k < n_; ++k) {
      const double turned = units::kTwoPi * (double(r.number + offset_turns_) + double(k) / double(n_));
      const LinkState s = motion_.at(drive_.time_at_turned(turned));
      e_w += std::pow(r.omega3_rad_s[k] - s.omega3_rad_s, 2), t_w += s.omega3_rad_s * s.omega3_rad_s;
      e_a += std::pow(r.alpha3_rad_s2[k] - s.alpha3_rad_s2, 2), t_a += s.alpha3_rad_s2 * s.alpha3_rad_s2;
    }
    auto& acc = early ? early_ : late_;
    acc.omega += std::sqrt(e_w / t_w), acc.alpha += std::sqrt(e_a / t_a);
    ++acc.count;
  }
  struct Acc {
    double omega = 0, alpha = 0;
    std::size_t count = 0;
  } early_, late_;
  std::size_t seen_ = 0;

 private:
  CrankDrive drive_;
  NominalMotionSource motion_;
  std::size_t window_, total_, n_ = 0;
  long offset_turns_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  bool thesis = false;
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--thesis") == 0) thesis = true;
    else args.emplace_back(argv[i]);
  }
  const double seconds = !args.empty() ? std::atof(args[0].c_str()) : 3600.0;
  const std::filesystem::path file = bench::long_recording_path(seconds, args.size() > 1 ? args[1].c_str() : nullptr);
  if (!bench::ensure_long_recording(file, seconds, "bench_analyze_pipeline")) return 1;
  const bench::LongRecording setup(file, seconds);
  const auto frames = static_cast<double>(std::llround(seconds * 25600));
  std::printf("file: %s, %.0f MB, %.0f frames\n", file.c_str(), double(std::filesystem::file_size(file)) / 1e6, frames);
  const std::size_t total_revs = static_cast<std::size_t>(seconds * 350 / 60);
  for (int method = 0; method < (thesis ? 2 : 1); ++method) {
    const ChildResult a = in_child([&] {
      AnalyzeOptions o = method == 0 ? AnalyzeOptions{} : AnalyzeOptions::thesis_method();
      o.progress = false;
      o.filter.mains_hz = 50;
      DriftCheck drift(setup, 500, total_revs);
      const auto t0 = std::chrono::steady_clock::now();
      const RecordingAnalysis r = analyze_recording(file, {}, o, &drift);
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("  %s: %zu revolutions averaged (N = %zu, %zu per chunk, kernel %zu taps), acquire passes %.1f + %.1f + "
                  "%.1f s (the last includes the analysis)\n",
                  method == 0 ? "this chain" : "thesis method", r.revolutions, r.grid_points_per_rev, r.chunk_revolutions,
                  r.kernel_taps, r.acquisition.pass_seconds[0], r.acquisition.pass_seconds[1],
                  r.acquisition.pass_seconds[2]);
      std::printf("    alpha3 RMS %.3f rad/s^2, omega3 RMS %.4f rad/s; spread (std RMS) alpha3 %.3f, omega3 %.5f\n",
                  r.coupler->alpha_rms_rad_s2, r.coupler->omega_rms_rad_s, r.coupler->alpha_std_rms_rad_s2,
                  r.coupler->omega_std_rms_rad_s);
      std::printf("    single revolutions vs truth, RMS error / RMS: first 500 revolutions omega3 %.4f %%, alpha3 %.4f %%; "
                  "last 500: omega3 %.4f %%, alpha3 %.4f %% (%zu, %zu revolutions)\n",
                  100 * drift.early_.omega / double(drift.early_.count), 100 * drift.early_.alpha / double(drift.early_.count),
                  100 * drift.late_.omega / double(drift.late_.count), 100 * drift.late_.alpha / double(drift.late_.count),
                  drift.early_.count, drift.late_.count);
      std::printf("    analyze_recording %.1f s wall, %.2f M frames/s\n", wall, frames / wall / 1e6);
      std::fflush(stdout);
      return 0;
    });
    if (a.status != 0) return 1;
    std::printf("  child: %.1f s wall, %.1f s CPU, %.2f M frames/s (wall), peak resident %.0f MB\n", a.wall_s, a.cpu_s,
                frames / a.wall_s / 1e6, a.peak_mb);
  }
  return 0;
}
