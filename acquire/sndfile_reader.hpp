#pragma once
// Audio-file recordings through libsndfile: WAV (integer, float, double,
// WAVE_FORMAT_EXTENSIBLE), W64, RF64, FLAC, CAF, AIFF and whatever else the
// installed libsndfile reads. Integer samples are normalised to ±1 at
// digital full scale (16-bit: value/32768, 24-bit: value/8388608); float and
// double samples are passed through as stored.

#include <span>

#include "acquire/reader.hpp"

namespace fourbar {

/// True when `head` (the first bytes of a file) starts like a container
/// libsndfile reads (RIFF/RIFX WAVE, RF64, W64, fLaC, caff, FORM AIFF/AIFC).
bool sndfile_claims(const std::filesystem::path& file, std::span<const unsigned char> head);

/// Opens the file; InputError when libsndfile cannot, when the header says
/// more data than the file holds (truncated copy), or the rate is 0.
std::unique_ptr<Reader> open_sndfile_reader(const std::filesystem::path& file, const ReaderOptions& options);

}  // namespace fourbar
