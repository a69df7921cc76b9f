#pragma once
// The long recording of the acquire and analyze benches, and how they run a
// job in a child process to measure it alone. One definition, so that both
// benches make (and share) the same file:
// the thesis rig at 350 rpm (±2 % speed fluctuation over 3 s), two
// accelerometers (coupler and rocker tangential, DC-coupled, at the
// coupler–rocker joint) + the crank pulse, 25.6 kHz float WAV, 50 dB SNR,
// 2 mV of 50 Hz hum.

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <string>
#include <tuple>

#include "common/units.hpp"
#include "virtual_rig/virtual_rig.hpp"

namespace fourbar::bench {

struct ChildResult {
  int status = -1;
  double wall_s = 0, cpu_s = 0, peak_mb = 0;
  double user_s = 0, system_s = 0;  ///< cpu_s split: user and kernel (page faults, I/O)
  long minor_faults = 0;            ///< pages first touched (fresh memory)
  long involuntary_switches = 0;    ///< times the scheduler took a CPU away (machine load)
};

/// Runs `work` in a child process: its exit status, wall and CPU time, and
/// peak resident memory (getrusage of the child alone).
inline ChildResult in_child(const std::function<int()>& work) {
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
  r.user_s = double(usage.ru_utime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec);
  r.system_s = double(usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_stime.tv_usec);
  r.cpu_s = r.user_s + r.system_s;
  r.minor_faults = usage.ru_minflt;
  r.involuntary_switches = usage.ru_nivcsw;
  r.peak_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
  return r;
}

/// The scene and [recording] of the bench recording.
struct LongRecording {
  Scene scene;
  RecordingSpec spec;
  /// `wheel`: a 60-2 tooth wheel in place of the once-per-turn pulse.
  LongRecording(const std::filesystem::path& file, double seconds, bool wheel = false) {
    scene.rig = std::make_shared<const Rig>(load_rig(FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml"));
    scene.source = file.parent_path() / "fourbar_bench_scene.toml";
    scene.crank_speed_rad_s = units::rpm_to_rad_s(350);
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
    if (wheel) spec.wheel.teeth = 60, spec.wheel.missing_teeth = 2;
    for (auto [name, role, pos] : {std::tuple{"coupler_t", ChannelRole::coupler_tangential, 0.309},
                                   std::tuple{"rocker_t", ChannelRole::rocker_tangential, 0.312}}) {
      ChannelSpec c;
      c.name = name, c.role = role, c.position_m = pos, c.volts_per_m_s2 = 0.01;
      c.index = static_cast<int>(spec.sensors.size());
      spec.sensors.push_back(c);
    }
  }
  CrankDrive drive() const { return crank_drive(scene, spec); }
};

/// `FILE` argument or /tmp/fourbar_bench_<SECONDS>s.wav (…_wheel_… with the wheel).
inline std::filesystem::path long_recording_path(double seconds, const char* given, bool wheel = false) {
  return given ? std::filesystem::path(given)
               : std::filesystem::temp_directory_path() /
                     (std::string(wheel ? "fourbar_bench_wheel_" : "fourbar_bench_") +
                      std::to_string(static_cast<long>(seconds)) + "s.wav");
}

/// Writes the recording (in a child process) unless it exists; false on failure.
inline bool ensure_long_recording(const std::filesystem::path& file, double seconds, const char* tool,
                                  bool wheel = false) {
  if (std::filesystem::exists(file)) {
    // Reuse it only if its manifest names this checkout's rig: a file left by
    // another checkout (or a removed one) would be read against the wrong rig.
    std::ifstream manifest(std::filesystem::path(file).replace_extension(".toml"));
    const std::string text{std::istreambuf_iterator<char>(manifest), std::istreambuf_iterator<char>()};
    if (text.find(FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml") != std::string::npos) return true;
    std::printf("%s was written by another checkout: writing it again\n", file.c_str());
  }
  std::printf("writing %s (%.0f s, 3 channels, 25.6 kHz float) ...\n", file.c_str(), seconds);
  const ChildResult g = in_child([&] {
    const LongRecording r(file, seconds, wheel);
    const CrankDrive drive = r.drive();
    const NominalMotionSource motion(r.scene.rig, drive);
    make_virtual_recording(r.scene, r.spec, drive, motion, file, Provenance{tool, {}}, {false, true});
    return 0;
  });
  if (g.status != 0) return false;
  std::printf("  virtual rig: %.1f s, peak %.0f MB\n", g.wall_s, g.peak_mb);
  return true;
}

}  // namespace fourbar::bench
