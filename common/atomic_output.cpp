#include "common/atomic_output.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>
#include <system_error>

#include "common/error.hpp"

namespace fourbar {

namespace {

// Temporary files to remove on SIGINT/SIGTERM/SIGHUP. Fixed storage, so the
// handler only reads plain memory and calls unlink (async-signal-safe).
constexpr int kSlots = 64;
enum SlotState : int { kFree = 0, kClaimed = 1, kLive = 2 };
std::array<std::atomic<int>, kSlots> g_state{};
std::array<std::array<char, 4096>, kSlots> g_paths{};
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

extern "C" void remove_temporaries_and_die(int sig) {
  for (int i = 0; i < kSlots; ++i)
    if (g_state[i].load() == kLive) ::unlink(g_paths[i].data());
  // SA_RESETHAND restored the default action: the signal, blocked while
  // this handler runs, is delivered again on return and ends the process.
  ::raise(sig);
}

void install_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : kSignals) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;  // keep SIG_IGN and others' handlers
      struct sigaction sa {};
      sa.sa_handler = remove_temporaries_and_die;
      sigemptyset(&sa.sa_mask);
      sa.sa_flags = SA_RESETHAND;
      ::sigaction(sig, &sa, nullptr);
    }
  });
}

std::filesystem::path temporary_name(const std::filesystem::path& path) {
  std::filesystem::path tmp = path;
  tmp += ".tmp-" + std::to_string(::getpid());
  return tmp;
}

}  // namespace

InterruptCleanup::InterruptCleanup(const std::filesystem::path& path) {
  const std::string& s = path.native();
  if (s.empty() || s.size() >= g_paths[0].size()) return;  // not tracked: at worst a .tmp file stays
  install_handlers();
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (g_state[i].compare_exchange_strong(expected, kClaimed)) {
      std::memcpy(g_paths[i].data(), s.c_str(), s.size() + 1);
      g_state[i].store(kLive);
      slot_ = i;
      return;
    }
  }
}

InterruptCleanup::~InterruptCleanup() {
  if (slot_ >= 0) g_state[slot_].store(kFree);
}

AtomicOutput::AtomicOutput(std::filesystem::path path, bool binary)
    : path_(std::move(path)), tmp_(temporary_name(path_)), cleanup_(tmp_) {
  out_.open(tmp_, binary ? std::ios::out | std::ios::binary | std::ios::trunc : std::ios::out | std::ios::trunc);
  if (!out_) throw RunError(path_.string() + ": cannot create output file (is the folder writable?)");
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
  }
}

void AtomicOutput::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok) throw RunError(path_.string() + ": write failed (disk full?); nothing was written");
  std::error_code ec;
  std::filesystem::rename(tmp_, path_, ec);
  if (ec) throw RunError(path_.string() + ": cannot move output into place: " + ec.message());
  committed_ = true;
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  AtomicOutput out(path);
  out.stream() << text;
  out.commit();
}

void ensure_output_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError(dir.string() + ": cannot create output folder (" +
                     (ec ? ec.message() : std::string("a file of that name exists")) + "); choose another --out");
}

}  // namespace fourbar
