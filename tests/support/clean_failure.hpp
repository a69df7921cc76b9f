#pragma once
// The CLI's promise for bad input, checked one way for every command: exit
// status 2, exactly one line on stderr that starts with "fourbar: " and names
// what is wrong, no "internal error", nothing on stdout, and nothing written
// into the output folder (absent or empty).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/run_command.hpp"

namespace fourbar::testing {

/// `needle`: a word the message must name (the option, file, key or value).
inline void expect_clean_failure(const CommandResult& r, const std::string& needle,
                                 const std::filesystem::path& out_dir) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("fourbar: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << "the message does not name '" << needle << "': " << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  const bool empty = !std::filesystem::exists(out_dir) || std::filesystem::is_empty(out_dir);
  EXPECT_TRUE(empty) << "something was written into " << out_dir;
}

}  // namespace fourbar::testing
