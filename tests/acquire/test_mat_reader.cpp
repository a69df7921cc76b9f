// The MATLAB reader on files libmatio writes in the test: v5 (plain and
// compressed) and v7.3; vectors, matrix columns, the time variable, the rate
// from a named variable; errors that name the variable and list what the
// file holds.

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include <zlib.h>

#include "acquire/manifest.hpp"
#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "support/temp_dir.hpp"
#include "format_writers.hpp"
#include "read_recording.hpp"

namespace fourbar {
namespace {

using testing::read_all;
using testing::read_error_of;
using testing::TempDir;

void write_vars(const std::filesystem::path& file, mat_ft version,
                const std::vector<std::tuple<std::string, std::size_t, std::size_t, std::vector<double>>>& vars) {
  mat_t* mat = Mat_CreateVer(file.c_str(), nullptr, version);
  ASSERT_NE(mat, nullptr);
  for (const auto& [name, rows, cols, data] : vars) {
    std::size_t dims[2] = {rows, cols};
    matvar_t* v = Mat_VarCreate(name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, const_cast<double*>(data.data()), 0);
    Mat_VarWrite(mat, v, MAT_COMPRESSION_NONE);
    Mat_VarFree(v);
  }
  Mat_Close(mat);
}

class MatVersion : public ::testing::TestWithParam<mat_ft> {};

TEST_P(MatVersion, VectorsAreChannelsInTheirOrderAndTheRateComesFromFs) {
  TempDir dir;
  const auto s = testing::inspection_signals();
  testing::write_mat(dir.path() / "r.mat", GetParam(), s);
  auto r = open_recording(dir.path() / "r.mat");
  EXPECT_EQ(r->info().format, GetParam() == MAT_FT_MAT73 ? "MAT v7.3" : "MAT v5");
  EXPECT_EQ(r->info().sample_format, "DOUBLE");
  EXPECT_EQ(r->info().channel_names, s.names);
  EXPECT_EQ(r->info().rate_variable, "fs");
  EXPECT_DOUBLE_EQ(r->info().sample_rate_hz, 10000.0);
  const auto all = read_all(*r, 1000);
  ASSERT_EQ(all.size(), testing::kFrames * 4);
  for (std::size_t i : {std::size_t{0}, std::size_t{123}, testing::kFrames - 1})
    for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(all[i * 4 + c], s.columns[c][i]) << i << " " << c;
  r->rewind();
  EXPECT_EQ(read_all(*r, 1000), all);
}

TEST_P(MatVersion, MatrixColumnsWithATimeVariable) {
  TempDir dir;
  const std::size_t n = 100;
  std::vector<double> t(n), data(n * 3), data_t(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    t[i] = 2.0 + static_cast<double>(i) / 500.0;
    for (std::size_t c = 0; c < 3; ++c) data[c * n + i] = data_t[i * 3 + c] = 10.0 * static_cast<double>(c) + static_cast<double>(i);
  }
  write_vars(dir.path() / "cols.mat", GetParam(), {{"t", n, 1, t}, {"data", n, 3, data}, {"gain", 1, 3, {1, 2, 3}}});
  auto r = open_recording(dir.path() / "cols.mat");
  EXPECT_EQ(r->info().channel_names, (std::vector<std::string>{"data(:,1)", "data(:,2)", "data(:,3)"}));
  EXPECT_NEAR(r->info().sample_rate_hz, 500.0, 1e-9);
  EXPECT_DOUBLE_EQ(r->info().start_time_s, 2.0);
  ASSERT_EQ(r->info().notes.size(), 1u);
  EXPECT_NE(r->info().notes[0].find("'gain'"), std::string::npos) << "another length: named, not a channel";
  const auto all = read_all(*r, 1000);
  EXPECT_EQ(all[5 * 3 + 2], 25.0);
  // Channels along the rows of a 3×N matrix (the longer dimension is time).
  write_vars(dir.path() / "rows.mat", GetParam(), {{"data", 3, n, data_t}});
  auto rows = open_recording(dir.path() / "rows.mat", {500.0, {}, {}});
  EXPECT_EQ(rows->info().channel_names[2], "data(3,:)");
  EXPECT_EQ(read_all(*rows, 1000), all);
}

INSTANTIATE_TEST_SUITE_P(V5AndV73, MatVersion, ::testing::Values(MAT_FT_MAT5, MAT_FT_MAT73),
                         [](const auto& info) { return std::string(info.param == MAT_FT_MAT73 ? "v73" : "v5"); });

TEST(MatReader, RateFromTheNamedVariableOrTheManifest) {
  TempDir dir;
  const auto s = testing::inspection_signals();
  testing::write_mat(dir.path() / "r.mat", MAT_FT_MAT5, s, "rate_of_daq");
  EXPECT_DOUBLE_EQ(open_recording(dir.path() / "r.mat", {{}, {}, "rate_of_daq"})->info().sample_rate_hz, 10000.0);
  EXPECT_DOUBLE_EQ(open_recording(dir.path() / "r.mat", {2500.0, {}, {}})->info().sample_rate_hz, 2500.0);
}

TEST(MatReader, ErrorsNameTheVariableAndListWhatTheFileHolds) {
  TempDir dir;
  const auto s = testing::inspection_signals();
  const auto f = dir.path() / "r.mat";
  testing::write_mat(f, MAT_FT_MAT5, s, "");  // no rate variable at all
  std::string e = read_error_of(f);
  EXPECT_NE(e.find(f.string() + ": no sample rate"), std::string::npos) << e;
  EXPECT_NE(e.find("coupler_t 20000x1"), std::string::npos) << e;
  EXPECT_NE(e.find("rate_variable"), std::string::npos) << e;
  e = read_error_of(f, {{}, {}, "fs"});  // the manifest names a variable the file lacks
  EXPECT_NE(e.find("rate_variable 'fs' is not a numeric variable in this file"), std::string::npos) << e;
  EXPECT_NE(e.find("variables found: coupler_t 20000x1, pulse 1x20000, rocker_t 20000x1, spare 20000x1)"), std::string::npos) << e;
  e = read_error_of(f, {{}, {}, "coupler_t"});
  EXPECT_NE(e.find("rate_variable 'coupler_t' is 20000x1, not a scalar"), std::string::npos) << e;

  write_vars(f, MAT_FT_MAT5, {{"a", 4, 1, {1, 2, NAN, 4}}, {"fs", 1, 1, {100}}});
  e = read_error_of(f);
  EXPECT_NE(e.find("variable 'a' element 3 is not a finite number"), std::string::npos) << e;

  write_vars(f, MAT_FT_MAT5, {{"t", 5, 1, {0, 0.1, 0.2, 0.3, 1.0}}, {"a", 5, 1, {1, 2, 3, 4, 5}}});  // a gap
  e = read_error_of(f);
  EXPECT_NE(e.find("time variable 't' element 2"), std::string::npos) << e;

  write_vars(f, MAT_FT_MAT5, {{"fs", 1, 1, {100}}});
  e = read_error_of(f);
  EXPECT_NE(e.find("no numeric variable with more than one value"), std::string::npos) << e;

  // A copy cut short: libmatio alone would drop the variables after the cut.
  testing::write_mat(f, MAT_FT_MAT5, s);
  {
    std::ifstream in(f, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (std::size_t keep : {bytes.size() - 1, bytes.size() - 20, bytes.size() / 2}) {
      const auto cut = dir.write("cut.mat", bytes.substr(0, keep));
      e = read_error_of(cut);
      EXPECT_NE(e.find(cut.string() + ": truncated"), std::string::npos) << keep << ": " << e;
    }
  }
  // v4: refused by name (libmatio spends seconds and gigabytes on a damaged one).
  testing::write_mat(f, MAT_FT_MAT4, s);
  e = read_error_of(f);
  EXPECT_NE(e.find("a MATLAB v4 file"), std::string::npos) << e;

  const auto junk = dir.write("junk.mat", "MATLAB 5.0 MAT-file, but then nothing sensible at all\n");
  e = read_error_of(junk);
  EXPECT_EQ(e.rfind(junk.string() + ": ", 0), 0u) << e;
}

std::string u32_bytes(std::initializer_list<std::uint32_t> words) {
  std::string out;
  for (std::uint32_t w : words) out.append(reinterpret_cast<const char*>(&w), 4);
  return out;
}

// libmatio allocates what a variable's dimensions or name part claims: such
// a part claiming more than the variable holds (plain), or more than a
// header part can be (compressed), is refused as damaged before libmatio
// reads the file (fuzzing found both: 3.9 GB asked, 9 s spent).
TEST(MatReader, HeaderPartsClaimingGigabytesAreRefusedBeforeLibmatio) {
  TempDir dir;
  const auto f = dir.path() / "r.mat";
  write_vars(f, MAT_FT_MAT5, {{"fs", 1, 1, {100}}, {"a", 4, 1, {1, 2, 3, 4}}});
  ASSERT_EQ(read_error_of(f), "");
  std::ifstream in(f, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_EQ(bytes.substr(128, 4), u32_bytes({14}));  // little-endian machine, miMATRIX first
  ASSERT_EQ(bytes.substr(152, 4), u32_bytes({5}));   // its dimensions part after the array flags
  std::string plain = bytes;
  plain.replace(156, 4, u32_bytes({0x7fff0000u}));
  std::string e = read_error_of(dir.write("plain.mat", plain));
  EXPECT_NE(e.find("damaged: a part of a variable at byte 152 claims 2147418112 bytes"), std::string::npos) << e;

  // A compressed variable whose name claims 2 GB (array flags, dimensions 1x1, name tag).
  const std::string header = u32_bytes({14, 48, 6, 8, 6, 0, 5, 8, 1, 1, 1, 0x80000000u});
  std::string z(compressBound(header.size()), '\0');
  uLongf z_size = z.size();
  ASSERT_EQ(compress(reinterpret_cast<Bytef*>(z.data()), &z_size, reinterpret_cast<const Bytef*>(header.data()),
                     header.size()), Z_OK);
  z.resize(z_size);
  e = read_error_of(dir.write("z.mat", bytes.substr(0, 128) + u32_bytes({15, static_cast<std::uint32_t>(z.size())}) + z));
  EXPECT_NE(e.find("damaged: the compressed variable at byte 128 has a header part claiming 2147483648 bytes"),
            std::string::npos) << e;
  // The same variable compressed by libmatio reads.
  mat_t* mat = Mat_CreateVer((dir.path() / "ok.mat").c_str(), nullptr, MAT_FT_MAT5);
  for (const auto& [name, value] : {std::pair<const char*, double>{"fs", 100}, {"a", 1}}) {
    std::size_t dims[2] = {name[0] == 'a' ? 4u : 1u, 1};
    double data[4] = {value, 2, 3, 4};
    matvar_t* v = Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, data, 0);
    Mat_VarWrite(mat, v, MAT_COMPRESSION_ZLIB);
    Mat_VarFree(v);
  }
  Mat_Close(mat);
  EXPECT_EQ(read_error_of(dir.path() / "ok.mat"), "");
}

TEST(MatReader, ManifestColumnsNameVariablesAndAMismatchListsThem) {
  TempDir dir;
  testing::write_mat(dir.path() / "r.mat", MAT_FT_MAT73, testing::inspection_signals());
  auto r = open_recording(dir.path() / "r.mat");
  Manifest m;
  m.file = dir.path() / "r.toml";
  ChannelSpec c;
  c.name = "coupler";
  c.column = "rocker_t";
  m.channels = {c};
  bind_channels(m, r->info());
  EXPECT_EQ(m.channels[0].index, 2);
  m.channels[0].column = "rocker";
  m.channels[0].index.reset();
  try {
    bind_channels(m, r->info());
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("column 'rocker' is not in"), std::string::npos) << what;
    EXPECT_NE(what.find("its channels are 'coupler_t', 'pulse', 'rocker_t', 'spare'"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace fourbar
