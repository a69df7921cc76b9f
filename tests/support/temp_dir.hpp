#pragma once
// A fresh folder per test, removed afterwards, and a one-call file writer.

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace fourbar::testing {

class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() / ("fourbar-test-" + std::to_string(rd()) + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p;
  }

 private:
  std::filesystem::path path_;
};

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The thesis rig as TOML text with one line replaced (for bad-input tests).
inline std::string thesis_rig_toml() {
  return R"(name = "thesis"
gravity_m_s2 = 9.8145
assembly = "open"
[ground]
length_mm = 387.0
[crank]
length_mm = 64.0
mass_centre_mm = 9.0
mass_kg = 0.6095
inertia_kg_mm2 = 2645.0
[coupler]
length_mm = 309.0
mass_centre_mm = 185.0
mass_kg = 0.2439
inertia_kg_mm2 = 2950.0
[rocker]
length_mm = 312.0
mass_centre_mm = 134.0
mass_kg = 0.2334
inertia_kg_mm2 = 3176.0
[clearance]
radial_mm = 0.254
)";
}

inline std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

}  // namespace fourbar::testing
