#include "acquire/tdms_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>

#include "acquire/tdms_structure.hpp"
#include "common/error.hpp"
#include "common/number_text.hpp"

namespace fourbar {

namespace {

std::string object_label(const TdmsObject& o) { return "'" + o.group + "/" + o.channel + "'"; }

/// The channel's sample rate from wf_increment (0 when it has none).
double rate_of(const TdmsObject& o) {
  const TdmsProperty* p = o.property("wf_increment");
  return p && p->number && *p->number > 0 && std::isfinite(1.0 / *p->number) ? 1.0 / *p->number : 0.0;
}

std::string unit_of(const TdmsObject& o) {
  for (const char* key : {"unit_string", "NI_UnitDescription"})
    if (const TdmsProperty* p = o.property(key); p && p->type == tdms_type::kString && !p->text.empty()) return p->text;
  return "";
}

double value_of(const unsigned char* b, std::uint32_t type, bool big) {
  const std::uint32_t n = tdms_type_size(type);
  unsigned char v[8];
  for (std::uint32_t i = 0; i < n; ++i) v[i] = b[big ? n - 1 - i : i];  // to little-endian
  std::uint64_t u = 0;
  for (std::uint32_t i = n; i-- > 0;) u = u << 8 | v[i];
  using namespace tdms_type;
  switch (type) {
    case kI8: return static_cast<std::int8_t>(u);
    case kI16: return static_cast<std::int16_t>(u);
    case kI32: return static_cast<std::int32_t>(u);
    case kI64: return static_cast<double>(static_cast<std::int64_t>(u));
    case kU8: case kU16: case kU32: case kU64: return static_cast<double>(u);
    case kBool: return u != 0 ? 1.0 : 0.0;
    case kSingle: case kSingleWithUnit: {
      const auto bits = static_cast<std::uint32_t>(u);
      float f;
      std::memcpy(&f, &bits, 4);
      return f;
    }
    default: {
      double d;
      std::memcpy(&d, &u, 8);
      return d;
    }
  }
}

class TdmsReader final : public Reader {
 public:
  TdmsReader(const std::filesystem::path& file, const ReaderOptions& options) : file_(file) {
    TdmsStructure s = read_tdms_structure(file);
    info_.file = file;
    info_.format = "TDMS";
    info_.notes = std::move(s.notes);
    const std::string f = file.string();

    // The recording: numeric channels of the longest length, at the rate of the first of them.
    std::vector<const TdmsObject*> numeric;
    for (const auto& o : s.objects) {
      if (o.channel.empty() || o.values == 0) continue;
      if (tdms_type_is_numeric(o.type)) numeric.push_back(&o);
      else info_.notes.push_back("channel " + object_label(o) + " (" + tdms_type_name(o.type) + ", " +
                                 std::to_string(o.values) + " values) is not numeric: not a channel");
    }
    if (numeric.empty())
      throw InputError(f + ": no channel with numeric data (integers, float, double or bool) in " +
                       std::to_string(s.objects.size()) + " TDMS objects; it holds no recording fourbar can use");
    std::uint64_t longest = 0;
    for (const auto* o : numeric) longest = std::max(longest, o->values);
    double rate = -1;
    for (const auto* o : numeric) {
      const double r = rate_of(*o);
      if (o->values != longest) {
        info_.notes.push_back("channel " + object_label(*o) + ": " + std::to_string(o->values) + " values" +
                              (r > 0 ? " at " + format_double(r) + " Hz" : "") + ", not the recording's " +
                              std::to_string(longest) + ": not a channel");
      } else if (rate >= 0 && std::abs(r - rate) > 1e-9 * std::max(r, rate)) {
        info_.notes.push_back("channel " + object_label(*o) + ": " + (r > 0 ? format_double(r) + " Hz" : "no wf_increment") +
                              ", not the recording's " + (rate > 0 ? format_double(rate) + " Hz" : "rate") + ": not a channel");
      } else {
        rate = r;
        channels_.push_back(*o);
      }
    }
    if (options.sample_rate_hz) {
      const double given = *options.sample_rate_hz;
      if (!(given > 0) || !std::isfinite(given))
        throw InputError(f + ": sample rate " + format_double(given) + " Hz from the manifest must be positive");
      if (rate > 0 && std::abs(given - rate) > 1e-9 * rate)
        throw InputError(f + ": the manifest's sample_rate_hz = " + format_double(given) + " contradicts the file's " +
                         format_double(rate) + " Hz (wf_increment of channel " + object_label(channels_.front()) +
                         "); delete sample_rate_hz from the manifest");
      rate = given;
    }
    if (!(rate > 0))
      throw InputError(f + ": channel " + object_label(channels_.front()) + " has no wf_increment property, so the "
                       "file does not state its sample rate; give sample_rate_hz in the manifest");
    info_.sample_rate_hz = rate;
    info_.frames = longest;
    info_.channels = static_cast<int>(channels_.size());
    if (const TdmsProperty* p = channels_.front().property("wf_start_offset"); p && p->number && std::isfinite(*p->number))
      info_.start_time_s = *p->number;
    if (const TdmsProperty* p = channels_.front().property("wf_start_time"); p && p->type == tdms_type::kTimeStamp)
      info_.started_at = p->text;

    std::map<std::string, int> uses;
    for (const auto& o : channels_) ++uses[o.channel];
    bool any_unit = false;
    std::uint32_t type = channels_.front().type;
    for (const auto& o : channels_) {
      info_.channel_names.push_back(uses[o.channel] > 1 ? o.group + "/" + o.channel : o.channel);
      info_.channel_units.push_back(unit_of(o));
      any_unit = any_unit || !info_.channel_units.back().empty();
      if (o.type != type) type = 0;
      if (o.property("NI_Number_Of_Scales"))
        info_.notes.push_back("channel " + object_label(o) + ": NI scaling properties (NI_Scale…) not applied: values as stored");
    }
    if (!any_unit) info_.channel_units.clear();
    info_.sample_format = type == 0 ? "MIXED" : tdms_type_name(type);
    for (const auto& o : channels_) {
      std::vector<std::uint64_t> starts{0};
      for (const auto& p : o.pieces) starts.push_back(starts.back() + p.values());
      starts_.push_back(std::move(starts));
    }
    in_.open(file, std::ios::binary);
    if (!in_) throw InputError(f + ": cannot open (check the path and permissions)");
  }

  std::size_t read(std::span<double> out) override {
    const auto channels = static_cast<std::size_t>(info_.channels);
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(out.size() / channels, info_.frames - position_));
    for (std::size_t c = 0; c < channels; ++c) read_channel(c, n, out);
    position_ += n;
    return n;
  }

  void rewind() override { position_ = 0; }

 private:
  void read_channel(std::size_t c, std::size_t n, std::span<double> out) {
    const TdmsObject& o = channels_[c];
    const auto& starts = starts_[c];
    const auto channels = static_cast<std::size_t>(info_.channels);
    const std::uint32_t size = tdms_type_size(o.type);
    std::uint64_t j = position_;
    std::size_t done = 0;
    auto piece_it = std::upper_bound(starts.begin(), starts.end(), j) - 1;
    auto p = static_cast<std::size_t>(piece_it - starts.begin());
    while (done < n) {
      const TdmsPiece& piece = o.pieces[p];
      const std::uint64_t local = j - starts[p];
      if (local >= piece.values()) {
        ++p;
        continue;
      }
      const std::uint64_t chunk = local / piece.values_per_chunk, k = local % piece.values_per_chunk;
      const std::size_t m = static_cast<std::size_t>(std::min<std::uint64_t>(n - done, piece.values_per_chunk - k));
      const std::uint64_t offset = piece.offset + chunk * piece.chunk_bytes + k * piece.stride;
      const std::size_t bytes = (m - 1) * piece.stride + size;
      buffer_.resize(bytes);
      in_.clear();
      in_.seekg(static_cast<std::streamoff>(offset));
      if (!in_.read(reinterpret_cast<char*>(buffer_.data()), static_cast<std::streamsize>(bytes)))
        throw InputError(file_.string() + ": cannot read channel " + object_label(o) + " at byte " +
                         std::to_string(offset) + " (the file changed or is damaged); copy it again");
      for (std::size_t i = 0; i < m; ++i)
        out[(done + i) * channels + c] = value_of(buffer_.data() + i * piece.stride, o.type, piece.big_endian);
      done += m;
      j += m;
    }
  }

  std::filesystem::path file_;
  std::vector<TdmsObject> channels_;
  std::vector<std::vector<std::uint64_t>> starts_;  ///< per channel: first value of each piece, then the total
  std::ifstream in_;
  std::vector<unsigned char> buffer_;
  std::uint64_t position_ = 0;
};

}  // namespace

bool tdms_claims(const std::filesystem::path& file, std::span<const unsigned char> head) {
  if (head.size() >= 4 && (std::memcmp(head.data(), "TDSm", 4) == 0 || std::memcmp(head.data(), "TDSh", 4) == 0))
    return true;
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".tdms" || ext == ".tdms_index";
}

std::unique_ptr<Reader> open_tdms_reader(const std::filesystem::path& file, const ReaderOptions& options) {
  return std::make_unique<TdmsReader>(file, options);
}

}  // namespace fourbar
