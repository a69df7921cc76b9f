#pragma once
// A recording as a block-streaming source of frames (one value per channel
// per sample), whatever file format it came in.
//
// Each format is one Reader implementation plus one line in the registry
// (reader_registry.cpp): `open_recording` picks the format from the file's
// content (magic bytes) and, for text formats, its extension. Samples are
// delivered as double in "recorded units": integer formats normalised so that
// digital full scale is ±1, float formats and text exactly as stored. The
// manifest's `full_scale_V` turns recorded units into volts.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fourbar {

struct RecordingInfo {
  std::filesystem::path file;
  std::string format;          ///< container, e.g. "WAV", "FLAC", "CSV"
  std::string sample_format;   ///< e.g. "PCM_16", "PCM_24", "FLOAT", "DOUBLE", "TEXT"
  int integer_bits = 0;        ///< 8…32 for integer samples, 0 for float and text
  int channels = 0;
  double sample_rate_hz = 0;
  std::uint64_t frames = 0;
  double start_time_s = 0;     ///< time of frame 0 (a CSV time column may not start at 0)
  /// Wall-clock time of the start as the file states it (TDMS wf_start_time
  /// in UTC, a UFF58 date line, a CSV preamble's start), empty when it does not.
  std::string started_at;
  /// Per channel: the column name for text formats, the variable name for
  /// MATLAB files, empty for audio files.
  std::vector<std::string> channel_names;
  /// Per channel: the unit a text export states (`coupler_t [V]` or a units
  /// row under the header), empty when none; empty vector when no channel has one.
  std::vector<std::string> channel_units;
  /// MATLAB: the scalar variable the sample rate was read from, when it was.
  std::optional<std::string> rate_variable;
  /// What a reader noticed and set aside (e.g. a MATLAB variable of another length).
  std::vector<std::string> notes;

  double duration_s() const { return sample_rate_hz > 0 ? static_cast<double>(frames) / sample_rate_hz : 0; }
};

/// What the manifest may tell a reader that the file itself does not say.
struct ReaderOptions {
  std::optional<double> sample_rate_hz;  ///< required for text without a time column
  std::optional<std::string> time_column;  ///< text: name of the time column (default: auto)
  std::optional<std::string> rate_variable;  ///< MATLAB: the scalar variable holding the sample rate in Hz
  std::optional<std::size_t> header_line;  ///< text: 1-based line of the column names (default: found below any preamble)
};

class Reader {
 public:
  virtual ~Reader() = default;
  const RecordingInfo& info() const { return info_; }

  /// Reads up to `out.size() / channels` frames, interleaved, into `out`.
  /// Returns the number of frames read (0 at the end). A damaged file throws
  /// InputError naming the file and where it broke.
  virtual std::size_t read(std::span<double> out) = 0;

  /// Back to frame 0 (the pipeline reads a recording in several passes, so
  /// that memory stays bounded however long it is).
  virtual void rewind() = 0;

 protected:
  RecordingInfo info_;
};

/// One registered format.
struct ReaderFormat {
  std::string_view name;         ///< "audio (libsndfile)", "delimited text"
  std::string_view description;  ///< one line for --help and errors
  /// True when this format recognises the file (by `head`, its first bytes,
  /// or by its extension for formats without magic bytes).
  bool (*claims)(const std::filesystem::path& file, std::span<const unsigned char> head);
  std::unique_ptr<Reader> (*open)(const std::filesystem::path& file, const ReaderOptions& options);
};

/// Every known format, tried in order.
std::span<const ReaderFormat> reader_formats();

/// Opens `file` with the first format that claims it. InputError when the
/// file is missing, unreadable, of unknown format, empty or damaged.
std::unique_ptr<Reader> open_recording(const std::filesystem::path& file, const ReaderOptions& options = {});

}  // namespace fourbar
