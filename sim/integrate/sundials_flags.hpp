#pragma once
// SUNDIALS return flags, as every integrator built on CVODE or ARKODE treats
// them: a negative flag is a RunError naming the solver and the call, and
// the library prints nothing itself (the flag carries the failure).

#include <string>

#include "common/error.hpp"

namespace fourbar {

/// Checks the flags of one solver's calls: check(flag, "init") throws
/// RunError "SOLVER init failed (flag N)" when `flag` is negative.
struct SundialsCheck {
  const char* solver;
  void operator()(int flag, const char* what) const {
    if (flag < 0) throw RunError(std::string(solver) + " " + what + " failed (flag " + std::to_string(flag) + ")");
  }
};

/// A SUNDIALS error handler that prints nothing.
inline void silent_sundials_handler(int, const char*, const char*, char*, void*) {}

}  // namespace fourbar
