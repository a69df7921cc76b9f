#include "acquire/sndfile_reader.hpp"

#include <sndfile.h>

#include <cstring>
#include <memory>
#include <regex>
#include <sstream>

#include "acquire/riff_structure.hpp"
#include "acquire/sndfile_formats.hpp"
#include "common/error.hpp"

namespace fourbar {

namespace {

bool starts_with(std::span<const unsigned char> head, std::size_t at, const char* magic) {
  const std::size_t n = std::strlen(magic);
  return head.size() >= at + n && std::memcmp(head.data() + at, magic, n) == 0;
}

/// libsndfile repairs a header that promises more data than the file holds
/// and only says so in its log ("data : 90000 (should be 44978)", "Calculated
/// frame count … does not match"). A shortened recording must not pass as a
/// shorter one, so such a log is an error.
std::optional<std::string> truncation_in_log(const std::string& log) {
  static const std::regex should_be(R"((\w[\w ]*?)\s*:\s*(\d+)\s*\(should be (\d+)\))");
  for (std::sregex_iterator it(log.begin(), log.end(), should_be), end; it != end; ++it) {
    const auto stated = std::stoull((*it)[2].str()), actual = std::stoull((*it)[3].str());
    if (stated > actual)
      return "its header promises " + std::to_string(stated) + " bytes of '" + (*it)[1].str() + "' but the file holds " +
             std::to_string(actual);
  }
  if (log.find("does not match") != std::string::npos || log.find("not equal to frame count") != std::string::npos)
    return "its frame count does not match the data it holds";
  return std::nullopt;
}

class SndfileReader final : public Reader {
 public:
  SndfileReader(const std::filesystem::path& file, const ReaderOptions& options) {
    // libsndfile trusts declared chunk sizes (a LIST sub-chunk claiming 4 GiB
    // makes sf_open spin forever): the structure is checked first.
    if (const auto defect = riff_structure_defect(file))
      throw InputError(file.string() + (defect->truncated ? ": truncated recording: " : ": damaged file header: ") +
                       defect->what + "; copy the file again from the DAQ");
    SF_INFO sf{};
    handle_.reset(sf_open(file.c_str(), SFM_READ, &sf));
    if (!handle_)
      throw InputError(file.string() + ": cannot read as audio recording (" + sf_strerror(nullptr) +
                       "); check that the file is complete and really a " + file.extension().string() + " file");
    char log[8192] = {};
    sf_command(handle_.get(), SFC_GET_LOG_INFO, log, sizeof log);
    if (auto why = truncation_in_log(log)) {
      throw InputError(file.string() + ": truncated recording: " + *why + "; copy the file again from the DAQ");
    }
    sf_command(handle_.get(), SFC_SET_NORM_DOUBLE, nullptr, SF_TRUE);
    info_.file = file;
    info_.format = sndfile_major_name(sf.format);
    info_.sample_format = sndfile_subtype_name(sf.format);
    info_.integer_bits = sndfile_integer_bits(sf.format);
    info_.channels = sf.channels;
    info_.sample_rate_hz = sf.samplerate;
    info_.frames = static_cast<std::uint64_t>(sf.frames);
    info_.channel_names.assign(static_cast<std::size_t>(sf.channels), "");
    if (sf.samplerate <= 0) throw InputError(file.string() + ": sample rate 0 in the header; the file is damaged");
    if (options.sample_rate_hz && std::abs(*options.sample_rate_hz - sf.samplerate) > 1e-6 * sf.samplerate) {
      std::ostringstream os;
      os << file.string() << ": the manifest says sample_rate_hz = " << *options.sample_rate_hz
         << " but the file says " << sf.samplerate << " Hz; remove sample_rate_hz from the manifest";
      throw InputError(os.str());
    }
    if (sf.frames <= 0) throw InputError(file.string() + ": the recording holds no samples");
    if (options.time_column)
      throw InputError(file.string() + ": the manifest names time_column '" + *options.time_column +
                       "' but an audio file has no columns; remove time_column");
  }
  SndfileReader(const SndfileReader&) = delete;
  SndfileReader& operator=(const SndfileReader&) = delete;

  std::size_t read(std::span<double> out) override {
    const auto want = static_cast<sf_count_t>(out.size() / static_cast<std::size_t>(info_.channels));
    if (want == 0 || position_ >= info_.frames) return 0;
    const sf_count_t got = sf_readf_double(handle_.get(), out.data(), want);
    position_ += static_cast<std::uint64_t>(std::max<sf_count_t>(got, 0));
    if (sf_error(handle_.get()) != SF_ERR_NO_ERROR || (got < want && position_ < info_.frames))
      throw InputError(info_.file.string() + ": truncated or damaged recording: reading stopped at frame " +
                       std::to_string(position_) + " of " + std::to_string(info_.frames) +
                       " (time " + std::to_string(static_cast<double>(position_) / info_.sample_rate_hz) +
                       " s); copy the file again from the DAQ");
    return static_cast<std::size_t>(got);
  }

  void rewind() override {
    if (sf_seek(handle_.get(), 0, SEEK_SET) != 0)
      // On a regular file this means the stream cannot be decoded again from
      // the start (seen with FLAC cut short after its first frames).
      throw InputError(info_.file.string() + ": truncated or damaged recording: cannot seek back to the start (" +
                       sf_strerror(handle_.get()) + "); copy the file again from the DAQ");
    position_ = 0;
  }

 private:
  // Owned, so that a constructor that throws after sf_open (sample rate 0,
  // no frames, a rate the manifest contradicts) closes it too: those paths
  // leaked libsndfile's state (found by fuzzing, issue 7).
  std::unique_ptr<SNDFILE, int (*)(SNDFILE*)> handle_{nullptr, sf_close};
  std::uint64_t position_ = 0;
};

}  // namespace

bool sndfile_claims(const std::filesystem::path&, std::span<const unsigned char> head) {
  if ((starts_with(head, 0, "RIFF") || starts_with(head, 0, "RIFX")) && starts_with(head, 8, "WAVE")) return true;
  if (starts_with(head, 0, "RF64") || starts_with(head, 0, "BW64")) return true;
  if (starts_with(head, 0, "riff") && head.size() >= 16) return true;  // W64: a GUID starting "riff"
  if (starts_with(head, 0, "fLaC") || starts_with(head, 0, "caff")) return true;
  if (starts_with(head, 0, "FORM") && (starts_with(head, 8, "AIFF") || starts_with(head, 8, "AIFC"))) return true;
  return false;
}

std::unique_ptr<Reader> open_sndfile_reader(const std::filesystem::path& file, const ReaderOptions& options) {
  return std::make_unique<SndfileReader>(file, options);
}

}  // namespace fourbar
