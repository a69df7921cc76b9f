#pragma once
// The libsndfile containers and sample formats fourbar reads and writes, by
// name and file extension (shared by the reader and the virtual rig's writer).

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace fourbar {

struct SndfileContainer {
  std::string_view extension;  ///< lower case, without the dot
  std::string_view name;       ///< "WAV", "W64", ...
  int major;                   ///< SF_FORMAT_WAV, ...
  std::string_view subtypes;   ///< sample formats it can hold, for messages
};

struct SndfileSubtype {
  std::string_view name;       ///< "pcm16", "pcm24", "pcm32", "float", "double"
  int subtype;                 ///< SF_FORMAT_PCM_16, ...
  int integer_bits;            ///< 0 for float formats
};

std::span<const SndfileContainer> sndfile_containers();
std::span<const SndfileSubtype> sndfile_subtypes();

/// The container for a file extension ("wav", "WAV", ".wav"), if any.
std::optional<SndfileContainer> sndfile_container_for_extension(std::string_view extension);
/// The subtype named `name` (see sndfile_subtypes()), if any.
std::optional<SndfileSubtype> sndfile_subtype(std::string_view name);

/// Libsndfile's names for a format word: {"WAV", "PCM_24"}.
std::string sndfile_major_name(int format);
std::string sndfile_subtype_name(int format);
/// Bits of an integer subtype (8, 16, 24, 32), 0 for float.
int sndfile_integer_bits(int format);

}  // namespace fourbar
