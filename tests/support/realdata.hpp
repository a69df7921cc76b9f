#pragma once
// Recordings written by other software, kept outside the repository in
// ../shared/realdata/ beside the source tree (README there). FOURBAR_REALDATA
// in the environment names another place (a worktree elsewhere). Tests skip,
// saying so, when the folder is absent.

#include <cstdlib>
#include <filesystem>

namespace fourbar::testing {

/// The realdata folder, or an empty path when it is not there.
inline std::filesystem::path realdata_dir() {
  std::filesystem::path p;
  if (const char* env = std::getenv("FOURBAR_REALDATA"); env && *env) p = env;
#ifdef FOURBAR_REALDATA_DIR
  else p = FOURBAR_REALDATA_DIR;
#endif
  std::error_code ec;
  return !p.empty() && std::filesystem::is_directory(p, ec) ? p : std::filesystem::path();
}

}  // namespace fourbar::testing

/// In a test: the realdata file `rel`, or GTEST_SKIP when the folder is absent.
#define FOURBAR_REALDATA_FILE(var, rel)                                                                  \
  const std::filesystem::path var = ::fourbar::testing::realdata_dir().empty()                         \
                                        ? std::filesystem::path()                                     \
                                        : ::fourbar::testing::realdata_dir() / (rel);                 \
  if (var.empty())                                                                                    \
  GTEST_SKIP() << "../shared/realdata is not beside the source tree (set FOURBAR_REALDATA to its path)"
