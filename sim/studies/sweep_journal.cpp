#include "sim/studies/sweep_journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "common/error.hpp"

namespace fourbar {

namespace {

std::string header_line(const std::string& fingerprint, std::size_t points) {
  return "# fourbar sweep journal " + fingerprint + " " + std::to_string(points) + " points\n";
}

void write_all(int fd, const std::string& text, const std::filesystem::path& path) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw RunError(path.string() + ": cannot write the sweep journal (" + std::strerror(errno) + ")");
    done += static_cast<std::size_t>(n);
  }
  if (::fdatasync(fd) != 0)
    throw RunError(path.string() + ": cannot write the sweep journal (" + std::strerror(errno) + ")");
}

}  // namespace

std::string fingerprint_of(const std::string& text) {
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

SweepJournal::SweepJournal(std::filesystem::path path, std::string fingerprint, std::size_t points)
    : path_(std::move(path)) {
  const std::string header = header_line(fingerprint, points);
  bool resume = false;
  if (std::ifstream in{path_, std::ios::binary}) {
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    resume = text.starts_with(header);
    discarded_stale_ = !resume;
    // Only complete lines count: the last one may have been cut by the kill.
    std::size_t at = resume ? header.size() : text.size();
    while (at < text.size()) {
      const std::size_t end = text.find('\n', at);
      if (end == std::string::npos) break;
      const std::string_view line(text.data() + at, end - at);
      std::size_t index = 0;
      const auto [rest, ec] = std::from_chars(line.data(), line.data() + line.size(), index);
      if (ec == std::errc() && rest < line.data() + line.size() && *rest == '\t' && index < points)
        finished_.emplace(index, std::string(rest + 1, line.data() + line.size()));
      at = end + 1;
    }
  }
  // Rewritten whole (atomically) with the complete lines only, then appended to.
  std::string clean = header;
  for (const auto& [i, r] : finished_) clean += std::to_string(i) + "\t" + r + "\n";
  const std::filesystem::path tmp = path_.string() + ".tmp-" + std::to_string(::getpid());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw RunError(tmp.string() + ": cannot create the sweep journal (" + std::strerror(errno) + ")");
  try {
    write_all(fd, clean, tmp);
  } catch (...) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw;
  }
  ::close(fd);
  std::error_code ec;
  std::filesystem::rename(tmp, path_, ec);
  if (ec) throw RunError(path_.string() + ": cannot write the sweep journal (" + ec.message() + ")");
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) throw RunError(path_.string() + ": cannot open the sweep journal (" + std::strerror(errno) + ")");
}

SweepJournal::~SweepJournal() {
  if (fd_ >= 0) ::close(fd_);
}

void SweepJournal::append(std::size_t index, const std::string& encoded_result) {
  write_all(fd_, std::to_string(index) + "\t" + encoded_result + "\n", path_);
}

void SweepJournal::remove() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::error_code ec;
  std::filesystem::remove(path_, ec);
}

}  // namespace fourbar
