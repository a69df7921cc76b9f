#include "acquire/riff_structure.hpp"

#include <array>
#include <cstring>
#include <fstream>
#include <map>

#include "common/error.hpp"

namespace fourbar {

namespace {

constexpr std::uint32_t kSizeInDs64 = 0xFFFFFFFFu;
constexpr std::array<unsigned char, 16> kW64Riff = {'r', 'i', 'f', 'f', 0x2E, 0x91, 0xCF, 0x11,
                                                    0xA5, 0xD6, 0x28, 0xDB, 0x04, 0xC1, 0x00, 0x00};
constexpr std::array<unsigned char, 16> kW64Wave = {'w', 'a', 'v', 'e', 0xF3, 0xAC, 0xD3, 0x11,
                                                    0x8C, 0xD1, 0x00, 0xC0, 0x4F, 0x8E, 0xDB, 0x8A};

/// Random access to the file's bytes, in the container's byte order.
class Bytes {
 public:
  explicit Bytes(const std::filesystem::path& file) : in_(file, std::ios::binary) {
    if (!in_) throw InputError(file.string() + ": cannot open (check the permissions)");
    in_.seekg(0, std::ios::end);
    size_ = static_cast<std::uint64_t>(in_.tellg());
  }
  std::uint64_t size() const { return size_; }
  bool big_endian = false;

  /// `n` bytes at `at`; false when the file ends before.
  bool read(std::uint64_t at, unsigned char* out, std::size_t n) {
    if (at > size_ || n > size_ - at) return false;
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(at));
    in_.read(reinterpret_cast<char*>(out), static_cast<std::streamsize>(n));
    return static_cast<std::size_t>(in_.gcount()) == n;
  }
  std::uint64_t uint(const unsigned char* p, int bytes) const {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= std::uint64_t{p[big_endian ? bytes - 1 - i : i]} << (8 * i);
    return v;
  }

 private:
  std::ifstream in_;
  std::uint64_t size_ = 0;
};

std::string fourcc(const unsigned char* p) {
  std::string s;
  for (int i = 0; i < 4; ++i) {
    const unsigned char c = p[i];
    if (c >= 0x20 && c < 0x7F) {
      s += static_cast<char>(c);
    } else {
      static const char* hex = "0123456789abcdef";
      s += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    }
  }
  return "'" + s + "'";
}

bool printable(const unsigned char* p) {
  for (int i = 0; i < 4; ++i)
    if (p[i] < 0x20 || p[i] >= 0x7F) return false;
  return true;
}

std::string at_byte(std::uint64_t pos) { return " at byte " + std::to_string(pos); }

std::string declares(std::uint64_t size) { return " declares " + std::to_string(size) + " bytes"; }

/// The sub-chunks of the LIST chunk whose body is [begin, end): each inside.
std::optional<RiffDefect> walk_list(Bytes& b, std::uint64_t list_pos, std::uint64_t begin, std::uint64_t end) {
  if (end - begin < 4)
    return RiffDefect{false, "the LIST chunk" + at_byte(list_pos) + " is too short to name its type"};
  unsigned char type[4];
  b.read(begin, type, 4);
  for (std::uint64_t pos = begin + 4; pos < end;) {
    unsigned char h[8];
    if (end - pos < 8 || !b.read(pos, h, 8))
      return RiffDefect{false, "the LIST " + fourcc(type) + " chunk" + at_byte(list_pos) + " ends with " +
                                   std::to_string(end - pos) + " bytes that are no sub-chunk"};
    const std::uint64_t size = b.uint(h + 4, 4);
    if (size > end - pos - 8)
      return RiffDefect{false, "sub-chunk " + fourcc(h) + at_byte(pos) + " of LIST " + fourcc(type) + declares(size) +
                                   " but its LIST holds only " + std::to_string(end - pos - 8) + " after it"};
    pos += 8 + size + (size & 1);
  }
  return std::nullopt;
}

/// Top-level chunks from `pos` on. Chunks starting before `declared_end`
/// (the container's end) must end by it; those after it are walked while
/// their identifiers are printable.
std::optional<RiffDefect> walk_riff(Bytes& b, std::uint64_t pos, std::uint64_t declared_end, bool rf64,
                                    const std::map<std::string, std::uint64_t>& ds64_sizes) {
  const std::uint64_t file_end = b.size();
  while (file_end - pos >= 8) {
    unsigned char h[8];
    b.read(pos, h, 8);
    if (pos < declared_end && declared_end - pos < 8) declared_end = pos;  // no room for a chunk: trailing bytes
    const bool inside = pos < declared_end;
    if (!inside && !printable(h)) break;
    std::uint64_t size = b.uint(h + 4, 4);
    const std::string id(reinterpret_cast<const char*>(h), 4);
    if (rf64 && size == kSizeInDs64) {
      const auto it = ds64_sizes.find(id);
      if (it == ds64_sizes.end())
        return RiffDefect{false, "chunk " + fourcc(h) + at_byte(pos) +
                                     " leaves its size to the ds64 chunk, which gives none for it"};
      size = it->second;
    }
    const std::uint64_t end = inside ? declared_end : file_end;
    if (size > end - pos - 8) {
      if (end == file_end)
        return RiffDefect{true, "chunk " + fourcc(h) + at_byte(pos) + declares(size) + " but the file holds only " +
                                    std::to_string(file_end - pos - 8) + " after it"};
      return RiffDefect{false, "chunk " + fourcc(h) + at_byte(pos) + declares(size) +
                                   " but the container's size leaves it only " + std::to_string(end - pos - 8)};
    }
    if (id == "LIST")
      if (auto d = walk_list(b, pos, pos + 8, pos + 8 + size)) return d;
    pos += 8 + size + (size & 1);
    if (pos > file_end) break;  // the last chunk's pad byte may be missing
  }
  return std::nullopt;
}

std::optional<RiffDefect> walk_wave(Bytes& b, const unsigned char* head, bool rf64) {
  const std::uint64_t file_size = b.size();
  std::uint64_t riff_size = b.uint(head + 4, 4);
  std::map<std::string, std::uint64_t> ds64_sizes;
  std::uint64_t pos = 12;
  if (rf64) {
    unsigned char h[36];
    if (!b.read(12, h, 8) || std::memcmp(h, "ds64", 4) != 0)
      return RiffDefect{false, "an RF64 file must start with a ds64 chunk" + at_byte(12) + ", this one does not"};
    if (!b.read(12, h, 36))
      return RiffDefect{true, "the file ends inside its ds64 chunk" + at_byte(12)};
    const std::uint64_t ds_size = b.uint(h + 4, 4);
    const std::uint64_t table = b.uint(h + 32, 4);
    if (ds_size < 28 || ds_size > file_size - 20 || (ds_size - 28) / 12 < table)
      return RiffDefect{false, "the ds64 chunk" + at_byte(12) + declares(ds_size) + " for a table of " +
                                   std::to_string(table) + " entries (needs 28 + 12 per entry, inside the file)"};
    if (riff_size == kSizeInDs64) riff_size = b.uint(h + 8, 8);
    ds64_sizes["data"] = b.uint(h + 16, 8);
    for (std::uint64_t i = 0; i < table; ++i) {
      unsigned char e[12];
      b.read(48 + 12 * i, e, 12);
      ds64_sizes[std::string(reinterpret_cast<const char*>(e), 4)] = b.uint(e + 4, 8);
    }
    pos = 20 + ds_size + (ds_size & 1);
  }
  if (riff_size < 4 || riff_size > file_size - 8)
    return RiffDefect{riff_size >= 4, "its header" + declares(riff_size + 8) + " of " + (rf64 ? "RF64" : "RIFF") +
                                          " data but the file holds " + std::to_string(file_size)};
  return walk_riff(b, pos, 8 + riff_size, rf64, ds64_sizes);
}

std::optional<RiffDefect> walk_w64(Bytes& b) {
  const std::uint64_t file_size = b.size();
  unsigned char h[24];
  b.read(16, h, 8);
  const std::uint64_t declared_end = b.uint(h, 8);
  if (declared_end < 40 || declared_end > file_size)
    return RiffDefect{declared_end >= 40, "its header" + declares(declared_end) + " of Wave64 data but the file holds " +
                                              std::to_string(file_size)};
  for (std::uint64_t pos = 40; file_size - pos >= 24;) {
    b.read(pos, h, 24);
    const bool inside = pos < declared_end;
    if (!inside && !printable(h)) break;
    const std::uint64_t size = b.uint(h + 16, 8);
    const std::uint64_t end = inside ? declared_end : file_size;
    if (size < 24)
      return RiffDefect{false, "chunk " + fourcc(h) + at_byte(pos) + declares(size) +
                                   ", less than its own 24-byte header"};
    if (size > end - pos)
      return RiffDefect{end == file_size, "chunk " + fourcc(h) + at_byte(pos) + declares(size) +
                                              (end == file_size ? " but the file holds only "
                                                                : " but the container's size leaves it only ") +
                                              std::to_string(end - pos)};
    pos += size + (8 - size % 8) % 8;
    if (pos > file_size) break;  // the last chunk's alignment may be missing
  }
  return std::nullopt;
}

}  // namespace

std::optional<RiffDefect> riff_structure_defect(const std::filesystem::path& file) {
  Bytes b(file);
  unsigned char head[40] = {};
  const bool full = b.read(0, head, sizeof head);
  const bool riff = std::memcmp(head, "RIFF", 4) == 0, rifx = std::memcmp(head, "RIFX", 4) == 0;
  const bool rf64 = std::memcmp(head, "RF64", 4) == 0 || std::memcmp(head, "BW64", 4) == 0;
  if ((riff || rifx || rf64) && b.size() >= 12 && std::memcmp(head + 8, "WAVE", 4) == 0) {
    b.big_endian = rifx;
    return walk_wave(b, head, rf64);
  }
  if (full && std::memcmp(head, kW64Riff.data(), 16) == 0 && std::memcmp(head + 24, kW64Wave.data(), 16) == 0)
    return walk_w64(b);
  return std::nullopt;
}

}  // namespace fourbar
