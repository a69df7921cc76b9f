#pragma once
// The journal of a sweep in progress, OUT.journal beside the table: one line
// per finished grid point, appended (one write, then fdatasync) the moment it
// finishes. A sweep that is interrupted (Ctrl-C, a killed job, a dead MPI
// rank, a node lost) and started again with the same inputs reads the
// finished points back, bit for bit, and computes only the rest. A torn last
// line is recomputed. The journal is removed once the table is written.

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>

namespace fourbar {

class SweepJournal {
 public:
  /// Opens (creating) `path`. `fingerprint` identifies the inputs (sweep,
  /// scene and rig files, the grid, the version): an existing journal with
  /// another fingerprint or another point count is from other inputs and is
  /// started afresh (`discarded_stale()` says so). RunError if it cannot be written.
  SweepJournal(std::filesystem::path path, std::string fingerprint, std::size_t points);
  ~SweepJournal();
  SweepJournal(const SweepJournal&) = delete;
  SweepJournal& operator=(const SweepJournal&) = delete;

  /// Points finished by earlier runs: index → encoded result.
  const std::map<std::size_t, std::string>& finished() const { return finished_; }
  bool discarded_stale() const { return discarded_stale_; }

  /// Records a finished point (durable when this returns).
  void append(std::size_t index, const std::string& encoded_result);
  /// Removes the journal (after the table has been committed).
  void remove();

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::map<std::size_t, std::string> finished_;
  bool discarded_stale_ = false;
  int fd_ = -1;
};

/// 64-bit FNV-1a of `text`, as 16 hex digits (the fingerprint of inputs;
/// change detection, not security).
std::string fingerprint_of(const std::string& text);

}  // namespace fourbar
