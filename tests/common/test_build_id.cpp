// The build-id read from the running program's notes equals the one binutils
// reads from the file (a second, independent reader).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>

#include <unistd.h>

#include "common/build_id.hpp"


TEST(BuildId, IsTheOneReadelfReadsFromTheExecutable) {
  // popen runs a shell, whose /proc/self/exe is the shell's: name this
  // process's file by its pid.
  const std::string id = fourbar::build_id();
  ASSERT_FALSE(id.empty()) << "the test executable has no GNU build-id note";
  EXPECT_EQ(id.find_first_not_of("0123456789abcdef"), std::string::npos) << id;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(
      popen(("readelf -n /proc/" + std::to_string(getpid()) + "/exe 2>/dev/null").c_str(), "r"), pclose);
  ASSERT_TRUE(pipe);
  std::string text;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), buf.size(), pipe.get())) text += buf.data();
  if (text.empty()) GTEST_SKIP() << "readelf (binutils) is not installed";
  EXPECT_NE(text.find("Build ID: " + id), std::string::npos) << text;
}
