#pragma once
// The structure of an NI TDMS file (versions 4712 and 4713), as NI's "TDMS
// File Format Internal Structure" describes it: a sequence of segments, each
// a 28-byte lead-in ("TDSm", table-of-contents flags, version, the offsets
// of the next segment and of the raw data), optional metadata (the objects
// — file, groups, channels — with their raw data index and properties) and
// raw data, contiguous or interleaved, in little- or big-endian order.
//
// The parse reads only lead-ins and metadata; for each channel it keeps
// where its values lie in the file (`TdmsPiece`), so a reader can stream
// them. Values appended to a channel in later segments ("same as previous"
// raw data index, or a segment without metadata) extend its pieces.
// Refused, with an InputError naming the file, the byte offset and the
// part: DAQmx raw data (index 0x69120000/0x69130000), multi-dimensional
// arrays, interleaved strings, unknown data or property types, a damaged
// lead-in or metadata. A last segment cut short (a recording stopped
// without closing the file) is read to its last whole chunk, with a note.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fourbar {

/// TDMS data type codes (tdsType…) used by fourbar.
namespace tdms_type {
inline constexpr std::uint32_t kI8 = 1, kI16 = 2, kI32 = 3, kI64 = 4, kU8 = 5, kU16 = 6, kU32 = 7, kU64 = 8,
                               kSingle = 9, kDouble = 10, kSingleWithUnit = 0x19, kDoubleWithUnit = 0x1A,
                               kString = 0x20, kBool = 0x21, kTimeStamp = 0x44, kComplexSingle = 0x08000C,
                               kComplexDouble = 0x10000D;
}

/// Bytes per value of a fixed-size type, 0 for strings and types fourbar does not know.
std::uint32_t tdms_type_size(std::uint32_t type);
/// "I16", "DOUBLE", "STRING", … for messages and RecordingInfo::sample_format.
std::string tdms_type_name(std::uint32_t type);
/// True for the types read as numbers (integers, floats, bool).
bool tdms_type_is_numeric(std::uint32_t type);

struct TdmsProperty {
  std::string name;
  std::uint32_t type = 0;
  std::string text;                  ///< strings as stored, numbers and timestamps written out (UTC, ISO 8601)
  std::optional<double> number;      ///< numeric properties; timestamps as seconds since 1970-01-01 UTC
};

/// Where a run of a channel's values lies: value j of the piece is at
/// offset + (j / values_per_chunk)·chunk_bytes + (j % values_per_chunk)·stride.
struct TdmsPiece {
  std::uint64_t offset = 0;
  std::uint64_t values_per_chunk = 0;
  std::uint64_t chunks = 0;
  std::uint64_t chunk_bytes = 0;
  std::uint32_t stride = 0;
  bool big_endian = false;
  std::uint64_t values() const { return values_per_chunk * chunks; }
};

struct TdmsObject {
  std::string path;     ///< as stored: "/", "/'group'", "/'group'/'channel'"
  std::string group;    ///< empty for the file object
  std::string channel;  ///< empty for the file and group objects
  std::vector<TdmsProperty> properties;
  std::uint32_t type = 0;        ///< data type of its raw data, 0 while it has none
  std::uint64_t values = 0;      ///< values over all segments
  std::vector<TdmsPiece> pieces; ///< empty for strings (not read as channels)

  const TdmsProperty* property(const std::string& name) const;
};

struct TdmsStructure {
  std::uint32_t version = 0;  ///< 4712 (TDMS 1.0) or 4713 (TDMS 2.0)
  std::size_t segments = 0;
  bool interleaved = false;   ///< some segment's raw data is interleaved
  bool big_endian = false;    ///< some segment is big-endian
  std::vector<TdmsObject> objects;  ///< in order of first appearance
  std::vector<std::string> notes;   ///< what was set aside or cut
};

/// Reads the segments of `file`. InputError naming the file and the byte
/// offset for anything damaged or not supported.
TdmsStructure read_tdms_structure(const std::filesystem::path& file);

}  // namespace fourbar
