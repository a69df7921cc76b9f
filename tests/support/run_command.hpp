#pragma once
// Runs the fourbar executable as a user would and captures what it says.

#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "support/temp_dir.hpp"

namespace fourbar::testing {

struct CommandResult {
  int status = -1;
  std::string out, err;
};

inline CommandResult run_fourbar(const std::string& args) {
  TempDir dir;
  const auto out = dir.path() / "stdout", err = dir.path() / "stderr";
  const std::string cmd = std::string(FOURBAR_EXE) + " " + args + " >" + out.string() + " 2>" + err.string() +
                          " </dev/null";
  const int raw = std::system(cmd.c_str());
  CommandResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

}  // namespace fourbar::testing
