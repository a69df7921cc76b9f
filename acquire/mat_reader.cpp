#include "acquire/mat_reader.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <new>
#include <optional>
#include <string_view>

#include "acquire/mat_contents.hpp"
#include "common/child_process.hpp"
#include "common/error.hpp"

namespace fourbar {

namespace {

class MatRecording final : public Reader {
 public:
  explicit MatRecording(MatContents c) : columns_(std::move(c.columns)) { info_ = std::move(c.info); }

  std::size_t read(std::span<double> out) override {
    const std::size_t channels = columns_.size();
    const std::size_t n = std::min<std::size_t>(out.size() / channels, info_.frames - position_);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < channels; ++c) out[i * channels + c] = columns_[c][position_ + i];
    position_ += n;
    return n;
  }

  void rewind() override { position_ = 0; }

 private:
  std::vector<std::vector<double>> columns_;
  std::uint64_t position_ = 0;
};

// What the child sends back: a tag, then the contents or an error message.
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

// A field added to RecordingInfo must be sent from the child too (encode,
// decode) — or the v7.3 path would drop it silently. (Size on x86-64 with
// libstdc++, the platform fourbar builds on.)
static_assert(sizeof(RecordingInfo) == 248, "RecordingInfo changed: send the new field in encode() and decode()");

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

/// The child's side: read the file, send the contents or the error.
std::string read_and_encode(const std::filesystem::path& file, const ReaderOptions& options) {
  auto error = [](Tag tag, const char* what) { return static_cast<char>(tag) + std::string(what); };
  try {
    return encode(read_mat_contents(file, options));
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

/// A v7.3 file, read in a child process (common/child_process.hpp). libhdf5
/// 1.10 (Debian 12) overflows heap blocks on damaged files (fuzzing:
/// tests/fuzz/regressions/mat/v73_attribute_heap_overflow_in_libhdf5.mat.bin)
/// and fourbar cannot check an HDF5 file's structure before it as it does a
/// v5 file's; in the child, a crash, a hang or corrupted memory ends there.
/// Errors the reading raises in the child are raised here unchanged; the
/// contents arrive bit for bit.
MatContents read_v73_isolated(const std::filesystem::path& file, const ReaderOptions& options) {
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(file, ec);
  // A minute, and a second more per MB: reading and sending a valid file
  // takes a small part of that even on a loaded machine.
  const std::chrono::milliseconds limit(60'000 + (ec ? 0 : static_cast<std::int64_t>(bytes / 1000)));
  const ChildResult res = run_in_child_process([&] { return read_and_encode(file, options); }, limit);
  const std::string f = file.string();
  const auto damaged = [&](const std::string& how) {
    return InputError(f + ": reading this MATLAB v7.3 (HDF5) file went wrong inside libmatio/libhdf5 — the reading "
                          "process " + how + ": the file is damaged; copy the file again, or re-save it from MATLAB "
                          "(save -v7.3, or -v7)");
  };
  if (!res.ok) throw damaged(res.failure);
  if (res.bytes.empty()) throw damaged("sent nothing");
  const std::string message = res.bytes.substr(1);
  switch (static_cast<Tag>(res.bytes[0])) {
    case kContents:
      if (auto c = decode(res.bytes, file)) return std::move(*c);
      throw damaged("sent garbled data");
    case kInputError: throw InputError(message);
    case kRunError: throw RunError(message);
    case kNoMemory: throw std::bad_alloc();
    case kOther: throw std::runtime_error(message);
  }
  throw damaged("sent garbled data");
}

}  // namespace

bool mat_claims(const std::filesystem::path& file, std::span<const unsigned char> head) {
  static constexpr char kMagic[] = "MATLAB ";
  if (head.size() >= 7 && std::memcmp(head.data(), kMagic, 7) == 0) return true;
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".mat";
}

std::unique_ptr<Reader> open_mat_reader(const std::filesystem::path& file, const ReaderOptions& options) {
  // v5 (and the v4 refusal) stay in this process: what fuzzing found in
  // libmatio's v5 code (sizes the file cannot hold, read as gigabytes to
  // allocate) is refused before libmatio reads the file — v5_damage in
  // mat_contents.cpp walks every element and inflates each compressed
  // variable's header with zlib — and the campaigns since found no memory
  // error there. An HDF5 file's object headers cannot be checked so
  // without a second HDF5 parser: v7.3 goes to a child process (above).
  if (mat_header_version(file) == 0x0200) return std::make_unique<MatRecording>(read_v73_isolated(file, options));
  return std::make_unique<MatRecording>(read_mat_contents(file, options));
}

}  // namespace fourbar
