#pragma once
// Writes a recording as the DAQ would: an audio file through libsndfile
// (container by extension, sample format chosen) or CSV text, block by
// block, under a temporary name that is renamed on commit() — so a failed
// run leaves no half file under the final name.
//
// Integer formats take values normalised to ±1 at full scale and store
// round(x·2^(b−1)) clipped to the b-bit range, which reads back exactly as
// (stored)/2^(b−1) (libsndfile's own double→int conversion scales by
// 2^(b−1) − 1 and would not round-trip). Float formats and text store the
// values as given.

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fourbar {

class RecordingWriter {
 public:
  virtual ~RecordingWriter() = default;
  /// Interleaved frames.
  virtual void write(std::span<const double> frames) = 0;
  virtual void commit() = 0;
  /// Bits of integer storage, 0 for float/text.
  virtual int integer_bits() const = 0;
  /// A CSV recording: also writes NAME.csv.json beside it at commit with
  /// `provenance` (common/csv_writer.hpp). An audio file keeps its
  /// provenance in its comment string and ignores this.
  virtual void describe_in_sidecar(nlohmann::json provenance) { (void)provenance; }
};

/// The container comes from the extension (wav, w64, rf64, flac, caf, aiff,
/// aif, csv); `sample_format` (pcm16, pcm24, pcm32, float, double; default
/// pcm24) must suit it. `comments` (provenance) go into the audio file's
/// comment string or a CSV's `#` lines above its header (give a CSV none
/// unless asked for; see RecordingWriter::describe_in_sidecar). InputError
/// for an unknown extension or an unsuitable sample format.
std::unique_ptr<RecordingWriter> open_recording_writer(const std::filesystem::path& file, int channels,
                                                       double sample_rate_hz, const std::vector<std::string>& names,
                                                       const std::string& sample_format,
                                                       const std::vector<std::string>& comments);

/// True when `file`'s extension names a text (CSV) recording.
bool is_text_recording(const std::filesystem::path& file);

}  // namespace fourbar
