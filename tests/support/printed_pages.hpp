#pragma once
// Pages of a PDF as grey images (pdftoppm from Debian's poppler-utils), to
// check a printed page by its ink: what lies where on the paper.

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace fourbar::testing {

/// pdftoppm, or nullopt when poppler-utils is not installed.
inline std::optional<std::filesystem::path> pdftoppm_binary() {
  for (const char* p : {"/usr/bin/pdftoppm", "/usr/local/bin/pdftoppm"})
    if (std::filesystem::exists(p)) return std::filesystem::path(p);
  return std::nullopt;
}

/// One page, 8-bit grey (0 black, 255 white), row by row.
struct GreyPage {
  int width = 0, height = 0;
  std::vector<unsigned char> grey;
  unsigned char at(int x, int y) const { return grey[static_cast<std::size_t>(y) * width + x]; }
};

/// A binary PGM (P5, maxval 255) as pdftoppm -gray writes it.
inline GreyPage read_pgm(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::string magic;
  int maxval = 0;
  GreyPage g;
  in >> magic >> g.width >> g.height >> maxval;
  in.get();  // the one whitespace byte before the pixels
  if (magic != "P5" || maxval != 255 || g.width <= 0 || g.height <= 0) return {};
  g.grey.resize(static_cast<std::size_t>(g.width) * g.height);
  in.read(reinterpret_cast<char*>(g.grey.data()), static_cast<std::streamsize>(g.grey.size()));
  if (!in) return {};
  return g;
}

/// Every page of `pdf` at `dpi`, in order; empty when pdftoppm failed.
inline std::vector<GreyPage> rasterise_pdf(const std::filesystem::path& pdftoppm, const std::filesystem::path& pdf,
                                           int dpi, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const std::string cmd = pdftoppm.string() + " -gray -r " + std::to_string(dpi) + " '" + pdf.string() + "' '" +
                          (dir / "page").string() + "' >/dev/null 2>&1 </dev/null";
  const int raw = std::system(cmd.c_str());
  if (!WIFEXITED(raw) || WEXITSTATUS(raw) != 0) return {};
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".pgm") files.push_back(e.path());
  std::sort(files.begin(), files.end());  // page-01.pgm, page-02.pgm, … (zero-padded)
  std::vector<GreyPage> pages;
  for (const auto& f : files) pages.push_back(read_pgm(f));
  return pages;
}

/// Pixels darker than `threshold` in the rectangle [x0, x1) × [y0, y1).
inline std::size_t ink(const GreyPage& g, int x0, int x1, int y0, int y1, unsigned char threshold = 200) {
  std::size_t n = 0;
  for (int y = std::max(0, y0); y < std::min(g.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(g.width, x1); ++x) n += g.at(x, y) < threshold;
  return n;
}

}  // namespace fourbar::testing
