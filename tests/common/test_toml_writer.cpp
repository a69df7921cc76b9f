// toml_quoted: every string, control characters and non-ASCII included, reads
// back through toml++ as the same bytes.
#include "common/toml_writer.hpp"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <random>
#include <string>

namespace fourbar {
namespace {

std::string read_back(const std::string& text) {
  const auto table = toml::parse("value = " + toml_quoted(text) + "\n");
  return std::string(*table["value"].value<std::string_view>());
}

TEST(TomlQuoted, EscapesWhatTomlRequires) {
  EXPECT_EQ(toml_quoted("a\"b\\c"), R"("a\"b\\c")");
  EXPECT_EQ(toml_quoted(std::string("\b\t\n\f\r", 5)), R"("\b\t\n\f\r")");
  EXPECT_EQ(toml_quoted(std::string("\x01\x1f\x7f", 3)), R"("\u0001\u001F\u007F")");
  EXPECT_EQ(toml_quoted(""), "\"\"");
}

TEST(TomlQuoted, EveryAsciiByteRoundTrips) {
  std::string all;
  for (int b = 1; b < 0x80; ++b) all += static_cast<char>(b);
  EXPECT_EQ(read_back(all), all);
  EXPECT_EQ(read_back(std::string("nul\0inside", 10)), std::string("nul\0inside", 10));
}

TEST(TomlQuoted, GeneratedUtf8StringsRoundTrip) {
  // Seeded: ASCII (controls included) mixed with 2-, 3- and 4-byte UTF-8.
  std::mt19937 gen(20261124);
  const char* pieces[] = {"\xC3\xA9", "\xCE\xB1", "\xE2\x80\x93", "\xE2\x82\xAC", "\xF0\x9F\x94\xA7", "\\", "\"", "'"};
  for (int trial = 0; trial < 500; ++trial) {
    std::string s;
    const int len = std::uniform_int_distribution<int>(0, 40)(gen);
    for (int i = 0; i < len; ++i) {
      if (gen() % 3 == 0) s += pieces[gen() % std::size(pieces)];
      else s += static_cast<char>(std::uniform_int_distribution<int>(0, 0x7F)(gen));
    }
    ASSERT_EQ(read_back(s), s) << "trial " << trial;
  }
}

}  // namespace
}  // namespace fourbar
