#pragma once
// Opens a local HTML file in Debian's headless Chromium (package chromium):
// the DOM after the page's scripts ran, and a screenshot. Flags as for this
// machine's closed network (no background requests, no sandbox as root).

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace fourbar::testing {

/// The Chromium binary, or nullopt when it is not installed.
inline std::optional<std::filesystem::path> chromium_binary() {
  if (const char* env = std::getenv("FOURBAR_CHROMIUM")) return std::filesystem::path(env);
  for (const char* p : {"/usr/bin/chromium", "/usr/bin/chromium-browser"})
    if (std::filesystem::exists(p)) return std::filesystem::path(p);
  return std::nullopt;
}

struct BrowserRun {
  int status = -1;
  std::string out, err;
};

/// Runs Chromium headless on `page` with `action` ("--dump-dom" or
/// "--screenshot=FILE"); the page gets 20 s of virtual time to finish.
inline BrowserRun run_chromium(const std::filesystem::path& chromium, const std::filesystem::path& page,
                               const std::string& action) {
  TempDir profile;
  const auto out = profile.path() / "stdout", err = profile.path() / "stderr";
  const std::string cmd = chromium.string() +
                          " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
                          " --disable-background-networking --disable-component-update --disable-sync"
                          " --disable-features=MediaRouter,OptimizationHints --user-data-dir=" +
                          (profile.path() / "profile").string() +
                          " --window-size=1280,2400 --virtual-time-budget=20000 --enable-logging=stderr --v=0 " + action +
                          " 'file://" + std::filesystem::absolute(page).string() + "' >" + out.string() + " 2>" +
                          err.string() + " </dev/null";
  const int raw = std::system(cmd.c_str());
  BrowserRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

}  // namespace fourbar::testing
