#include "common/atomic_output.hpp"

#include <unistd.h>

#include <system_error>

#include "common/error.hpp"

namespace fourbar {

AtomicOutput::AtomicOutput(std::filesystem::path path, bool binary) : path_(std::move(path)) {
  tmp_ = path_;
  tmp_ += ".tmp-" + std::to_string(::getpid());
  out_.open(tmp_, binary ? std::ios::out | std::ios::binary | std::ios::trunc : std::ios::out | std::ios::trunc);
  if (!out_) throw RunError(path_.string() + ": cannot create output file (is the folder writable?)");
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
  }
}

void AtomicOutput::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok) throw RunError(path_.string() + ": write failed (disk full?); nothing was written");
  std::error_code ec;
  std::filesystem::rename(tmp_, path_, ec);
  if (ec) throw RunError(path_.string() + ": cannot move output into place: " + ec.message());
  committed_ = true;
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  AtomicOutput out(path);
  out.stream() << text;
  out.commit();
}

void ensure_output_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError(dir.string() + ": cannot create output folder (" +
                     (ec ? ec.message() : std::string("a file of that name exists")) + "); choose another --out");
}

}  // namespace fourbar
