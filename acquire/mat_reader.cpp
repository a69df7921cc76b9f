#include "acquire/mat_reader.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "acquire/mat_contents.hpp"
#include "acquire/mat_wire.hpp"
#include "common/child_process.hpp"
#include "common/error.hpp"
#include "common/number_text.hpp"

namespace fourbar {

namespace {

class MatRecording final : public Reader {
 public:
  explicit MatRecording(MatContents c) : columns_(std::move(c.columns)) { info_ = std::move(c.info); }

  std::size_t read(std::span<double> out) override {
    const std::size_t channels = columns_.size();
    const std::size_t n = std::min<std::size_t>(out.size() / channels, info_.frames - position_);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < channels; ++c) out[i * channels + c] = columns_[c][position_ + i];
    position_ += n;
    return n;
  }

  void rewind() override { position_ = 0; }

 private:
  std::vector<std::vector<double>> columns_;
  std::uint64_t position_ = 0;
};

/// fourbar-read-mat: FOURBAR_READ_MAT when set, else beside this program
/// (build/cli/ holds both), else where the build put it (for the test
/// programs, which live elsewhere in the build tree).
std::filesystem::path reader_program() {
  if (const char* env = std::getenv("FOURBAR_READ_MAT"); env && *env) {
    if (::access(env, X_OK) == 0) return env;
    throw RunError(std::string("cannot read MATLAB files: FOURBAR_READ_MAT=") + env +
                   " is not an executable program; point it at fourbar-read-mat (built beside fourbar), or unset it");
  }
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  std::vector<std::filesystem::path> tried;
  if (!ec) tried.push_back(self.parent_path() / "fourbar-read-mat");
#ifdef FOURBAR_READ_MAT_BUILD_PATH
  if (tried.empty() || tried.front() != FOURBAR_READ_MAT_BUILD_PATH) tried.emplace_back(FOURBAR_READ_MAT_BUILD_PATH);
#endif
  for (const auto& p : tried)
    if (::access(p.c_str(), X_OK) == 0) return p;
  std::string where;
  for (const auto& p : tried) where += (where.empty() ? "" : ", ") + p.string();
  throw RunError("cannot read MATLAB files: the program fourbar-read-mat that reads them is not installed (looked for " +
                 where + "); build it with fourbar, or set FOURBAR_READ_MAT to its path");
}

/// The file read by fourbar-read-mat, a process of its own. libhdf5 1.10
/// (Debian 12) overflows heap blocks on damaged v7.3 files (fuzzing:
/// tests/fuzz/regressions/mat/v73_attribute_heap_overflow_in_libhdf5.mat.bin)
/// and fourbar cannot check an HDF5 file's structure before it as it does a
/// v5 file's; there a crash, a hang or corrupted memory ends in that
/// process. It keeps libmatio and libhdf5 (and the ~40 libraries they load)
/// out of fourbar itself: every command starts faster. Errors the reading
/// raises there are raised here unchanged; the contents arrive bit for bit.
MatContents read_in_reader_program(const std::filesystem::path& file, const ReaderOptions& options) {
  std::vector<std::string> argv{reader_program().string(), file.string()};
  if (options.rate_variable) argv.insert(argv.end(), {"--rate-variable", *options.rate_variable});
  if (options.sample_rate_hz) argv.insert(argv.end(), {"--sample-rate", format_double(*options.sample_rate_hz)});
  if (options.time_column) argv.insert(argv.end(), {"--time-column", *options.time_column});
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(file, ec);
  // A minute, and a second more per MB: reading and sending a valid file
  // takes a small part of that even on a loaded machine.
  const std::chrono::milliseconds limit(60'000 + (ec ? 0 : static_cast<std::int64_t>(bytes / 1000)));
  const ChildResult res = run_program(argv, limit);
  const std::string f = file.string();
  const auto damaged = [&](const std::string& how) {
    return InputError(f + ": reading this MATLAB file went wrong inside libmatio/libhdf5 — the reading process " + how +
                      ": the file is damaged; copy the file again, or re-save it from MATLAB (save -v7, or -v7.3)");
  };
  if (!res.ok) throw damaged(res.failure);
  if (res.bytes.empty()) throw damaged("sent nothing");
  if (auto c = decode_mat_result(res.bytes, file)) return std::move(*c);
  throw damaged("sent garbled data");
}

}  // namespace

bool mat_claims(const std::filesystem::path& file, std::span<const unsigned char> head) {
  static constexpr char kMagic[] = "MATLAB ";
  if (head.size() >= 7 && std::memcmp(head.data(), kMagic, 7) == 0) return true;
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".mat";
}

std::unique_ptr<Reader> open_mat_reader(const std::filesystem::path& file, const ReaderOptions& options) {
  return std::make_unique<MatRecording>(read_in_reader_program(file, options));
}

unsigned mat_header_version(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char h[128];
  if (!in.read(reinterpret_cast<char*>(h), sizeof h)) return 0;
  const bool im = h[126] == 'I' && h[127] == 'M', mi = h[126] == 'M' && h[127] == 'I';
  // The version is written in the file's byte order, as the mark is ("IM" read on this machine).
  const unsigned version = im ? h[124] | h[125] << 8 : h[124] << 8 | h[125];
  return (im || mi) && (version == 0x0100 || version == 0x0200) ? version : 0;
}

}  // namespace fourbar
