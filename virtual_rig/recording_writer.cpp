#include "virtual_rig/recording_writer.hpp"

#include <sndfile.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "acquire/sndfile_formats.hpp"
#include "common/atomic_output.hpp"
#include "common/csv_writer.hpp"
#include "common/error.hpp"

namespace fourbar {

namespace {

class SndfileWriter final : public RecordingWriter {
 public:
  SndfileWriter(const std::filesystem::path& file, int channels, double rate, int format, int bits,
                const std::vector<std::string>& comments)
      : path_(file), channels_(channels), bits_(bits) {
    tmp_ = file;
    tmp_ += ".tmp-" + std::to_string(::getpid());
    cleanup_ = std::make_unique<InterruptCleanup>(tmp_);
    SF_INFO info{};
    info.channels = channels;
    info.samplerate = static_cast<int>(std::lround(rate));
    info.format = format;
    if (!sf_format_check(&info))
      throw InputError(file.string() + ": libsndfile cannot write this combination of container, sample format, " +
                       std::to_string(channels) + " channels and " + std::to_string(info.samplerate) + " Hz");
    handle_ = sf_open(tmp_.c_str(), SFM_WRITE, &info);
    if (!handle_) throw RunError(file.string() + ": cannot create (" + std::string(sf_strerror(nullptr)) + ")");
    // Provenance in the file's own metadata where the container has some
    // (WAV, AIFF, FLAC, CAF); silently skipped where it has none.
    std::string comment;
    for (const auto& c : comments) comment += (comment.empty() ? "" : "; ") + c;
    sf_set_string(handle_, SF_STR_SOFTWARE, "fourbar virtual-rig");
    if (!comment.empty()) sf_set_string(handle_, SF_STR_COMMENT, comment.c_str());
  }
  ~SndfileWriter() override {
    if (handle_) sf_close(handle_);
    if (!committed_) {
      std::error_code ec;
      std::filesystem::remove(tmp_, ec);
    }
  }
  void write(std::span<const double> frames) override {
    const auto n = static_cast<sf_count_t>(frames.size() / static_cast<std::size_t>(channels_));
    sf_count_t done;
    if (bits_ > 0) {
      // Integer storage: round to the b-bit grid ourselves, stored left-aligned in 32 bits.
      const double top = std::ldexp(1.0, bits_ - 1);
      ints_.resize(frames.size());
      for (std::size_t i = 0; i < frames.size(); ++i) {
        const double q = std::clamp(std::nearbyint(frames[i] * top), -top, top - 1);
        ints_[i] = static_cast<int>(static_cast<long long>(q) * (1LL << (32 - bits_)));
      }
      done = sf_writef_int(handle_, ints_.data(), n);
    } else {
      done = sf_writef_double(handle_, frames.data(), n);
    }
    if (done != n) throw RunError(path_.string() + ": write failed (" + std::string(sf_strerror(handle_)) + ")");
  }
  void commit() override {
    if (sf_close(handle_) != 0) {
      handle_ = nullptr;
      throw RunError(path_.string() + ": write failed on close");
    }
    handle_ = nullptr;
    std::error_code ec;
    std::filesystem::rename(tmp_, path_, ec);
    if (ec) throw RunError(path_.string() + ": cannot move output into place: " + ec.message());
    committed_ = true;
  }
  int integer_bits() const override { return bits_; }

 private:
  std::filesystem::path path_, tmp_;
  int channels_, bits_;
  std::unique_ptr<InterruptCleanup> cleanup_;  // removes tmp_ on SIGINT/SIGTERM/SIGHUP
  SNDFILE* handle_ = nullptr;
  bool committed_ = false;
  std::vector<int> ints_;
};

class TextWriter final : public RecordingWriter {
 public:
  TextWriter(const std::filesystem::path& file, int channels, double rate, const std::vector<std::string>& names,
             const std::vector<std::string>& comments)
      : csv_(file, comments, with_time(names)), channels_(static_cast<std::size_t>(channels)), rate_(rate),
        row_(channels_ + 1) {}
  void write(std::span<const double> frames) override {
    for (std::size_t f = 0; f * channels_ < frames.size(); ++f) {
      row_[0] = static_cast<double>(n_++) / rate_;
      std::copy_n(frames.begin() + static_cast<std::ptrdiff_t>(f * channels_), channels_, row_.begin() + 1);
      csv_.row(row_);
    }
  }
  void commit() override { csv_.commit(); }
  int integer_bits() const override { return 0; }
  void describe_in_sidecar(nlohmann::json provenance) override { csv_.describe_in_sidecar(std::move(provenance)); }

 private:
  static std::vector<std::string> with_time(std::vector<std::string> names) {
    names.insert(names.begin(), "time_s");
    return names;
  }
  CsvWriter csv_;
  std::size_t channels_;
  double rate_;
  std::vector<double> row_;
  std::uint64_t n_ = 0;
};

}  // namespace

bool is_text_recording(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".csv";
}

std::unique_ptr<RecordingWriter> open_recording_writer(const std::filesystem::path& file, int channels,
                                                       double sample_rate_hz, const std::vector<std::string>& names,
                                                       const std::string& sample_format,
                                                       const std::vector<std::string>& comments) {
  if (is_text_recording(file)) {
    if (!sample_format.empty())
      throw InputError(file.string() + ": sample_format = \"" + sample_format +
                       "\" is for audio files; a CSV recording holds text (remove it or use quantisation_bits)");
    return std::make_unique<TextWriter>(file, channels, sample_rate_hz, names, comments);
  }
  const auto container = sndfile_container_for_extension(file.extension().string());
  if (!container) {
    std::string list;
    for (const auto& c : sndfile_containers()) list += "." + std::string(c.extension) + " ";
    throw InputError(file.string() + ": unknown output format '" + file.extension().string() + "'; use one of " +
                     list + ".csv");
  }
  const std::string name = sample_format.empty() ? "pcm24" : sample_format;
  const auto subtype = sndfile_subtype(name);
  if (!subtype || container->subtypes.find(name) == std::string_view::npos)
    throw InputError(file.string() + ": a " + std::string(container->name) + " file cannot hold sample_format = \"" +
                     name + "\"; it takes " + std::string(container->subtypes));
  return std::make_unique<SndfileWriter>(file, channels, sample_rate_hz, container->major | subtype->subtype,
                                         subtype->integer_bits, comments);
}

}  // namespace fourbar
