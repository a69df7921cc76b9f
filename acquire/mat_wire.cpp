#include "acquire/mat_wire.hpp"

#include <cstdint>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string_view>

#include "common/error.hpp"

namespace fourbar {

namespace {

// What fourbar-read-mat sends back: a tag, then the contents or an error message.
// Numbers as their bytes (doubles bit for bit), strings and vectors as a
// count then their elements.
enum Tag : std::uint8_t { kContents = 'C', kInputError = 'I', kRunError = 'R', kNoMemory = 'M', kOther = 'X' };

struct WireOut {
  std::string s;
  void u64(std::uint64_t v) { s.append(reinterpret_cast<const char*>(&v), sizeof v); }
  void f64(double v) { s.append(reinterpret_cast<const char*>(&v), sizeof v); }
  void str(const std::string& v) { u64(v.size()), s += v; }
  void strs(const std::vector<std::string>& v) {
    u64(v.size());
    for (const auto& x : v) str(x);
  }
};

/// Reads what WireOut wrote; any read past the end sets `bad` (the data are then garbled).
struct WireIn {
  std::string_view s;
  std::size_t at = 0;
  bool bad = false;
  bool take(void* out, std::size_t n) {
    if (bad || n > s.size() - at) return !(bad = true);
    std::memcpy(out, s.data() + at, n);
    at += n;
    return true;
  }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    take(&v, sizeof v);
    return v;
  }
  double f64() {
    double v = 0;
    take(&v, sizeof v);
    return v;
  }
  std::string str() {
    const std::uint64_t n = u64();
    if (bad || n > s.size() - at) return (bad = true), std::string();
    std::string v(s.substr(at, n));
    at += n;
    return v;
  }
  std::vector<std::string> strs() {
    std::vector<std::string> v;
    for (std::uint64_t n = u64(); !bad && n > 0; --n) v.push_back(str());
    return v;
  }
};

// A field added to RecordingInfo must be sent by fourbar-read-mat too (encode,
// decode) — or the MATLAB path would drop it silently. (Size on x86-64 with
// libstdc++, the platform fourbar builds on.)
static_assert(sizeof(RecordingInfo) == 280, "RecordingInfo changed: send the new field in encode() and decode()");

std::string encode(const MatContents& c) {
  WireOut w;
  w.s.push_back(static_cast<char>(kContents));
  const RecordingInfo& i = c.info;
  w.str(i.format), w.str(i.sample_format);
  w.u64(static_cast<std::uint64_t>(static_cast<std::int64_t>(i.integer_bits)));
  w.u64(static_cast<std::uint64_t>(static_cast<std::int64_t>(i.channels)));
  w.f64(i.sample_rate_hz), w.u64(i.frames), w.f64(i.start_time_s);
  w.strs(i.channel_names), w.strs(i.channel_units);
  w.u64(i.rate_variable ? 1 : 0);
  if (i.rate_variable) w.str(*i.rate_variable);
  w.strs(i.notes);
  w.str(i.started_at);
  w.u64(c.columns.size());
  for (const auto& col : c.columns) {
    w.u64(col.size());
    w.s.append(reinterpret_cast<const char*>(col.data()), col.size() * sizeof(double));
  }
  return w.s;
}

/// The contents, or nothing when the bytes are not exactly one encoded,
/// self-consistent MatContents.
std::optional<MatContents> decode(std::string_view bytes, const std::filesystem::path& file) {
  WireIn r{bytes.substr(1)};
  MatContents c;
  RecordingInfo& i = c.info;
  i.file = file;
  i.format = r.str(), i.sample_format = r.str();
  i.integer_bits = static_cast<int>(static_cast<std::int64_t>(r.u64()));
  i.channels = static_cast<int>(static_cast<std::int64_t>(r.u64()));
  i.sample_rate_hz = r.f64(), i.frames = r.u64(), i.start_time_s = r.f64();
  i.channel_names = r.strs(), i.channel_units = r.strs();
  if (r.u64() == 1) i.rate_variable = r.str();
  i.notes = r.strs();
  i.started_at = r.str();
  for (std::uint64_t n = r.u64(); !r.bad && n > 0; --n) {
    const std::uint64_t len = r.u64();
    if (r.bad || len > (r.s.size() - r.at) / sizeof(double)) return std::nullopt;
    std::vector<double> col(len);
    r.take(col.data(), len * sizeof(double));
    c.columns.push_back(std::move(col));
  }
  if (r.bad || r.at != r.s.size() || i.channels < 1 || c.columns.size() != static_cast<std::size_t>(i.channels) ||
      i.channel_names.size() != c.columns.size())
    return std::nullopt;
  for (const auto& col : c.columns)
    if (col.size() != i.frames) return std::nullopt;
  return c;
}

}  // namespace

std::string encode_mat_result(const std::function<MatContents()>& read) {
  auto error = [](Tag tag, const char* what) { return static_cast<char>(tag) + std::string(what); };
  try {
    return encode(read());
  } catch (const InputError& e) {
    return error(kInputError, e.what());
  } catch (const RunError& e) {
    return error(kRunError, e.what());
  } catch (const std::bad_alloc&) {
    return error(kNoMemory, "");
  } catch (const std::exception& e) {
    return error(kOther, e.what());
  }
}

std::optional<MatContents> decode_mat_result(std::string_view bytes, const std::filesystem::path& file) {
  if (bytes.empty()) return std::nullopt;
  const std::string message(bytes.substr(1));
  switch (static_cast<Tag>(bytes[0])) {
    case kContents: return decode(bytes, file);
    case kInputError: throw InputError(message);
    case kRunError: throw RunError(message);
    case kNoMemory: throw std::bad_alloc();
    case kOther: throw std::runtime_error(message);
  }
  return std::nullopt;
}

}  // namespace fourbar
