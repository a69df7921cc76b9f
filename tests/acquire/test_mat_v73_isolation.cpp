// MATLAB v7.3 files are read in a child process (acquire/mat_reader.cpp):
// what the recording front end delivers must be bit for bit what reading
// the file in this process gives (read_mat_contents) — every field of the
// description, every sample — and the errors the reading raises arrive
// unchanged. A damaged v7.3 file found by fuzzing (libhdf5 overflows a heap
// block on it) is refused as damaged.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <random>

#include "acquire/mat_contents.hpp"
#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "format_writers.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

using testing::TempDir;

template <class T>
void write_var(mat_t* mat, const char* name, matio_classes cls, matio_types type, std::size_t rows, std::size_t cols,
               std::vector<T> data) {
  std::size_t dims[2] = {rows, cols};
  matvar_t* v = Mat_VarCreate(name, cls, type, 2, dims, data.data(), 0);
  Mat_VarWrite(mat, v, MAT_COMPRESSION_ZLIB);
  Mat_VarFree(v);
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

void expect_same(const MatContents& in_process, Reader& r) {
  const RecordingInfo &a = in_process.info, &b = r.info();
  EXPECT_EQ(a.file, b.file);
  EXPECT_EQ(a.format, b.format);
  EXPECT_EQ(a.sample_format, b.sample_format);
  EXPECT_EQ(a.integer_bits, b.integer_bits);
  EXPECT_EQ(a.channels, b.channels);
  EXPECT_EQ(std::memcmp(&a.sample_rate_hz, &b.sample_rate_hz, sizeof(double)), 0) << a.sample_rate_hz;
  EXPECT_EQ(a.frames, b.frames);
  EXPECT_EQ(std::memcmp(&a.start_time_s, &b.start_time_s, sizeof(double)), 0) << a.start_time_s;
  EXPECT_EQ(a.channel_names, b.channel_names);
  EXPECT_EQ(a.channel_units, b.channel_units);
  EXPECT_EQ(a.rate_variable, b.rate_variable);
  EXPECT_EQ(a.notes, b.notes);
  const auto channels = static_cast<std::size_t>(b.channels);
  std::vector<double> all(channels * b.frames), block(channels * 777);
  std::size_t at = 0;
  for (std::size_t n; (n = r.read(block)) > 0; at += n * channels)
    std::copy_n(block.begin(), n * channels, all.begin() + static_cast<std::ptrdiff_t>(at));
  ASSERT_EQ(at, all.size());
  ASSERT_EQ(in_process.columns.size(), channels);
  std::size_t differ = 0;
  for (std::size_t c = 0; c < channels; ++c)
    for (std::size_t i = 0; i < b.frames; ++i)
      differ += std::memcmp(&all[i * channels + c], &in_process.columns[c][i], sizeof(double)) != 0;
  EXPECT_EQ(differ, 0u) << "samples not bit-identical";
}

TEST(MatV73Isolation, TheChildsReadingIsBitIdenticalToThisProcesss) {
  TempDir dir;
  const auto s = testing::inspection_signals();
  testing::write_mat(dir.path() / "vectors.mat", MAT_FT_MAT73, s);
  testing::write_mat(dir.path() / "zlib.mat", MAT_FT_MAT73, s, "rate_of_daq", MAT_COMPRESSION_ZLIB);

  // Matrix columns beside a time variable, integer and single classes, and
  // doubles that text would not keep: subnormals, -0, extremes, random bits.
  const std::size_t n = 3001;
  std::mt19937_64 rng(73);
  std::vector<double> t(n), doubles(n * 3);
  std::vector<std::int16_t> ints(n * 2);
  std::vector<float> singles(n);
  for (std::size_t i = 0; i < n; ++i) {
    t[i] = 0.25 + static_cast<double>(i) / 2048.0;
    for (std::size_t c = 0; c < 3; ++c) {
      double x;
      do {
        const std::uint64_t bits = rng();
        std::memcpy(&x, &bits, sizeof x);
      } while (!std::isfinite(x));
      doubles[c * n + i] = x;
    }
    ints[i] = static_cast<std::int16_t>(rng()), ints[n + i] = static_cast<std::int16_t>(-32768 + static_cast<int>(i));
    singles[i] = static_cast<float>(std::sin(static_cast<double>(i))) * 1e-3f;
  }
  doubles[0] = std::numeric_limits<double>::denorm_min(), doubles[1] = -0.0;
  doubles[2] = std::numeric_limits<double>::max(), doubles[3] = -std::numeric_limits<double>::min();
  mat_t* mat = Mat_CreateVer((dir.path() / "mixed.mat").c_str(), nullptr, MAT_FT_MAT73);
  ASSERT_NE(mat, nullptr);
  write_var(mat, "t", MAT_C_DOUBLE, MAT_T_DOUBLE, n, 1, t);
  write_var(mat, "data", MAT_C_DOUBLE, MAT_T_DOUBLE, n, 3, doubles);
  write_var(mat, "counts", MAT_C_INT16, MAT_T_INT16, 2, n, ints);  // channels along rows
  write_var(mat, "strain", MAT_C_SINGLE, MAT_T_SINGLE, 1, n, singles);
  write_var(mat, "gain", MAT_C_DOUBLE, MAT_T_DOUBLE, 1, 2, std::vector<double>{1, 2});  // a note
  Mat_Close(mat);

  struct Case {
    const char* file;
    ReaderOptions options;
  };
  for (const Case& c : {Case{"vectors.mat", {}}, Case{"zlib.mat", {{}, {}, "rate_of_daq"}}, Case{"mixed.mat", {}},
                        Case{"mixed.mat", {4096.0, {}, {}}}}) {
    SCOPED_TRACE(c.file);
    const auto f = dir.path() / c.file;
    ASSERT_EQ(mat_header_version(f), 0x0200u);
    const MatContents in_process = read_mat_contents(f, c.options);
    const auto r = open_recording(f, c.options);
    expect_same(in_process, *r);
  }
  const auto mixed = open_recording(dir.path() / "mixed.mat");
  EXPECT_EQ(mixed->info().channels, 6);  // data ×3, counts ×2, strain
  EXPECT_EQ(mixed->info().sample_format, "MIXED");
  EXPECT_DOUBLE_EQ(mixed->info().start_time_s, 0.25);
}

TEST(MatV73Isolation, ErrorsRaisedInTheChildArriveUnchanged) {
  TempDir dir;
  const auto f = dir.path() / "bad.mat";
  mat_t* mat = Mat_CreateVer(f.c_str(), nullptr, MAT_FT_MAT73);
  ASSERT_NE(mat, nullptr);
  write_var(mat, "t", MAT_C_DOUBLE, MAT_T_DOUBLE, 4, 1, std::vector<double>{0, 1, 2, 5});
  write_var(mat, "a", MAT_C_DOUBLE, MAT_T_DOUBLE, 4, 1, std::vector<double>{1, 2, 3, 4});
  Mat_Close(mat);
  const std::string in_process = error_of([&] { read_mat_contents(f, {}); });
  EXPECT_NE(in_process.find("is not uniform"), std::string::npos) << in_process;
  EXPECT_EQ(error_of([&] { open_recording(f); }), in_process);
  const std::string no_var = error_of([&] { read_mat_contents(f, {{}, {}, "fs"}); });
  EXPECT_NE(no_var.find("rate_variable 'fs'"), std::string::npos) << no_var;
  EXPECT_EQ(error_of([&] { open_recording(f, {{}, {}, "fs"}); }), no_var);
}

// Found by fuzzing: reading this file's variables makes libhdf5 1.10
// overflow a heap block (AddressSanitizer sees it; without it the damage
// is silent). In the child it cannot touch this process; the file is
// refused as damaged, whatever the child made of it.
TEST(MatV73Isolation, AFileThatOverflowsLibhdf5IsRefusedAsDamaged) {
  TempDir dir;
  std::ifstream in(std::string(FOURBAR_SOURCE_DIR) +
                       "/tests/fuzz/regressions/mat/v73_attribute_heap_overflow_in_libhdf5.mat.bin",
                   std::ios::binary);
  ASSERT_TRUE(in);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto f = dir.write("damaged.mat", bytes.substr(1));  // the fuzz input's first byte picks the options
  ASSERT_EQ(mat_header_version(f), 0x0200u);
  const std::string e = error_of([&] { open_recording(f); });
  EXPECT_EQ(e.rfind(f.string() + ": ", 0), 0u) << e;
  EXPECT_NE(e.find("damaged"), std::string::npos) << e;
}

}  // namespace
}  // namespace fourbar
