// The RIFF / RF64 / Wave64 chunk walk that guards libsndfile: every file
// libsndfile writes passes; every size that runs past its file, container or
// LIST is refused before sf_open sees it (a LIST sub-chunk whose size reads
// as -8 makes sf_open 1.2.0 loop forever).

#include "acquire/riff_structure.hpp"

#include <gtest/gtest.h>
#include <sndfile.h>

#include <cstdint>
#include <fstream>

#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "support/temp_dir.hpp"
#include "virtual_rig/recording_writer.hpp"

namespace fourbar {
namespace {

using testing::TempDir;
using Bytes = std::string;

Bytes u32(std::uint32_t v) {
  Bytes b(4, '\0');
  for (int i = 0; i < 4; ++i) b[static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xFF);
  return b;
}
Bytes u64(std::uint64_t v) { return u32(static_cast<std::uint32_t>(v)) + u32(static_cast<std::uint32_t>(v >> 32)); }
Bytes u16(unsigned v) { return u32(v).substr(0, 2); }

/// A RIFF chunk: id, size (the body's unless given), body, pad byte.
Bytes chunk(const std::string& id, const Bytes& body, std::optional<std::uint32_t> size = {}) {
  return id + u32(size.value_or(static_cast<std::uint32_t>(body.size()))) + body + (body.size() % 2 ? Bytes(1, '\0') : "");
}
const Bytes kFmt = u16(1) + u16(1) + u32(48000) + u32(96000) + u16(2) + u16(16);  // PCM, mono, 16 bit
const Bytes kSamples(76, '\x01');                                                 // 38 frames

Bytes info_list(const std::string& sub, std::uint32_t sub_size) {
  return chunk("LIST", "INFO" + sub + u32(sub_size) + Bytes("comment\0", 8));
}
Bytes wav(const Bytes& chunks) { return "RIFF" + u32(static_cast<std::uint32_t>(4 + chunks.size())) + "WAVE" + chunks; }
Bytes rf64(const Bytes& chunks_after_ds64, std::uint32_t table_entries = 0, const Bytes& table = "") {
  const Bytes ds64 = chunk("ds64", u64(4 + 8 + 28 + table.size() + chunks_after_ds64.size()) + u64(kSamples.size()) +
                                       u64(38) + u32(table_entries) + table);
  return "RF64" + u32(0xFFFFFFFF) + "WAVE" + ds64 + chunks_after_ds64;
}

const Bytes kW64Tail("\xF3\xAC\xD3\x11\x8C\xD1\x00\xC0\x4F\x8E\xDB\x8A", 12);
Bytes w64_chunk(const std::string& id, const Bytes& body, std::optional<std::uint64_t> size = {}) {
  return id + kW64Tail + u64(size.value_or(24 + body.size())) + body + Bytes((8 - body.size() % 8) % 8, '\0');
}
Bytes w64(const Bytes& chunks) {
  return "riff" + Bytes("\x2E\x91\xCF\x11\xA5\xD6\x28\xDB\x04\xC1\x00\x00", 12) + u64(40 + chunks.size()) + "wave" +
         kW64Tail + chunks;
}

class RiffStructure : public ::testing::Test {
 protected:
  std::filesystem::path put(const std::string& name, const Bytes& bytes) {
    const auto f = dir.path() / name;
    std::ofstream(f, std::ios::binary) << bytes;
    return f;
  }
  std::optional<RiffDefect> defect(const Bytes& bytes, const std::string& ext = "wav") {
    return riff_structure_defect(put("x." + ext, bytes));
  }
  TempDir dir;
};

TEST_F(RiffStructure, HandMadeSoundFilesPass) {
  EXPECT_FALSE(defect(wav(chunk("fmt ", kFmt) + chunk("data", kSamples))));
  EXPECT_FALSE(defect(wav(chunk("fmt ", kFmt) + info_list("ICMT", 8) + chunk("data", kSamples))));
  EXPECT_FALSE(defect(rf64(chunk("fmt ", kFmt) + chunk("data", kSamples, 0xFFFFFFFF)), "rf64"));
  EXPECT_FALSE(defect(w64(w64_chunk("fmt ", kFmt) + w64_chunk("data", kSamples)), "w64"));
  // An odd-sized last chunk without its pad byte, and bytes after the RIFF
  // chunk that are no chunk (libsndfile stops parsing there too).
  const Bytes odd = chunk("fmt ", kFmt) + chunk("data", kSamples + "x");
  EXPECT_FALSE(defect(wav(odd.substr(0, odd.size() - 1))));
  EXPECT_FALSE(defect(wav(chunk("fmt ", kFmt) + chunk("data", kSamples)) + Bytes("\0\0\0\0\0\0\0\0\0\0", 10)));
  // Not RIFF-family: not examined.
  EXPECT_FALSE(defect("fLaC and whatever follows", "flac"));
}

TEST_F(RiffStructure, EveryFileLibsndfileWritesPasses) {
  int files = 0;
  for (const std::string ext : {"wav", "w64", "rf64", "flac", "caf", "aiff"}) {
    for (const std::string format : {"pcm16", "pcm24", "float"}) {
      if (ext == "flac" && format == "float") continue;
      for (const std::size_t frames : {1u, 777u, 10001u}) {
        const auto f = dir.path() / ("w" + std::to_string(files) + "." + ext);
        // Odd comment lengths give odd LIST/INFO sub-chunks (pad bytes);
        // one channel of pcm24 over an odd frame count an odd data chunk.
        auto w = open_recording_writer(f, 1, 25600, {"a"}, format, {"made by a test", std::to_string(frames)});
        const std::vector<double> v(frames, 0.25);
        w->write(v);
        w->commit();
        EXPECT_FALSE(riff_structure_defect(f)) << f << ": " << riff_structure_defect(f)->what;
        EXPECT_EQ(open_recording(f)->info().frames, frames) << f;
        ++files;
      }
    }
  }
  EXPECT_EQ(files, 51);
}

TEST_F(RiffStructure, SubChunkThatWouldHangLibsndfileIsRefused) {
  // libsndfile 1.2.0 reads the size 0xFFFFFFF8 as -8, seeks back over the
  // sub-chunk's own header and parses it again, forever (issue #1118).
  for (const std::uint32_t size : {0xFFFFFFF8u, 0xFFFFFFFFu, 40u}) {
    for (const bool is_rf64 : {false, true}) {
      const Bytes list = info_list(size == 40 ? "ICMT" : "IXYZ", size);
      const Bytes bytes = is_rf64 ? rf64(chunk("fmt ", kFmt) + list + chunk("data", kSamples, 0xFFFFFFFF))
                                  : wav(chunk("fmt ", kFmt) + list + chunk("data", kSamples));
      const auto d = defect(bytes, is_rf64 ? "rf64" : "wav");
      ASSERT_TRUE(d) << size;
      EXPECT_FALSE(d->truncated);
      EXPECT_NE(d->what.find("sub-chunk 'I"), std::string::npos) << d->what;
      EXPECT_NE(d->what.find("of LIST 'INFO' declares " + std::to_string(size) + " bytes"), std::string::npos) << d->what;
    }
  }
}

TEST_F(RiffStructure, SizesPastTheFileAreTruncation) {
  const Bytes whole = wav(chunk("fmt ", kFmt) + chunk("data", kSamples));
  const auto d = defect(whole.substr(0, whole.size() - 10));
  ASSERT_TRUE(d);
  EXPECT_TRUE(d->truncated);
  EXPECT_NE(d->what.find("header declares " + std::to_string(whole.size()) + " bytes"), std::string::npos) << d->what;
  // The RIFF size agrees with the cut file but the data chunk does not.
  const Bytes cut = whole.substr(8, whole.size() - 18);
  const auto d2 = defect("RIFF" + u32(static_cast<std::uint32_t>(cut.size())) + cut);
  ASSERT_TRUE(d2);
  EXPECT_TRUE(d2->truncated);
  EXPECT_NE(d2->what.find("chunk 'data' at byte 36 declares 76 bytes but the file holds only 66"), std::string::npos)
      << d2->what;
  const auto w = defect(w64(w64_chunk("fmt ", kFmt) + w64_chunk("LIST", "INFO", 0xFFFFFFFF0ull)), "w64");
  ASSERT_TRUE(w);
  EXPECT_TRUE(w->truncated);
  EXPECT_NE(w->what.find("chunk 'LIST' at byte 80 declares 68719476720 bytes"), std::string::npos) << w->what;
}

TEST_F(RiffStructure, InconsistentHeadersAreDamage) {
  // A chunk running past the end of the RIFF chunk (but not of the file).
  const Bytes body = "WAVE" + chunk("fmt ", kFmt) + chunk("data", kSamples);
  auto d = defect("RIFF" + u32(static_cast<std::uint32_t>(body.size() - 20)) + body);
  ASSERT_TRUE(d);
  EXPECT_FALSE(d->truncated);
  EXPECT_NE(d->what.find("chunk 'data' at byte 36"), std::string::npos) << d->what;
  // Wave64 chunk sizes count their own 24-byte header: 0 would never advance.
  d = defect(w64(w64_chunk("fmt ", kFmt) + w64_chunk("junk", "", 0) + w64_chunk("data", kSamples)), "w64");
  ASSERT_TRUE(d);
  EXPECT_NE(d->what.find("chunk 'junk' at byte 80 declares 0 bytes, less than its own 24-byte header"),
            std::string::npos)
      << d->what;
  // RF64 without ds64; with a ds64 too short for its table; a 0xFFFFFFFF
  // size ds64 has no entry for.
  d = defect("RF64" + u32(0xFFFFFFFF) + "WAVE" + chunk("fmt ", kFmt) + chunk("data", kSamples), "rf64");
  ASSERT_TRUE(d);
  EXPECT_NE(d->what.find("must start with a ds64 chunk"), std::string::npos) << d->what;
  d = defect(rf64(chunk("fmt ", kFmt) + chunk("data", kSamples, 0xFFFFFFFF), 3), "rf64");
  ASSERT_TRUE(d);
  EXPECT_NE(d->what.find("table of 3 entries"), std::string::npos) << d->what;
  d = defect(rf64(chunk("fmt ", kFmt) + chunk("junk", "abcd", 0xFFFFFFFF) + chunk("data", kSamples, 0xFFFFFFFF)),
             "rf64");
  ASSERT_TRUE(d);
  EXPECT_NE(d->what.find("chunk 'junk' at byte 72 leaves its size to the ds64 chunk"), std::string::npos) << d->what;
  // ...but one the ds64 table sizes passes.
  EXPECT_FALSE(defect(rf64(chunk("fmt ", kFmt) + chunk("junk", "abcd", 0xFFFFFFFF) +
                               chunk("data", kSamples, 0xFFFFFFFF),
                           1, "junk" + u64(4)),
                      "rf64"));
}

TEST_F(RiffStructure, ReaderRefusesWithAdvice) {
  const auto f = put("REC.wav", wav(chunk("fmt ", kFmt) + info_list("IXYZ", 0xFFFFFFF8) + chunk("data", kSamples)));
  try {
    open_recording(f);
    ADD_FAILURE() << "opened";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(f.string() + ": damaged file header: sub-chunk 'IXYZ' at byte 48 of LIST 'INFO'", 0), 0u) << m;
    EXPECT_NE(m.find("; copy the file again from the DAQ"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace fourbar
