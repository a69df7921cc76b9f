#include "acquire/tdms_structure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <limits>

#include "common/error.hpp"
#include "common/number_text.hpp"

namespace fourbar {

namespace {

// Table-of-contents flags of a segment's lead-in.
constexpr std::uint32_t kTocMetaData = 1u << 1, kTocNewObjList = 1u << 2, kTocRawData = 1u << 3,
                        kTocInterleavedData = 1u << 5, kTocBigEndian = 1u << 6, kTocDAQmxRawData = 1u << 7;
// Raw data index words with a meaning of their own.
constexpr std::uint32_t kSameAsPrevious = 0x00000000, kNoData = 0xFFFFFFFF, kDaqmxFormatChanging = 0x69120000,
                        kDaqmxDigitalLine = 0x69130000;
constexpr std::size_t kLeadInBytes = 28;
constexpr std::uint64_t kUnclosed = 0xFFFFFFFFFFFFFFFFull;
// Seconds from the TDMS epoch (1904-01-01 UTC) to the Unix epoch.
constexpr double kEpoch1904To1970_s = 2082844800.0;

std::string hex(std::uint64_t v) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%llX", static_cast<unsigned long long>(v));
  return buf;
}

/// Little- or big-endian reads from a byte buffer, each checked against its end.
class Cursor {
 public:
  Cursor(const std::vector<unsigned char>& bytes, bool big_endian, std::uint64_t file_offset, std::string where)
      : bytes_(bytes), big_(big_endian), base_(file_offset), where_(std::move(where)) {}
  std::uint64_t unsigned_of(std::size_t n) {
    need(n);
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint64_t b = bytes_[pos_ + (big_ ? i : n - 1 - i)];
      v = v << 8 | b;
    }
    pos_ += n;
    return v;
  }
  std::uint32_t u32() { return static_cast<std::uint32_t>(unsigned_of(4)); }
  std::uint64_t u64() { return unsigned_of(8); }
  std::string string() {
    const std::uint32_t n = u32();
    need(n);
    std::string s(reinterpret_cast<const char*>(bytes_.data() + pos_), n);
    pos_ += n;
    return s;
  }
  void need(std::uint64_t n) const {
    if (n > bytes_.size() - pos_)
      throw InputError(where_ + " (byte " + std::to_string(base_ + pos_) + "): the metadata ends inside a value "
                       "(damaged file); copy the file again or re-save it from the NI software");
  }
  std::uint64_t offset() const { return base_ + pos_; }
  bool big_endian() const { return big_; }

 private:
  const std::vector<unsigned char>& bytes_;
  bool big_;
  std::uint64_t base_;
  std::string where_;
  std::size_t pos_ = 0;
};

double signed_of(std::uint64_t v, std::size_t bytes) {
  if (bytes == 8) return static_cast<double>(static_cast<std::int64_t>(v));
  const std::uint64_t sign = 1ull << (8 * bytes - 1);
  return v & sign ? static_cast<double>(static_cast<std::int64_t>(v) - static_cast<std::int64_t>(sign << 1))
                  : static_cast<double>(v);
}

/// "2012-07-09T23:58:23.5Z" from seconds since 1970.
std::string utc_text(double unix_s) {
  if (!std::isfinite(unix_s) || std::abs(unix_s) > 1e13) return "?";
  const auto whole = static_cast<std::time_t>(std::floor(unix_s));
  std::tm tm{};
  if (!gmtime_r(&whole, &tm)) return "?";
  char buf[48];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  std::string s = buf;
  const double frac = unix_s - std::floor(unix_s);
  if (frac > 5e-7) {
    char f[16];
    std::snprintf(f, sizeof f, "%.6f", frac);
    std::string fs = f + 1;  // ".xxxxxx"
    while (fs.back() == '0') fs.pop_back();
    s += fs;
  }
  return s + "Z";
}

TdmsProperty read_property(Cursor& c, const std::string& where) {
  TdmsProperty p;
  p.name = c.string();
  p.type = c.u32();
  using namespace tdms_type;
  switch (p.type) {
    case kI8: case kI16: case kI32: case kI64: {
      const std::size_t n = tdms_type_size(p.type);
      p.number = signed_of(c.unsigned_of(n), n);
      break;
    }
    case kU8: case kU16: case kU32: case kU64:
      p.number = static_cast<double>(c.unsigned_of(tdms_type_size(p.type)));
      break;
    case kSingle: case kSingleWithUnit: {
      const auto bits = static_cast<std::uint32_t>(c.unsigned_of(4));
      float f;
      std::memcpy(&f, &bits, 4);
      p.number = f;
      break;
    }
    case kDouble: case kDoubleWithUnit: {
      const std::uint64_t bits = c.u64();
      double d;
      std::memcpy(&d, &bits, 8);
      p.number = d;
      break;
    }
    case kString: p.text = c.string(); break;
    case kBool: p.number = c.unsigned_of(1) != 0 ? 1.0 : 0.0; break;
    case kTimeStamp: {
      // Little-endian: fractions (2^-64 s) then seconds since 1904; big-endian: the other way round.
      std::uint64_t fractions = 0, seconds = 0;
      if (c.big_endian()) seconds = c.u64(), fractions = c.u64();
      else fractions = c.u64(), seconds = c.u64();
      p.number = static_cast<double>(static_cast<std::int64_t>(seconds)) - kEpoch1904To1970_s +
                 static_cast<double>(fractions) * 0x1p-64;
      p.text = utc_text(*p.number);
      break;
    }
    default:
      throw InputError(where + " (byte " + std::to_string(c.offset()) + "): property '" + p.name + "' has data type " +
                       hex(p.type) + ", which fourbar does not read (it reads integers, float, double, string, bool "
                       "and timestamp properties); re-save the file without it or export to CSV");
  }
  if (p.number && p.type != kTimeStamp) p.text = format_double(*p.number);
  return p;
}

/// "/'group'/'channel'" → group, channel ('' inside quotes is one quote).
void split_path(TdmsObject& o) {
  std::vector<std::string> parts;
  const std::string& s = o.path;
  std::size_t i = 0;
  while (i < s.size()) {
    if (s[i] != '/' || i + 1 >= s.size() || s[i + 1] != '\'') return;  // not the documented form: no group/channel
    std::string part;
    i += 2;
    for (;;) {
      if (i >= s.size()) return;
      if (s[i] == '\'') {
        if (i + 1 < s.size() && s[i + 1] == '\'') part += '\'', i += 2;
        else break;
      } else {
        part += s[i++];
      }
    }
    ++i;  // the closing quote
    parts.push_back(std::move(part));
  }
  if (parts.size() >= 1) o.group = parts[0];
  if (parts.size() >= 2) o.channel = parts[1];
}

/// An object's raw data in the current segment.
struct ActiveEntry {
  std::size_t object = 0;
  bool has_data = false;
  std::uint32_t type = 0;
  std::uint64_t count = 0;  ///< values per chunk
  std::uint64_t bytes = 0;  ///< bytes per chunk
};

struct PreviousIndex {
  bool known = false;
  std::uint32_t type = 0;
  std::uint64_t count = 0, bytes = 0;
};

/// A segment's lead-in (28 bytes at `pos`): tag, table of contents, version,
/// the offsets of the next segment and of the raw data.
struct LeadIn {
  std::uint32_t toc = 0, version = 0;
  std::uint64_t next = 0, raw = 0;
};

LeadIn read_lead_in(std::ifstream& in, std::uint64_t pos, const std::string& f, const std::string& seg) {
  std::vector<unsigned char> lead(kLeadInBytes);
  in.seekg(static_cast<std::streamoff>(pos));
  if (!in.read(reinterpret_cast<char*>(lead.data()), kLeadInBytes)) throw InputError(seg + ": cannot read the lead-in");
  if (std::memcmp(lead.data(), "TDSm", 4) != 0) {
    if (std::memcmp(lead.data(), "TDSh", 4) == 0)
      throw InputError(f + ": a TDMS index file (.tdms_index), not the data; give the .tdms file beside it");
    throw InputError(seg + ": no segment tag 'TDSm' where the previous segment's offset points (damaged file); "
                     "copy the file again or re-save it from the NI software");
  }
  const std::uint32_t toc = lead[4] | lead[5] << 8 | lead[6] << 16 | static_cast<std::uint32_t>(lead[7]) << 24;
  const bool big = (toc & kTocBigEndian) != 0;
  Cursor lc(lead, big, pos, seg);
  lc.u64();  // tag and ToC, read above
  const std::uint32_t version = lc.u32();
  const std::uint64_t next = lc.u64(), raw = lc.u64();
  if (version != 4712 && version != 4713)
    throw InputError(seg + ": TDMS version " + std::to_string(version) + " (fourbar reads 4712 and 4713, TDMS 1.0 "
                     "and 2.0); re-save the file as TDMS 2.0");
  return {toc, version, next, raw};
}

/// What the segments so far say about the objects a raw data chunk holds.
struct SegmentState {
  std::vector<ActiveEntry> active;      ///< the objects in the current raw data, in order
  std::vector<PreviousIndex> previous;  ///< per object: its last raw data index
};

/// A segment's metadata: its objects (new ones added to s), their raw data
/// indexes (the active list) and properties. `seg` names the segment in errors.
void read_metadata(Cursor& c, std::uint64_t file_size, const std::string& seg, TdmsStructure& s, SegmentState& st) {
  std::vector<ActiveEntry>& active = st.active;
  std::vector<PreviousIndex>& previous = st.previous;
  const std::uint32_t n = c.u32();
  for (std::uint32_t k = 0; k < n; ++k) {
    TdmsObject probe;
    probe.path = c.string();
    auto it = std::find_if(s.objects.begin(), s.objects.end(), [&](const TdmsObject& o) { return o.path == probe.path; });
    const auto oi = static_cast<std::size_t>(it - s.objects.begin());
    if (it == s.objects.end()) {
      split_path(probe);
      s.objects.push_back(std::move(probe));
      previous.emplace_back();
    }
    TdmsObject& o = s.objects[oi];
    const std::string obj = seg + ": object " + o.path;
    ActiveEntry e;
    e.object = oi;
    const std::uint32_t index = c.u32();
    if (index == kDaqmxFormatChanging || index == kDaqmxDigitalLine)
      throw InputError(obj + " holds DAQmx raw data (raw data index " + hex(index) + "), which fourbar does not "
                       "read: its scaling to physical units needs NI's DAQmx scalers; export the channels from "
                       "LabVIEW, DIAdem or FlexLogger as scaled data (TDMS without DAQmx raw data, or CSV)");
    if (index == kSameAsPrevious) {
      if (!previous[oi].known)
        throw InputError(obj + ": its raw data index is 'same as previous' but no earlier segment gave one (damaged file)");
      e.has_data = true, e.type = previous[oi].type, e.count = previous[oi].count, e.bytes = previous[oi].bytes;
    } else if (index != kNoData) {
      const std::uint64_t index_start = c.offset();
      e.type = c.u32();
      const std::uint32_t dims = c.u32();
      e.count = c.u64();
      if (dims != 1)
        throw InputError(obj + ": raw data of dimension " + std::to_string(dims) + " (TDMS allows only 1; damaged file)");
      if (e.type == tdms_type::kString) {
        e.bytes = c.u64();
        if (e.count > e.bytes / 4)  // an end offset of 4 bytes per string, at least
          throw InputError(obj + ": " + std::to_string(e.count) + " strings in " + std::to_string(e.bytes) +
                           " bytes (damaged file)");
      } else {
        const std::uint32_t size = tdms_type_size(e.type);
        if (size == 0)
          throw InputError(obj + ": raw data of " + tdms_type_name(e.type) + ", which fourbar does not read "
                           "(integers, float, double, bool, string, timestamp); export this channel as double");
        if (e.count > file_size / size)
          throw InputError(obj + ": " + std::to_string(e.count) + " values promised, more than the file holds (damaged file)");
        e.bytes = e.count * size;
      }
      if (c.offset() - index_start + 4 != index)
        throw InputError(obj + ": raw data index of " + std::to_string(index) + " bytes, but its fields take " +
                         std::to_string(c.offset() - index_start + 4) + " (damaged file)");
      if (o.type != 0 && o.type != e.type)
        throw InputError(obj + ": its data type changes from " + tdms_type_name(o.type) + " to " +
                         tdms_type_name(e.type) + " (damaged file)");
      e.has_data = true;
      previous[oi] = {true, e.type, e.count, e.bytes};
    }
    if (e.has_data) o.type = e.type;
    auto slot = std::find_if(active.begin(), active.end(), [&](const ActiveEntry& a) { return a.object == oi; });
    if (slot == active.end()) active.push_back(e);
    else *slot = e;
    const std::uint32_t props = c.u32();
    for (std::uint32_t p = 0; p < props; ++p) {
      TdmsProperty prop = read_property(c, obj);
      auto same = std::find_if(o.properties.begin(), o.properties.end(), [&](const TdmsProperty& q) { return q.name == prop.name; });
      if (same == o.properties.end()) o.properties.push_back(std::move(prop));
      else *same = std::move(prop);
    }
  }
}

/// A segment's raw data [data_start, end): each active object's pieces (where
/// its values sit, chunk by chunk). `cut`: the segment was cut short, so an
/// incomplete last chunk is set aside instead of refused.
void add_raw_data(std::uint64_t data_start, std::uint64_t end, bool interleaved, bool big, bool cut,
                  std::uint64_t file_size, const std::string& seg, const std::vector<ActiveEntry>& active,
                  TdmsStructure& s) {
  const std::uint64_t data_size = end - data_start;
  std::uint64_t chunk = 0, count = 0;
  for (const auto& e : active) {
    if (!e.has_data || e.count == 0) continue;
    if (interleaved && e.type == tdms_type::kString)
      throw InputError(seg + ": object " + s.objects[e.object].path + " holds strings in interleaved raw data, "
                       "which TDMS does not allow (damaged file)");
    if (interleaved && count != 0 && e.count != count)
      throw InputError(seg + ": interleaved channels of different lengths (" + std::to_string(count) + " and " +
                       std::to_string(e.count) + " values; damaged file)");
    count = e.count;
    if (e.bytes > file_size || chunk + e.bytes > file_size)
      throw InputError(seg + ": its raw data index promises more bytes than the file holds (damaged file)");
    chunk += e.bytes;
  }
  if (chunk > 0) {
    std::uint64_t chunks = data_size / chunk;
    if (data_size % chunk != 0) {
      if (!cut)
        throw InputError(seg + ": " + std::to_string(data_size) + " bytes of raw data are not a whole number of "
                         "chunks of " + std::to_string(chunk) + " bytes (damaged file)");
      s.notes.push_back("segment " + std::to_string(s.segments) + ": " + std::to_string(data_size % chunk) +
                        " bytes of a last, incomplete chunk set aside");
    }
    s.interleaved = s.interleaved || interleaved;
    std::uint64_t offset = 0;
    std::uint32_t stride = 0;
    if (interleaved)
      for (const auto& e : active)
        if (e.has_data && e.count > 0) stride += tdms_type_size(e.type);
    for (const auto& e : active) {
      if (!e.has_data || e.count == 0 || chunks == 0) continue;
      TdmsObject& o = s.objects[e.object];
      const std::uint32_t size = tdms_type_size(e.type);
      o.values += e.count * chunks;
      if (e.type != tdms_type::kString) {
        TdmsPiece piece;
        piece.offset = data_start + offset;
        piece.values_per_chunk = e.count;
        piece.chunks = chunks;
        piece.chunk_bytes = chunk;
        piece.stride = interleaved ? stride : size;
        piece.big_endian = big;
        o.pieces.push_back(piece);
      }
      offset += interleaved ? size : e.bytes;
    }
  }
}

}  // namespace

std::uint32_t tdms_type_size(std::uint32_t type) {
  using namespace tdms_type;
  switch (type) {
    case kI8: case kU8: case kBool: return 1;
    case kI16: case kU16: return 2;
    case kI32: case kU32: case kSingle: case kSingleWithUnit: return 4;
    case kI64: case kU64: case kDouble: case kDoubleWithUnit: case kComplexSingle: return 8;
    case kTimeStamp: case kComplexDouble: return 16;
    default: return 0;
  }
}

std::string tdms_type_name(std::uint32_t type) {
  using namespace tdms_type;
  switch (type) {
    case kI8: return "I8";
    case kI16: return "I16";
    case kI32: return "I32";
    case kI64: return "I64";
    case kU8: return "U8";
    case kU16: return "U16";
    case kU32: return "U32";
    case kU64: return "U64";
    case kSingle: case kSingleWithUnit: return "FLOAT";
    case kDouble: case kDoubleWithUnit: return "DOUBLE";
    case kString: return "STRING";
    case kBool: return "BOOL";
    case kTimeStamp: return "TIMESTAMP";
    case kComplexSingle: return "COMPLEX_FLOAT";
    case kComplexDouble: return "COMPLEX_DOUBLE";
    default: return "type " + hex(type);
  }
}

bool tdms_type_is_numeric(std::uint32_t type) {
  using namespace tdms_type;
  return (type >= kI8 && type <= kDouble) || type == kSingleWithUnit || type == kDoubleWithUnit || type == kBool;
}

const TdmsProperty* TdmsObject::property(const std::string& name) const {
  for (const auto& p : properties)
    if (p.name == name) return &p;
  return nullptr;
}

TdmsStructure read_tdms_structure(const std::filesystem::path& file) {
  const std::string f = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(f + ": cannot open (check the path and permissions)");
  in.seekg(0, std::ios::end);
  const auto file_size = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);

  TdmsStructure s;
  SegmentState st;
  std::uint64_t pos = 0;
  while (pos < file_size) {
    const std::string seg = f + ": TDMS segment " + std::to_string(s.segments + 1) + " at byte " + std::to_string(pos);
    if (file_size - pos < kLeadInBytes) {
      if (s.segments == 0) throw InputError(f + ": shorter than a TDMS lead-in (28 bytes): not a TDMS file or cut short");
      s.notes.push_back(std::to_string(file_size - pos) + " bytes after the last segment set aside (a lead-in cut short)");
      break;
    }
    const LeadIn lead = read_lead_in(in, pos, f, seg);
    const std::uint32_t toc = lead.toc, version = lead.version;
    const std::uint64_t next = lead.next, raw = lead.raw;
    const bool big = (toc & kTocBigEndian) != 0;
    if (s.segments == 0) s.version = version;
    ++s.segments;
    s.big_endian = s.big_endian || big;
    const std::uint64_t start = pos + kLeadInBytes, left = file_size - start;
    bool cut = false;
    std::uint64_t end;
    if (next == kUnclosed || next > left) {
      end = file_size, cut = true;
      s.notes.push_back("segment " + std::to_string(s.segments) + " " +
                        (next == kUnclosed ? "was never closed" : "is cut short") + " (the writer stopped): read to the end of the file");
    } else {
      end = start + next;
    }
    if (raw > end - start)
      throw InputError(seg + ": its raw data offset " + std::to_string(raw) + " lies beyond the segment (" +
                       std::to_string(end - start) + " bytes; damaged file)");
    if (toc & kTocDAQmxRawData)
      throw InputError(seg + ": holds DAQmx raw data (ToC flag kTocDAQmxRawData), which fourbar does not read: its "
                       "scaling to physical units needs NI's DAQmx scalers; export the channels from LabVIEW, "
                       "DIAdem or FlexLogger as scaled data (TDMS without DAQmx raw data, or CSV)");

    if (toc & kTocMetaData) {
      std::vector<unsigned char> meta(static_cast<std::size_t>(raw));
      if (raw > 0 && !in.read(reinterpret_cast<char*>(meta.data()), static_cast<std::streamsize>(raw)))
        throw InputError(seg + ": cannot read its metadata");
      Cursor c(meta, big, start, seg);
      if (toc & kTocNewObjList) st.active.clear();
      read_metadata(c, file_size, seg, s, st);
    }

    if ((toc & kTocRawData) && end - start > raw)
      add_raw_data(start + raw, end, (toc & kTocInterleavedData) != 0, big, cut, file_size, seg, st.active, s);
    pos = end;
  }
  return s;
}

}  // namespace fourbar
