// Audio recordings through libsndfile: every container and sample format
// reads back exactly what was written; truncated files are errors.

#include <gtest/gtest.h>

#include <cmath>

#include "acquire/reader.hpp"
#include "acquire/sndfile_formats.hpp"
#include "common/error.hpp"
#include "virtual_rig/recording_writer.hpp"
#include "support/temp_dir.hpp"
#include "read_recording.hpp"

namespace fourbar {
namespace {

using testing::read_all;
using testing::TempDir;

/// Frames of a 3-channel test signal on the grid of `bits` (exact in any format).
std::vector<double> test_frames(std::size_t frames, int bits) {
  std::vector<double> v(frames * 3);
  const double step = bits > 0 ? std::ldexp(1.0, 1 - bits) : std::ldexp(1.0, -20);
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = std::round(0.9 * std::sin(0.001 * static_cast<double>(i * i % 100003)) / step) * step;
  v[3] = -1.0;  // negative full scale is representable in every format
  return v;
}

void write_file(const std::filesystem::path& f, const std::string& subtype, const std::vector<double>& data) {
  auto w = open_recording_writer(f, 3, 25600, {"a", "b", "c"}, subtype, {});
  w->write(std::span<const double>(data).subspan(0, 9000));
  w->write(std::span<const double>(data).subspan(9000));
  w->commit();
}

TEST(SndfileReader, EveryContainerAndSampleFormatRoundTrips) {
  TempDir dir;
  int files = 0;
  for (const auto& c : sndfile_containers()) {
    for (const auto& s : sndfile_subtypes()) {
      if (c.subtypes.find(s.name) == std::string_view::npos) continue;
      const auto f = dir.path() / ("r_" + std::string(s.name) + "." + std::string(c.extension));
      const auto data = test_frames(10000, s.integer_bits ? s.integer_bits : (s.name == "float" ? 24 : 0));
      write_file(f, std::string(s.name), data);
      auto r = open_recording(f);
      const RecordingInfo& info = r->info();
      EXPECT_EQ(info.format, c.name) << f;
      EXPECT_EQ(info.integer_bits, s.integer_bits) << f;
      EXPECT_EQ(info.channels, 3);
      EXPECT_EQ(info.sample_rate_hz, 25600);
      EXPECT_EQ(info.frames, 10000u);
      const auto got = read_all(*r, 777);
      ASSERT_EQ(got.size(), data.size()) << f;
      for (std::size_t i = 0; i < data.size(); ++i) ASSERT_EQ(got[i], data[i]) << f << " sample " << i;
      r->rewind();
      EXPECT_EQ(read_all(*r, 4096), got) << f;
      ++files;
    }
  }
  EXPECT_EQ(files, 32);  // wav w64 rf64 caf aiff aif: 5 sample formats each; flac: 2
}

TEST(SndfileReader, IntegerFullScaleIsOne) {
  TempDir dir;
  const auto f = dir.path() / "fs.wav";
  write_file(f, "pcm16", test_frames(10000, 16));
  auto r = open_recording(f);
  EXPECT_EQ(r->info().sample_format, "PCM_16");
  std::vector<double> block(3 * 2);
  r->read(block);
  EXPECT_EQ(block[3], -1.0);  // -32768 reads as -1
}

TEST(SndfileReader, TruncatedFilesAreErrors) {
  TempDir dir;
  for (const std::string ext : {"wav", "w64", "rf64", "aiff", "flac", "caf"}) {
    const auto f = dir.path() / ("t." + ext);
    write_file(f, ext == "flac" ? "pcm24" : "float", test_frames(10000, 24));
    std::filesystem::resize_file(f, std::filesystem::file_size(f) / 2);
    try {
      auto r = open_recording(f);
      read_all(*r, 1000);
      std::vector<double> block(30);
      ADD_FAILURE() << ext << ": truncation not noticed";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(f.string()), std::string::npos) << m;
      EXPECT_TRUE(m.find("truncated") != std::string::npos || m.find("cannot read") != std::string::npos) << m;
    }
  }
}

TEST(SndfileReader, FormatTable) {
  EXPECT_EQ(sndfile_container_for_extension(".WAV")->name, "WAV");
  EXPECT_EQ(sndfile_container_for_extension("aif")->name, "AIFF");
  EXPECT_FALSE(sndfile_container_for_extension("mp3"));
  EXPECT_EQ(sndfile_subtype("pcm24")->integer_bits, 24);
  EXPECT_FALSE(sndfile_subtype("pcm12"));
}

TEST(RecordingWriter, RefusesUnknownFormats) {
  TempDir dir;
  EXPECT_THROW(open_recording_writer(dir.path() / "x.mp3", 2, 1000, {"a", "b"}, "", {}), InputError);
  EXPECT_THROW(open_recording_writer(dir.path() / "x.flac", 2, 1000, {"a", "b"}, "float", {}), InputError);
  EXPECT_THROW(open_recording_writer(dir.path() / "x.csv", 2, 1000, {"a", "b"}, "pcm16", {}), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.flac"));
}

}  // namespace
}  // namespace fourbar
