// Disk and partial-output safety (issue 7): a `fourbar sim` run interrupted
// by SIGINT or SIGTERM while it simulates or while it writes leaves no file
// under a final name (nor its temporary file), and keeps the output of an
// earlier run intact; a write that fails (file-size limit standing in for a
// full disk, a read-only folder) ends with one `fourbar: ` line, exit
// status 1 and no output file.

#include <gtest/gtest.h>
#include <signal.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "support/run_command.hpp"

extern char** environ;

namespace fourbar {
namespace {

namespace fs = std::filesystem;
using testing::count_lines;
using testing::read_file;
using testing::TempDir;

std::string rig_line() { return "rig = \"" FOURBAR_SOURCE_DIR "/data/rigs/thesis.toml\"\n"; }

/// A nominal scene whose series.csv takes a while to write (2 M rows).
std::string big_nominal_scene() {
  return rig_line() + "crank_speed_rpm = 350\nrevolutions = 4\nsamples_per_revolution = 500000\n"
                      "outputs = [\"time_s\", \"theta3_rad\", \"omega3_rad_s\"]\n";
}

/// A clearance scene that simulates for many seconds before writing anything.
std::string long_clearance_scene() {
  return rig_line() + "model = \"clearance\"\ncrank_speed_rpm = 350\nrevolutions = 100000\n"
                      "samples_per_revolution = 36\noutputs = [\"alpha3_rad_s2\"]\n[clearance]\nrestitution = 0.5\n";
}

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> out;
  if (fs::exists(dir))
    for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename());
  return out;
}

bool has_temporary(const fs::path& dir) {
  for (const auto& f : files_in(dir))
    if (f.string().find(".tmp-") != std::string::npos && fs::file_size(dir / f) > 0) return true;
  return false;
}

/// Starts `fourbar sim SCENE --out DIR` (output discarded) and returns its pid.
pid_t spawn_sim(const fs::path& scene, const fs::path& out) {
  const std::string exe = FOURBAR_EXE, sim = "sim", opt = "--out", s = scene.string(), o = out.string();
  std::vector<char*> argv{const_cast<char*>(exe.c_str()), const_cast<char*>(sim.c_str()), const_cast<char*>(s.c_str()),
                          const_cast<char*>(opt.c_str()), const_cast<char*>(o.c_str()), nullptr};
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, exe.c_str(), &fa, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&fa);
  return pid;
}

/// Waits (bounded) until `ready()` holds while the child still runs.
template <class F>
bool wait_for(pid_t pid, F ready, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (ready()) return true;
    int status;
    if (waitpid(pid, &status, WNOHANG) == pid) return false;  // ended on its own
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return false;
}

int wait_signal(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFSIGNALED(status) ? WTERMSIG(status) : -1;
}

TEST(OutputSafety, InterruptedWhileWritingLeavesNoFileAndKeepsTheOldOutput) {
  for (int sig : {SIGTERM, SIGINT}) {
    SCOPED_TRACE(sig == SIGTERM ? "SIGTERM" : "SIGINT");
    TempDir dir;
    const fs::path out = dir.path() / "out";
    // A complete earlier run in the same folder.
    const auto small = dir.write("small.toml", rig_line() + "crank_speed_rpm = 350\noutputs = [\"time_s\"]\n");
    const auto first = testing::run_fourbar("sim " + small.string() + " --out " + out.string());
    ASSERT_EQ(first.status, 0) << first.err;
    const std::string old_series = read_file(out / "series.csv"), old_summary = read_file(out / "summary.json");

    const pid_t pid = spawn_sim(dir.write("big.toml", big_nominal_scene()), out);
    ASSERT_TRUE(wait_for(pid, [&] { return has_temporary(out); }, 60)) << "never saw the temporary file";
    ASSERT_EQ(kill(pid, sig), 0);
    EXPECT_EQ(wait_signal(pid), sig);  // ended by the signal, midway
    EXPECT_EQ(read_file(out / "series.csv"), old_series);
    EXPECT_EQ(read_file(out / "summary.json"), old_summary);
    for (const auto& f : files_in(out)) EXPECT_EQ(f.string().find(".tmp-"), std::string::npos) << f;
    EXPECT_EQ(files_in(out).size(), 2u);
  }
}

TEST(OutputSafety, InterruptedWhileSimulatingWritesNothing) {
  TempDir dir;
  const fs::path out = dir.path() / "out";
  const pid_t pid = spawn_sim(dir.write("long.toml", long_clearance_scene()), out);
  // The output folder is made before the run starts; then the simulation runs.
  ASSERT_TRUE(wait_for(pid, [&] { return fs::exists(out); }, 60));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_EQ(kill(pid, SIGINT), 0);
  EXPECT_EQ(wait_signal(pid), SIGINT);
  EXPECT_TRUE(files_in(out).empty());
}

TEST(OutputSafety, FullDiskFailsWithOneLineAndNoFile) {
  // A 64 KiB file-size limit (SIGXFSZ ignored, so write() fails with EFBIG)
  // stands in for a full disk.
  TempDir dir;
  const fs::path out = dir.path() / "out";
  const auto scene = dir.write("s.toml", rig_line() + "crank_speed_rpm = 350\nsamples_per_revolution = 20000\n"
                                                      "outputs = [\"time_s\", \"theta3_rad\"]\n");
  const fs::path err = dir.path() / "stderr";
  const std::string cmd = "bash -c 'trap \"\" XFSZ; ulimit -f 64; exec " FOURBAR_EXE " sim " + scene.string() +
                          " --out " + out.string() + "' >/dev/null 2>" + err.string();
  const int raw = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 1);
  const std::string message = read_file(err);
  EXPECT_EQ(message.rfind("fourbar: " + (out / "series.csv").string() + ": write failed", 0), 0u) << message;
  EXPECT_EQ(count_lines(message), 1) << message;
  EXPECT_TRUE(files_in(out).empty());
}

TEST(OutputSafety, ReadOnlyFolderFailsWithOneLine) {
  // As root a mode-0555 folder is still writable: use a read-only mount then.
  TempDir dir;
  fs::path folder = dir.path() / "readonly";
  fs::create_directories(folder);
  fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec);
  // Root writes there anyway: then /proc, where no one can create a file.
  auto writable = [](const fs::path& d) {
    const fs::path probe = d / "fourbar-probe";
    const bool ok = static_cast<bool>(std::ofstream(probe));
    std::error_code ec;
    fs::remove(probe, ec);
    return ok;
  };
  if (writable(folder)) folder = "/proc";
  if (writable(folder) || !fs::is_directory(folder)) GTEST_SKIP() << "no read-only folder on this machine";
  const auto scene = dir.write("s.toml", rig_line() + "crank_speed_rpm = 350\noutputs = [\"time_s\"]\n");
  const auto r = testing::run_fourbar("sim " + scene.string() + " --out " + folder.string());
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.err.rfind("fourbar: " + (folder / "series.csv").string() + ": cannot create", 0), 0u) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_FALSE(fs::exists(folder / "series.csv"));
  fs::permissions(dir.path() / "readonly", fs::perms::owner_all);
}

}  // namespace
}  // namespace fourbar
