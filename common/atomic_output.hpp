#pragma once
// An output file that appears under its final name only when complete:
// written to a temporary file beside it and renamed on commit(). An
// interrupted run leaves no half file that looks finished.

#include <filesystem>
#include <fstream>

namespace fourbar {

class AtomicOutput {
 public:
  explicit AtomicOutput(std::filesystem::path path, bool binary = false);
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicOutput();

  std::ofstream& stream() { return out_; }
  /// Flushes, checks for write errors and renames into place (RunError on failure).
  void commit();

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::filesystem::path tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Writes a whole text file atomically.
void write_text_file(const std::filesystem::path& path, const std::string& text);

/// Creates `dir` (and parents); InputError naming it when that fails.
void ensure_output_dir(const std::filesystem::path& dir);

}  // namespace fourbar
