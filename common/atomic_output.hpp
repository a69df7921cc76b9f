#pragma once
// An output file that appears under its final name only when complete:
// written to a temporary file beside it and renamed on commit(). An
// interrupted run leaves no half file that looks finished: SIGINT, SIGTERM
// and SIGHUP remove the temporary files still open before the process ends
// (InterruptCleanup); a crash or SIGKILL may leave a `NAME.tmp-PID` file,
// never a file under the final name.

#include <filesystem>
#include <fstream>

namespace fourbar {

/// While alive, `path` is removed if the process is ended by SIGINT, SIGTERM
/// or SIGHUP (handlers installed on first use where the signal's disposition
/// is the default; the signal then ends the process as before). For the
/// temporary files of outputs not yet committed.
class InterruptCleanup {
 public:
  explicit InterruptCleanup(const std::filesystem::path& path);
  InterruptCleanup(const InterruptCleanup&) = delete;
  InterruptCleanup& operator=(const InterruptCleanup&) = delete;
  ~InterruptCleanup();

 private:
  int slot_ = -1;
};

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
  InterruptCleanup cleanup_;  // after tmp_: removes it on SIGINT/SIGTERM/SIGHUP until commit
  std::ofstream out_;
  bool committed_ = false;
};

/// Writes a whole text file atomically.
void write_text_file(const std::filesystem::path& path, const std::string& text);

/// Creates `dir` (and parents); InputError naming it when that fails.
void ensure_output_dir(const std::filesystem::path& dir);

}  // namespace fourbar
