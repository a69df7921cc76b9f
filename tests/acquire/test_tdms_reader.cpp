// NI TDMS recordings: files written by a writer of the tests' own
// (tests/acquire/tdms_writer.hpp, from NI's format description) read back
// bit for bit — several segments, contiguous and interleaved, both byte
// orders, appended values, "same as previous" and "no data" indexes, every
// numeric type — and a file LabVIEW SignalExpress wrote
// (../shared/realdata/tdms/Digital_Input.tdms).

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "support/temp_dir.hpp"
#include "tdms_writer.hpp"
#include "read_recording.hpp"

namespace fourbar {
namespace {

using testing::read_all;
using testing::open_error_of;
using testing::append_tdms_segment;
using testing::TdmsBytes;
using testing::TdmsTestObject;
using testing::TempDir;
namespace toc = testing::tdms_toc;

/// The numeric TDMS types and a value of each that the type holds exactly.
struct TypeCase {
  std::uint32_t code;
  const char* name;
};
constexpr TypeCase kTypes[] = {{1, "i8"}, {2, "i16"}, {3, "i32"}, {4, "i64"}, {5, "u8"},     {6, "u16"},
                               {7, "u32"}, {8, "u64"}, {9, "f32"}, {10, "f64"}, {0x21, "bool"}};

double value_for(std::uint32_t code, std::uint64_t i) {
  const double k = static_cast<double>(i);
  switch (code) {
    case 1: return static_cast<double>(static_cast<int>(i * 37 % 256) - 128);
    case 2: return static_cast<double>(static_cast<int>(i * 7919 % 65536) - 32768);
    case 3: return static_cast<double>(static_cast<std::int64_t>(i * 123456789ull % 4294967296ull) - 2147483648LL);
    case 4: return -9007199254740992.0 + k * 1e12;  // −2^53 upwards: exact in a double
    case 5: return static_cast<double>(i * 37 % 256);
    case 6: return static_cast<double>(i * 7919 % 65536);
    case 7: return 4294967295.0 - k * 3.0;
    case 8: return 9007199254740992.0 - k;
    case 9: return static_cast<double>(static_cast<float>(std::sin(k) * 3.7f));
    case 10: return std::sin(k) * 1e-3 + 1.0 / 3.0;
    default: return static_cast<double>(i % 3 == 0);
  }
}

void put_value(TdmsBytes& b, std::uint32_t code, double v) {
  switch (code) {
    case 1: b.put(static_cast<std::int8_t>(v)); break;
    case 2: b.put(static_cast<std::int16_t>(v)); break;
    case 3: b.put(static_cast<std::int32_t>(v)); break;
    case 4: b.put(static_cast<std::int64_t>(v)); break;
    case 5: b.put(static_cast<std::uint8_t>(v)); break;
    case 6: b.put(static_cast<std::uint16_t>(v)); break;
    case 7: b.put(static_cast<std::uint32_t>(v)); break;
    case 8: b.put(static_cast<std::uint64_t>(v)); break;
    case 9: b.put(static_cast<float>(v)); break;
    case 10: b.put(v); break;
    default: b.put(static_cast<std::uint8_t>(v != 0)); break;
  }
}

std::string channel_path(const char* name) { return std::string("/'Rig ''A'''/'") + name + "'"; }

/// Contiguous values of every type channel for values [first, first + count), appended to `b`.
void contiguous(TdmsBytes& b, std::uint64_t first, std::uint64_t count) {
  for (const auto& t : kTypes)
    for (std::uint64_t i = first; i < first + count; ++i) put_value(b, t.code, value_for(t.code, i));
}

TEST(TdmsReader, SegmentsContiguousInterleavedBothByteOrdersReadBackBitForBit) {
  TempDir dir;
  std::vector<unsigned char> file;
  // Segment 1: the file, the group and a channel of each type (5 values a
  // chunk, 2 chunks), properties on each level.
  std::vector<TdmsTestObject> objects{
      {"/", TdmsTestObject::kNoData, 0, 0, 0, {testing::tdms_string("name", "round trip")}},
      {"/'Rig ''A'''", TdmsTestObject::kNoData, 0, 0, 0, {testing::tdms_string("operator", "me")}}};
  for (const auto& t : kTypes) {
    TdmsTestObject o{channel_path(t.name), TdmsTestObject::kNew, t.code, 5, 0, {}};
    o.properties = {testing::tdms_double("wf_increment", 1.0 / 2048), testing::tdms_string("unit_string", "V"),
                    testing::tdms_double("wf_start_offset", 0.25),
                    testing::tdms_time("wf_start_time", 3'784'000'000, 1ull << 63)};
    if (t.code == 10) o.properties[1] = testing::tdms_string("NI_UnitDescription", "m/s^2");
    objects.push_back(o);
  }
  TdmsBytes raw1(false);
  contiguous(raw1, 0, 5);
  contiguous(raw1, 5, 5);
  append_tdms_segment(file, toc::kMetaData | toc::kNewObjList | toc::kRawData, objects, raw1.bytes);
  std::uint64_t written = 10;

  // Segment 2: no metadata — the same objects and indexes, 1 chunk appended.
  TdmsBytes raw2(false);
  contiguous(raw2, written, 5);
  append_tdms_segment(file, toc::kRawData, {}, raw2.bytes);
  written += 5;

  // Segment 3: metadata without a new object list: every channel "same as
  // previous", plus a string channel appended to the list (no values for the recording).
  std::vector<TdmsTestObject> same;
  for (const auto& t : kTypes) same.push_back({channel_path(t.name), TdmsTestObject::kSameAsPrevious, 0, 0, 0, {}});
  same.push_back({"/'Rig ''A'''/'comment'", TdmsTestObject::kNew, 0x20, 2, 8 + 3, {}});
  TdmsBytes raw3(false);
  contiguous(raw3, written, 5);
  raw3.put(std::uint32_t{1}), raw3.put(std::uint32_t{3});
  raw3.bytes.insert(raw3.bytes.end(), {'a', 'b', 'c'});
  append_tdms_segment(file, toc::kMetaData | toc::kRawData, same, raw3.bytes);
  written += 5;

  // Segment 4: big-endian, interleaved, a new object list with 7 values per
  // channel and the string channel "no data".
  std::vector<TdmsTestObject> inter;
  for (const auto& t : kTypes) inter.push_back({channel_path(t.name), TdmsTestObject::kNew, t.code, 7, 0, {}});
  inter.push_back({"/'Rig ''A'''/'comment'", TdmsTestObject::kNoData, 0, 0, 0, {}});
  TdmsBytes raw4(true);
  for (std::uint64_t i = written; i < written + 7; ++i)
    for (const auto& t : kTypes) put_value(raw4, t.code, value_for(t.code, i));
  append_tdms_segment(file, toc::kMetaData | toc::kNewObjList | toc::kRawData | toc::kInterleaved | toc::kBigEndian,
                      inter, raw4.bytes);
  written += 7;

  // Segment 5: little-endian interleaved, no metadata: the previous segment's list, 2 chunks.
  TdmsBytes raw5(false);
  for (std::uint64_t i = written; i < written + 14; ++i)
    for (const auto& t : kTypes) put_value(raw5, t.code, value_for(t.code, i));
  append_tdms_segment(file, toc::kRawData | toc::kInterleaved, {}, raw5.bytes);
  written += 14;

  const auto f = dir.path() / "round_trip.tdms";
  testing::write_bytes(f, file);
  const auto r = open_recording(f);
  const RecordingInfo& info = r->info();
  EXPECT_EQ(info.format, "TDMS");
  EXPECT_EQ(info.sample_format, "MIXED");
  ASSERT_EQ(info.channels, static_cast<int>(std::size(kTypes)));
  EXPECT_EQ(info.frames, written);
  EXPECT_EQ(info.sample_rate_hz, 2048.0);
  EXPECT_EQ(info.start_time_s, 0.25);
  EXPECT_EQ(info.started_at, "2023-11-28T07:06:40.5Z");  // 3 784 000 000 s after 1904-01-01, + 2^63 / 2^64 s
  for (std::size_t c = 0; c < std::size(kTypes); ++c) {
    EXPECT_EQ(info.channel_names[c], kTypes[c].name);
    EXPECT_EQ(info.channel_units[c], kTypes[c].code == 10 ? "m/s^2" : "V");
  }
  bool string_noted = false;
  for (const auto& n : info.notes) string_noted = string_noted || n.find("'Rig 'A'/comment' (STRING, 2 values)") != std::string::npos;
  EXPECT_TRUE(string_noted) << "the string channel is listed as set aside";
  for (std::size_t block : {1u, 3u, 1000u}) {
    const auto got = read_all(*r, block);
    ASSERT_EQ(got.size(), written * std::size(kTypes));
    for (std::uint64_t i = 0; i < written; ++i)
      for (std::size_t c = 0; c < std::size(kTypes); ++c) {
        const double want = value_for(kTypes[c].code, i), have = got[i * std::size(kTypes) + c];
        ASSERT_EQ(std::memcmp(&want, &have, sizeof want), 0) << kTypes[c].name << " value " << i << ": " << have << " != " << want;
      }
    r->rewind();
  }
}

TEST(TdmsReader, ChannelsOfAnotherLengthOrRateAreNotesAndDuplicateNamesGetTheirGroup) {
  TempDir dir;
  std::vector<unsigned char> file;
  auto ch = [](std::string path, std::uint64_t n, double dt) {
    return TdmsTestObject{std::move(path), TdmsTestObject::kNew, 10, n, 0, {testing::tdms_double("wf_increment", dt)}};
  };
  TdmsBytes raw(false);
  for (int i = 0; i < 4 + 4 + 4 + 2; ++i) raw.put(static_cast<double>(i));
  append_tdms_segment(file, toc::kMetaData | toc::kNewObjList | toc::kRawData,
                      {ch("/'a'/'x'", 4, 0.01), ch("/'b'/'x'", 4, 0.01), ch("/'b'/'slow'", 4, 0.02), ch("/'b'/'short'", 2, 0.01)},
                      raw.bytes);
  const auto f = dir.path() / "groups.tdms";
  testing::write_bytes(f, file);
  const auto r = open_recording(f);
  ASSERT_EQ(r->info().channels, 2);
  EXPECT_EQ(r->info().channel_names, (std::vector<std::string>{"a/x", "b/x"}));
  EXPECT_EQ(r->info().sample_rate_hz, 100.0);
  ASSERT_EQ(r->info().notes.size(), 2u);
  EXPECT_NE(r->info().notes[0].find("'b/slow': 50 Hz, not the recording's 100 Hz"), std::string::npos) << r->info().notes[0];
  EXPECT_NE(r->info().notes[1].find("'b/short': 2 values at 100 Hz, not the recording's 4"), std::string::npos) << r->info().notes[1];
  const auto got = read_all(*r, 10);
  EXPECT_EQ(got, (std::vector<double>{0, 4, 1, 5, 2, 6, 3, 7}));
}

TEST(TdmsReader, UnsupportedAndDamagedPartsAreNamedErrors) {
  TempDir dir;
  const auto f = dir.path() / "bad.tdms";
  auto one = [](std::uint32_t index_word) {
    std::vector<unsigned char> file;
    TdmsBytes meta(false);
    meta.put(std::uint32_t{1});
    meta.put_string("/'g'/'daq'");
    meta.put(index_word);
    meta.put(std::uint32_t{0});
    TdmsBytes lead(false);
    lead.bytes = {'T', 'D', 'S', 'm', 0x0E, 0, 0, 0};
    lead.put(std::uint32_t{4713}), lead.put(static_cast<std::uint64_t>(meta.bytes.size())), lead.put(static_cast<std::uint64_t>(meta.bytes.size()));
    file = lead.bytes;
    file.insert(file.end(), meta.bytes.begin(), meta.bytes.end());
    return file;
  };
  testing::write_bytes(f, one(0x69120000));
  EXPECT_NE(open_error_of(f).find("bad.tdms: TDMS segment 1 at byte 0: object /'g'/'daq' holds DAQmx raw data (raw data index 0x69120000)"),
            std::string::npos) << open_error_of(f);
  testing::write_bytes(f, one(0));
  EXPECT_NE(open_error_of(f).find("'same as previous' but no earlier segment gave one"), std::string::npos) << open_error_of(f);

  // A later segment whose tag is not "TDSm": the byte offset is named.
  std::vector<unsigned char> file;
  TdmsBytes raw(false);
  raw.put(1.0);
  append_tdms_segment(file, toc::kMetaData | toc::kNewObjList | toc::kRawData,
                      {{"/'g'/'c'", TdmsTestObject::kNew, 10, 1, 0, {testing::tdms_double("wf_increment", 1)}}}, raw.bytes);
  const std::size_t first = file.size();
  append_tdms_segment(file, toc::kRawData, {}, raw.bytes);
  file[first] = 'X';
  testing::write_bytes(f, file);
  EXPECT_NE(open_error_of(f).find("TDMS segment 2 at byte " + std::to_string(first) + ": no segment tag 'TDSm'"), std::string::npos)
      << open_error_of(f);

  // No wf_increment: the manifest's rate is needed, and then used; a contradicting one is refused.
  file.clear();
  append_tdms_segment(file, toc::kMetaData | toc::kNewObjList | toc::kRawData,
                      {{"/'g'/'c'", TdmsTestObject::kNew, 10, 1, 0, {}}}, raw.bytes);
  testing::write_bytes(f, file);
  EXPECT_NE(open_error_of(f).find("has no wf_increment property"), std::string::npos) << open_error_of(f);
  EXPECT_EQ(open_recording(f, {.sample_rate_hz = 500.0})->info().sample_rate_hz, 500.0);
}

TEST(TdmsReader, AnUnclosedLastSegmentIsReadToItsLastWholeChunkWithANote) {
  TempDir dir;
  std::vector<unsigned char> file;
  TdmsBytes raw(false);
  for (int i = 0; i < 6; ++i) raw.put(static_cast<double>(i));
  append_tdms_segment(file, toc::kMetaData | toc::kNewObjList | toc::kRawData,
                      {{"/'g'/'c'", TdmsTestObject::kNew, 10, 2, 0, {testing::tdms_double("wf_increment", 0.5)}}}, raw.bytes);
  for (int k = 0; k < 8; ++k) file[12 + k] = 0xFF;  // next segment offset: "never closed"
  file.resize(file.size() - 12);                      // 4.5 chunks of 2 doubles are left
  const auto f = dir.path() / "unclosed.tdms";
  testing::write_bytes(f, file);
  const auto r = open_recording(f);
  EXPECT_EQ(r->info().frames, 4u);
  EXPECT_EQ(read_all(*r, 3), (std::vector<double>{0, 1, 2, 3}));
  ASSERT_EQ(r->info().notes.size(), 2u);
  EXPECT_NE(r->info().notes[0].find("never closed"), std::string::npos);
  EXPECT_NE(r->info().notes[1].find("4 bytes of a last, incomplete chunk set aside"), std::string::npos) << r->info().notes[1];
}

}  // namespace
}  // namespace fourbar
