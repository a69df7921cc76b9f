#pragma once
// A small NI TDMS writer for tests, written from NI's "TDMS File Format
// Internal Structure" independently of the reader: the test states each
// segment's ToC flags, objects (raw data index: new, "same as previous" or
// "no data"; properties) and raw data, and the writer lays out the bytes
// (lead-in with both offsets, metadata, raw data) in either byte order.

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fourbar::testing {

namespace tdms_toc {
inline constexpr std::uint32_t kMetaData = 1u << 1, kNewObjList = 1u << 2, kRawData = 1u << 3,
                               kInterleaved = 1u << 5, kBigEndian = 1u << 6;
}

class TdmsBytes {
 public:
  explicit TdmsBytes(bool big_endian) : big_(big_endian) {}
  template <class T>
  void put(T v) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    for (std::size_t i = 0; i < sizeof(T); ++i) bytes.push_back(b[big_ ? sizeof(T) - 1 - i : i]);
  }
  void put_string(const std::string& s) {
    put(static_cast<std::uint32_t>(s.size()));
    bytes.insert(bytes.end(), s.begin(), s.end());
  }
  std::vector<unsigned char> bytes;

 private:
  bool big_;
};

struct TdmsTestProperty {
  std::string name;
  std::uint32_t type;    ///< 0x20 string, 10 double, 3 I32, 0x21 bool, 0x44 timestamp
  std::string text;      ///< strings
  double number = 0;     ///< double, I32, bool
  std::int64_t seconds_1904 = 0;
  std::uint64_t fractions = 0;  ///< timestamps
};

inline TdmsTestProperty tdms_string(std::string name, std::string value) { return {std::move(name), 0x20, std::move(value)}; }
inline TdmsTestProperty tdms_double(std::string name, double value) { return {std::move(name), 10, "", value}; }
inline TdmsTestProperty tdms_time(std::string name, std::int64_t s, std::uint64_t f) { return {std::move(name), 0x44, "", 0, s, f}; }

struct TdmsTestObject {
  enum Index { kNew, kSameAsPrevious, kNoData };
  std::string path;
  Index index = kNoData;
  std::uint32_t type = 0;     ///< with kNew
  std::uint64_t count = 0;    ///< values per chunk, with kNew
  std::uint64_t string_bytes = 0;  ///< kNew of strings: bytes of offsets and text
  std::vector<TdmsTestProperty> properties;
};

/// Appends one segment to `file_bytes`: lead-in, metadata (when kMetaData), raw.
inline void append_tdms_segment(std::vector<unsigned char>& file_bytes, std::uint32_t toc,
                                const std::vector<TdmsTestObject>& objects, const std::vector<unsigned char>& raw) {
  const bool big = (toc & tdms_toc::kBigEndian) != 0;
  TdmsBytes meta(big);
  if (toc & tdms_toc::kMetaData) {
    meta.put(static_cast<std::uint32_t>(objects.size()));
    for (const auto& o : objects) {
      meta.put_string(o.path);
      if (o.index == TdmsTestObject::kNoData) meta.put(std::uint32_t{0xFFFFFFFF});
      else if (o.index == TdmsTestObject::kSameAsPrevious) meta.put(std::uint32_t{0});
      else {
        meta.put(std::uint32_t{o.type == 0x20 ? 28u : 20u});
        meta.put(o.type), meta.put(std::uint32_t{1}), meta.put(o.count);
        if (o.type == 0x20) meta.put(o.string_bytes);
      }
      meta.put(static_cast<std::uint32_t>(o.properties.size()));
      for (const auto& p : o.properties) {
        meta.put_string(p.name);
        meta.put(p.type);
        switch (p.type) {
          case 0x20: meta.put_string(p.text); break;
          case 10: meta.put(p.number); break;
          case 3: meta.put(static_cast<std::int32_t>(p.number)); break;
          case 0x21: meta.put(static_cast<std::uint8_t>(p.number != 0)); break;
          case 0x44:
            if (big) meta.put(p.seconds_1904), meta.put(p.fractions);
            else meta.put(p.fractions), meta.put(p.seconds_1904);
            break;
          default: break;
        }
      }
    }
  }
  TdmsBytes lead(big);
  lead.bytes = {'T', 'D', 'S', 'm'};
  for (int i = 0; i < 4; ++i) lead.bytes.push_back(static_cast<unsigned char>(toc >> (8 * i)));  // always little-endian
  lead.put(std::uint32_t{4713});
  lead.put(static_cast<std::uint64_t>(meta.bytes.size() + raw.size()));
  lead.put(static_cast<std::uint64_t>(meta.bytes.size()));
  file_bytes.insert(file_bytes.end(), lead.bytes.begin(), lead.bytes.end());
  file_bytes.insert(file_bytes.end(), meta.bytes.begin(), meta.bytes.end());
  file_bytes.insert(file_bytes.end(), raw.begin(), raw.end());
}

inline void write_bytes(const std::filesystem::path& f, const std::vector<unsigned char>& bytes) {
  std::ofstream out(f, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace fourbar::testing
