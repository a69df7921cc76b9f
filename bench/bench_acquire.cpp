// acquire on a long recording: read + pulses + crank angle + revolutions for
// a one-hour, 3-channel (two accelerometers + crank pulse), 25.6 kHz float
// WAV (issue target: under 10 s and under 200 MB peak on this machine).
//
//   build/bench/bench_acquire [--wheel] [SECONDS=3600] [FILE=/tmp/fourbar_bench_<SECONDS>s.wav]
//
// --wheel: the crank angle from a 60-2 tooth wheel (58 edges per turn, the
// spline through all of them) in place of the once-per-turn pulse.
//
// The recording is written once by the virtual rig (350 rpm, ±2 % speed
// fluctuation, 50 dB SNR, hum) and kept for later runs. Generation and
// acquisition each run in a child process, so the peak resident memory
// reported (getrusage of the child) is that of acquire alone; the second
// acquisition reads from the page cache, as a lab PC would after copying.

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "acquire/acquisition.hpp"
#include "long_recording.hpp"

namespace {

using namespace fourbar;
using bench::ChildResult;
using bench::in_child;

/// Counts what acquire delivers, keeping nothing.
struct CountingSink : AcquisitionSink {
  std::size_t samples = 0, revolutions = 0;
  double checksum = 0;
  void on_samples(const SampleBlock& b) override { samples += b.size(); }
  void on_revolution(const Revolution& r) override {
    ++revolutions;
    checksum += r.channels_m_s2[0][r.channels_m_s2[0].size() / 2];
  }
};

}  // namespace

int main(int argc, char** argv) {
  const bool wheel = argc > 1 && std::string(argv[1]) == "--wheel";
  if (wheel) --argc, ++argv;
  if (argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::printf("usage: bench_acquire [--wheel] [SECONDS [FILE]]\n"
                "  writes a SECONDS-long 3-channel 25.6 kHz float recording with the virtual rig\n"
                "  (default 3600 s, kept in the temp folder), then times read + pulses + angle +\n"
                "  revolutions and reports frames per second and peak memory\n");
    return 0;
  }
  const double seconds = argc > 1 ? std::atof(argv[1]) : 3600.0;
  if (!(seconds >= 1.0)) {
    std::fprintf(stderr, "bench_acquire: SECONDS must be a number >= 1, not '%s'\n", argv[1]);
    return 2;
  }
  const std::filesystem::path file = bench::long_recording_path(seconds, argc > 2 ? argv[2] : nullptr, wheel);
  if (!bench::ensure_long_recording(file, seconds, "bench_acquire", wheel)) return 1;
  std::printf("file: %s, %.0f MB\n", file.c_str(), static_cast<double>(std::filesystem::file_size(file)) / 1e6);
  for (int run = 1; run <= 2; ++run) {
    std::uint64_t frames = 0;
    const ChildResult a = in_child([&] {
      OpenedRecording o = open_with_manifest(file, {});
      CountingSink sink;
      AcquireOptions options;
      options.progress = false;
      const AcquisitionReport rep = acquire(*o.reader, o.manifest, options, sink);
      std::printf("  run %d: %zu revolutions of %d crank angles, %zu tagged samples, %zu pulses removed, %zu inserted, "
                  "%.3f rpm mean (checksum %.6g)\n",
                  run, sink.revolutions, rep.grid_points_per_rev, sink.samples, rep.pulses.removed_s.size(),
                  rep.pulses.inserted_s.size(), rep.speed.mean_rpm, sink.checksum);
      if (rep.wheel.positions_per_rev > 0)
        std::printf("  run %d: %s, %zu edges\n", run, rep.wheel.source.c_str(), rep.wheel.edges);
      std::printf("  run %d: passes scan %.2f s, pulses %.2f s, samples+revolutions %.2f s\n", run,
                  rep.pass_seconds[0], rep.pass_seconds[1], rep.pass_seconds[2]);
      std::fflush(stdout);
      return sink.revolutions == rep.revolutions ? 0 : 1;
    });
    frames = static_cast<std::uint64_t>(seconds * 25600);
    if (a.status != 0) return 1;
    std::printf("  run %d: acquire %.2f s wall, %.1f M frames/s, peak resident %.0f MB\n", run, a.wall_s,
                static_cast<double>(frames) / a.wall_s / 1e6, a.peak_mb);
  }
  return 0;
}
