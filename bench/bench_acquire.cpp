// acquire on a long recording: read + pulses + crank angle + revolutions for
// a one-hour, 3-channel (two accelerometers + crank pulse), 25.6 kHz float
// WAV (issue target: under 10 s and under 200 MB peak on this machine).
//
//   build/bench/bench_acquire [SECONDS=3600] [FILE=/tmp/fourbar_bench_<SECONDS>s.wav]
//
// The recording is written once by the virtual rig (350 rpm, ±2 % speed
// fluctuation, 50 dB SNR, hum) and kept for later runs. Generation and
// acquisition each run in a child process, so the peak resident memory
// reported (getrusage of the child) is that of acquire alone; the second
// acquisition reads from the page cache, as a lab PC would after copying.

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>

#include "acquire/acquisition.hpp"
#include "common/units.hpp"
#include "sim/virtual_rig/virtual_rig.hpp"

namespace {

using namespace fourbar;

struct ChildResult {
  int status = -1;
  double wall_s = 0;
  double peak_mb = 0;
};

/// Runs `work` in a child process; its wall time and peak resident memory.
ChildResult in_child(const std::function<int()>& work) {
  std::fflush(stdout);  // or the child would print the parent's buffer again
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) std::_Exit(work());
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  ChildResult r;
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
  return r;
}

int generate(const std::filesystem::path& file, double seconds) {
  Scene scene;
  scene.rig = std::make_shared<const Rig>(load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml"));
  scene.source = file.parent_path() / "fourbar_bench_scene.toml";
  scene.crank_speed_rad_s = units::rpm_to_rad_s(350);
  RecordingSpec spec;
  spec.sample_rate_hz = 25600;
  spec.duration_s = seconds;
  spec.sample_format = "float";
  spec.noise_snr_db = 50;
  spec.hum_V = 0.002;
  spec.speed_fluctuation = 0.02;
  spec.speed_fluctuation_period_s = 3.0;
  spec.pulse.width_rad = units::deg_to_rad(10);
  spec.pulse.rise_s = 150e-6;
  spec.pulse.jitter_s = 2e-6;
  for (auto [name, role, pos] : {std::tuple{"coupler_t", ChannelRole::coupler_tangential, 0.309},
                                 std::tuple{"rocker_t", ChannelRole::rocker_tangential, 0.312}}) {
    ChannelSpec c;
    c.name = name, c.role = role, c.position_m = pos, c.volts_per_m_s2 = 0.01;
    c.index = static_cast<int>(spec.sensors.size());
    spec.sensors.push_back(c);
  }
  const CrankDrive drive = crank_drive(scene, spec);
  const NominalMotionSource motion(scene.rig, drive);
  make_virtual_recording(scene, spec, drive, motion, file, Provenance{"bench_acquire", {}}, {false, true});
  return 0;
}

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
  if (argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::printf("usage: bench_acquire [SECONDS [FILE]]\n"
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
  const std::filesystem::path file =
      argc > 2 ? std::filesystem::path(argv[2])
               : std::filesystem::temp_directory_path() / ("fourbar_bench_" + std::to_string(static_cast<long>(seconds)) + "s.wav");
  if (!std::filesystem::exists(file)) {
    std::printf("writing %s (%.0f s, 3 channels, 25.6 kHz float) ...\n", file.c_str(), seconds);
    const ChildResult g = in_child([&] { return generate(file, seconds); });
    if (g.status != 0) return 1;
    std::printf("  virtual rig: %.1f s, peak %.0f MB\n", g.wall_s, g.peak_mb);
  }
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
                  run, sink.revolutions, rep.samples_per_revolution, sink.samples, rep.pulses.removed_s.size(),
                  rep.pulses.inserted_s.size(), rep.speed.mean_rpm, sink.checksum);
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
