#pragma once
// Error types that carry the process exit status the CLI reports.
// Documented exit codes (README "The command"):
//   0  success
//   1  the run failed (numerical failure, cannot write output, internal error)
//   2  bad input: usage, a file, a key, a value or a channel the user gave

#include <stdexcept>
#include <string>

namespace fourbar {

/// The user gave something unusable: a bad argument, file, key or value.
/// The message names the object and says how to fix it. Exit status 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A correct input could not be processed to the end. Exit status 1.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr int kExitOk = 0;
inline constexpr int kExitRunError = 1;
inline constexpr int kExitInputError = 2;

}  // namespace fourbar
