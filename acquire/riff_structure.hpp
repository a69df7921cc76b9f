#pragma once
// The chunk structure of RIFF-family audio files (RIFF/RIFX WAVE, RF64/BW64,
// Sony Wave64), checked before the file reaches libsndfile. libsndfile trusts
// declared chunk sizes: a LIST/INFO sub-chunk that claims 0xFFFFFFFF bytes
// makes sf_open spin forever (libsndfile issue #1118, still in 1.2.0), so one
// damaged file would stop a whole `fourbar report`.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace fourbar {

struct RiffDefect {
  /// True when a size runs past the end of the file (a copy cut short);
  /// false when the sizes contradict each other inside the file.
  bool truncated = false;
  /// What is wrong, naming the chunk and its byte offset.
  std::string what;
};

/// Walks every chunk of a RIFF/RIFX WAVE, RF64/BW64 or Wave64 file, and every
/// sub-chunk inside its LIST chunks, and returns the first defect:
///  * the container size (RF64: ds64's riff size) larger than the file;
///  * a chunk or sub-chunk running past the end of the file, of its container
///    or of its LIST; a LIST too short for its type; Wave64 sizes below the
///    24-byte chunk header;
///  * RF64: no ds64 chunk first, a ds64 too short for its table, a chunk
///    whose size 0xFFFFFFFF has no ds64 entry.
/// The pad byte (RIFF) or alignment (Wave64) after the last chunk may be
/// missing. Bytes after the container's declared end are walked while they
/// look like chunks (printable identifiers), as libsndfile parses them too.
/// Other files (FLAC, CAF, AIFF, anything without these magic bytes) are
/// not examined: nullopt. Throws InputError when the file cannot be read.
std::optional<RiffDefect> riff_structure_defect(const std::filesystem::path& file);

}  // namespace fourbar
