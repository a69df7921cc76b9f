// The whole analyze chain (acquire + analyze_recording) on a long recording:
// by default the one-hour, 3-channel (two accelerometers + crank pulse),
// 25.6 kHz float WAV of bench_acquire (same generator and settings, so the
// same file is shared). Frames per second, peak resident memory, and the
// drift check: ω3 and α3 of single revolutions against the virtual rig's
// nominal truth at the start and at the end of the record.
//
//   build/bench/bench_analyze_pipeline [SECONDS=3600] [FILE=/tmp/fourbar_bench_<SECONDS>s.wav] [--thesis]
//                                      [--threads N]
//
// Generation and analysis each run in a child process, so the peak resident
// memory reported (getrusage of the child) is the analysis's alone.
// --threads N: each analysis runs twice, back to back, with 1 and with N
// threads (AnalyzeOptions::threads): the wall-time ratio measured in one run
// (so under the same machine load), and a digest of every number of the two
// results (averages, spreads, spectra, every revolution's grids) that must
// be equal bit for bit.

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "analyze/pipeline.hpp"
#include "long_recording.hpp"

namespace {

using namespace fourbar;
using bench::ChildResult;
using bench::in_child;

/// FNV-1a over the bytes of doubles: equal digests, equal numbers (bit for bit).
struct Digest {
  std::uint64_t h = 1469598103934665603ull;
  void add(double v) {
    unsigned char b[sizeof v];
    std::memcpy(b, &v, sizeof v);
    for (unsigned char c : b) h = (h ^ c) * 1099511628211ull;
  }
  void add(std::span<const double> v) {
    for (double x : v) add(x);
  }
};

/// The 1, 5 and 15 minute load averages (/proc/loadavg), for the ratio line.
std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

/// Every number of the result that the threads could change.
void add_result(Digest& d, const RecordingAnalysis& r) {
  d.add(double(r.revolutions)), d.add(double(r.spectra.segments));
  d.add(r.crank_speed_rad_s.mean), d.add(r.crank_speed_rad_s.std);
  for (const auto* l : {&r.coupler, &r.rocker}) {
    if (!*l) continue;
    const LinkResult& x = **l;
    for (const AngleAverage* a : {&x.alpha_rad_s2, &x.omega_rad_s}) d.add(a->mean), d.add(a->std);
    d.add(x.alpha_amplitude);
  }
}

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
    digest_.add(double(r.number)), digest_.add(r.averaged ? 1.0 : 0.0);
    for (const auto& v : {r.crank_speed_rad_s, r.alpha3_rad_s2, r.omega3_rad_s, r.alpha4_rad_s2, r.omega4_rad_s})
      digest_.add(v);
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
  Digest digest_;

 private:
  CrankDrive drive_;
  NominalMotionSource motion_;
  std::size_t window_, total_, n_ = 0;
  long offset_turns_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  bool thesis = false;
  unsigned threads = 1;
  std::size_t chunk_revolutions = 0;  // 0: the planned default
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--thesis") == 0) thesis = true;
    else if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) threads = static_cast<unsigned>(std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--chunk-revolutions") == 0 && i + 1 < argc)
      chunk_revolutions = static_cast<std::size_t>(std::atol(argv[++i]));
    else args.emplace_back(argv[i]);
  }
  const double seconds = !args.empty() ? std::atof(args[0].c_str()) : 3600.0;
  const std::filesystem::path file = bench::long_recording_path(seconds, args.size() > 1 ? args[1].c_str() : nullptr);
  if (!bench::ensure_long_recording(file, seconds, "bench_analyze_pipeline")) return 1;
  const bench::LongRecording setup(file, seconds);
  const auto frames = static_cast<double>(std::llround(seconds * 25600));
  std::printf("file: %s, %.0f MB, %.0f frames\n", file.c_str(), double(std::filesystem::file_size(file)) / 1e6, frames);
  const std::size_t total_revs = static_cast<std::size_t>(seconds * 350 / 60);
  const std::string load_before = load_average();
  for (int method = 0; method < (thesis ? 2 : 1); ++method) {
    double wall_one = 0, cpu_one = 0;
    std::uint64_t digest_one = 0;
    for (const unsigned t : threads > 1 ? std::vector<unsigned>{1, threads} : std::vector<unsigned>{1}) {
      int digest_pipe[2];
      if (pipe(digest_pipe) != 0) return 1;
      const ChildResult a = in_child([&] {
        AnalyzeOptions o = method == 0 ? AnalyzeOptions{} : AnalyzeOptions::thesis_method();
        o.progress = false;
        o.filter.mains_hz = 50;
        o.threads = t;
        o.chunk_revolutions = chunk_revolutions;
        DriftCheck drift(setup, 500, total_revs);
        const auto t0 = std::chrono::steady_clock::now();
        const RecordingAnalysis r = analyze_recording(file, {}, o, &drift);
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("  %s, %u thread%s: %zu revolutions averaged (N = %zu, %zu per chunk, kernel %zu taps), acquire "
                    "passes %.1f + %.1f + %.1f s (the last includes the analysis)\n",
                    method == 0 ? "this chain" : "thesis method", t, t == 1 ? "" : "s", r.revolutions,
                    r.grid_points_per_rev, r.chunk_revolutions, r.kernel_taps, r.acquisition.pass_seconds[0],
                    r.acquisition.pass_seconds[1], r.acquisition.pass_seconds[2]);
        std::printf("    alpha3 RMS %.3f rad/s^2, omega3 RMS %.4f rad/s; spread (std RMS) alpha3 %.3f, omega3 %.5f\n",
                    r.coupler->alpha_rms_rad_s2, r.coupler->omega_rms_rad_s, r.coupler->alpha_std_rms_rad_s2,
                    r.coupler->omega_std_rms_rad_s);
        std::printf("    single revolutions vs truth, RMS error / RMS: first 500 revolutions omega3 %.4f %%, alpha3 %.4f "
                    "%%; last 500: omega3 %.4f %%, alpha3 %.4f %% (%zu, %zu revolutions)\n",
                    100 * drift.early_.omega / double(drift.early_.count),
                    100 * drift.early_.alpha / double(drift.early_.count),
                    100 * drift.late_.omega / double(drift.late_.count), 100 * drift.late_.alpha / double(drift.late_.count),
                    drift.early_.count, drift.late_.count);
        rusage self{};
        getrusage(RUSAGE_THREAD, &self);
        std::printf("    analyze_recording %.1f s wall, %.2f M frames/s; calling thread CPU %.1f s\n", wall, frames / wall / 1e6,
                    double(self.ru_utime.tv_sec + self.ru_stime.tv_sec) + 1e-6 * double(self.ru_utime.tv_usec + self.ru_stime.tv_usec));
        std::fflush(stdout);
        add_result(drift.digest_, r);
        return write(digest_pipe[1], &drift.digest_.h, sizeof drift.digest_.h) == sizeof drift.digest_.h ? 0 : 1;
      });
      std::uint64_t digest = 0;
      const bool got = a.status == 0 && read(digest_pipe[0], &digest, sizeof digest) == sizeof digest;
      close(digest_pipe[0]), close(digest_pipe[1]);
      if (!got) return 1;
      std::printf("  child: %.1f s wall, %.1f s CPU, %.2f M frames/s (wall), peak resident %.0f MB; result digest %016llx\n",
                  a.wall_s, a.cpu_s, frames / a.wall_s / 1e6, a.peak_mb, static_cast<unsigned long long>(digest));
      std::printf("  child CPU: user %.2f s, system %.2f s, %ld minor page faults, %ld involuntary switches\n", a.user_s,
                  a.system_s, a.minor_faults, a.involuntary_switches);
      if (t == 1) {
        wall_one = a.wall_s, cpu_one = a.cpu_s, digest_one = digest;
      } else {
        std::printf("  %u threads / 1 thread: wall %.1f / %.1f s = %.2f; results %s\n", t, a.wall_s, wall_one,
                    a.wall_s / wall_one, digest == digest_one ? "identical (bit for bit)" : "DIFFER");
        // The line to quote (wall-clock ratio: meaningful only with the load beside it).
        std::printf("RATIO %.0f s analysis, %u threads / 1: %.2f (target <= 0.6); CPU %.2f / %.2f s; load average %s -> "
                    "%s on %ld cores\n",
                    seconds, t, a.wall_s / wall_one, a.cpu_s, cpu_one, load_before.c_str(), load_average().c_str(),
                    sysconf(_SC_NPROCESSORS_ONLN));
        if (digest != digest_one) return 1;
      }
    }
  }
  return 0;
}
