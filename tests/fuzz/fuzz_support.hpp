#pragma once
// Helpers shared by the fuzz targets: every loader of fourbar reads a file,
// so each input is written to a file in a private temporary folder (one per
// process, removed at exit) beside a valid rig file that scenes and
// manifests may point to as "rig.toml".
//
// The contract under test: any input either loads or fails with InputError
// (exit status 2 in the CLI). Any other exception escapes the target and
// libFuzzer reports it as a crash, as it does for sanitizer findings.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include <vector>

#include "acquire/reader.hpp"
#include "support/temp_dir.hpp"

namespace fourbar::fuzz {

class Workspace {
 public:
  Workspace() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "fourbar-fuzz-XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) std::abort();
    dir_ = tmpl;
    // The thesis rig, for scenes and manifests that name "rig.toml".
    const std::string rig = testing::thesis_rig_toml();
    write("rig.toml", reinterpret_cast<const std::uint8_t*>(rig.data()), rig.size());
  }
  ~Workspace() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  /// Writes `data` to `name` in the workspace and returns its path.
  std::filesystem::path write(const std::string& name, const std::uint8_t* data, std::size_t size) const {
    const auto p = dir_ / name;
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) std::abort();
    return p;
  }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

/// The process's workspace (created on first use).
inline Workspace& workspace() {
  static Workspace w;
  return w;
}

/// Reads every frame twice (the pipeline rewinds); the frame count the
/// reader promised is what reads back, or the target aborts.
inline void read_all_twice(Reader& reader) {
  std::vector<double> block(static_cast<std::size_t>(reader.info().channels) * 7);
  for (int pass = 0; pass < 2; ++pass) {
    std::uint64_t frames = 0;
    while (const std::size_t n = reader.read(block)) frames += n;
    if (frames != reader.info().frames) std::abort();
    reader.rewind();
  }
}

}  // namespace fourbar::fuzz
