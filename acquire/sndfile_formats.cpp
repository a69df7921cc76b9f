#include "acquire/sndfile_formats.hpp"

#include <sndfile.h>

#include <algorithm>
#include <array>
#include <cctype>

namespace fourbar {

std::span<const SndfileContainer> sndfile_containers() {
  static constexpr std::array table{
      SndfileContainer{"wav", "WAV", SF_FORMAT_WAV, "pcm16, pcm24, pcm32, float, double"},
      SndfileContainer{"w64", "W64", SF_FORMAT_W64, "pcm16, pcm24, pcm32, float, double"},
      SndfileContainer{"rf64", "RF64", SF_FORMAT_RF64, "pcm16, pcm24, pcm32, float, double"},
      SndfileContainer{"flac", "FLAC", SF_FORMAT_FLAC, "pcm16, pcm24"},
      SndfileContainer{"caf", "CAF", SF_FORMAT_CAF, "pcm16, pcm24, pcm32, float, double"},
      SndfileContainer{"aiff", "AIFF", SF_FORMAT_AIFF, "pcm16, pcm24, pcm32, float, double"},
      SndfileContainer{"aif", "AIFF", SF_FORMAT_AIFF, "pcm16, pcm24, pcm32, float, double"},
  };
  return table;
}

std::span<const SndfileSubtype> sndfile_subtypes() {
  static constexpr std::array table{
      SndfileSubtype{"pcm16", SF_FORMAT_PCM_16, 16}, SndfileSubtype{"pcm24", SF_FORMAT_PCM_24, 24},
      SndfileSubtype{"pcm32", SF_FORMAT_PCM_32, 32}, SndfileSubtype{"float", SF_FORMAT_FLOAT, 0},
      SndfileSubtype{"double", SF_FORMAT_DOUBLE, 0},
  };
  return table;
}

std::optional<SndfileContainer> sndfile_container_for_extension(std::string_view extension) {
  std::string ext(extension);
  if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const auto& c : sndfile_containers())
    if (c.extension == ext) return c;
  return std::nullopt;
}

std::optional<SndfileSubtype> sndfile_subtype(std::string_view name) {
  for (const auto& s : sndfile_subtypes())
    if (s.name == name) return s;
  return std::nullopt;
}

std::string sndfile_major_name(int format) {
  switch (format & SF_FORMAT_TYPEMASK) {
    case SF_FORMAT_WAV: return "WAV";
    case SF_FORMAT_WAVEX: return "WAVEX";
    case SF_FORMAT_W64: return "W64";
    case SF_FORMAT_RF64: return "RF64";
    case SF_FORMAT_FLAC: return "FLAC";
    case SF_FORMAT_CAF: return "CAF";
    case SF_FORMAT_AIFF: return "AIFF";
    default: {
      SF_FORMAT_INFO fi{};
      fi.format = format & SF_FORMAT_TYPEMASK;
      if (sf_command(nullptr, SFC_GET_FORMAT_INFO, &fi, sizeof fi) == 0 && fi.name) return fi.name;
      return "audio";
    }
  }
}

std::string sndfile_subtype_name(int format) {
  switch (format & SF_FORMAT_SUBMASK) {
    case SF_FORMAT_PCM_S8: return "PCM_S8";
    case SF_FORMAT_PCM_U8: return "PCM_U8";
    case SF_FORMAT_PCM_16: return "PCM_16";
    case SF_FORMAT_PCM_24: return "PCM_24";
    case SF_FORMAT_PCM_32: return "PCM_32";
    case SF_FORMAT_FLOAT: return "FLOAT";
    case SF_FORMAT_DOUBLE: return "DOUBLE";
    default: return "other";
  }
}

int sndfile_integer_bits(int format) {
  switch (format & SF_FORMAT_SUBMASK) {
    case SF_FORMAT_PCM_S8:
    case SF_FORMAT_PCM_U8: return 8;
    case SF_FORMAT_PCM_16: return 16;
    case SF_FORMAT_PCM_24: return 24;
    case SF_FORMAT_PCM_32: return 32;
    default: return 0;
  }
}

}  // namespace fourbar
