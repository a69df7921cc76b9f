// toml_quoted: every string, control characters and non-ASCII included, reads
// back through toml++ as the same bytes.
#include "common/toml_writer.hpp"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>
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

double number_back(const std::string& text) {
  const auto table = toml::parse("value = " + text + "\n");
  if (const auto i = table["value"].value_exact<std::int64_t>()) return static_cast<double>(*i);
  return *table["value"].value_exact<double>();
}

TEST(TomlNumber, ShortestAndAlwaysReadable) {
  EXPECT_EQ(toml_number(1), "1");
  EXPECT_EQ(toml_number(25600), "25600");
  EXPECT_EQ(toml_number(0.258), "0.258");
  EXPECT_EQ(toml_number(1e300), "1e+300");
  // Shortest as 21 digits without a point: a TOML integer out of range.
  EXPECT_EQ(toml_number(1.2345678901234568e20), "123456789012345683968.0");
  EXPECT_EQ(toml_number(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(toml_number(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(toml_number(std::numeric_limits<double>::quiet_NaN()), "nan");
}

TEST(TomlNumber, GeneratedDoublesReadBackExactly) {
  // Seeded: every exponent, subnormals, the extremes, integers near 2^63.
  std::mt19937_64 gen(1124);
  std::vector<double> values = {std::numeric_limits<double>::max(), std::numeric_limits<double>::min(),
                                std::numeric_limits<double>::denorm_min(), 9223372036854775807.0, 0.0, -0.0};
  for (int i = 0; i < 20000; ++i) {
    double v;
    const std::uint64_t bits = gen();
    std::memcpy(&v, &bits, sizeof v);
    if (std::isfinite(v)) values.push_back(v);
    values.push_back(std::ldexp(static_cast<double>(gen() >> 11), static_cast<int>(gen() % 40)));  // large integers
  }
  for (const double v : values) ASSERT_EQ(number_back(toml_number(v)), v) << toml_number(v);
}

TEST(TomlNumberInUnit, ShortestDecimalThatConvertsBack) {
  auto mm_to_m = [](double mm) { return mm * 1e-3; };
  const double m = mm_to_m(0.258);
  ASSERT_NE(m * 1e3, 0.258);  // the naive way back drifts
  EXPECT_EQ(toml_number_in_unit(m, m * 1e3, mm_to_m), "0.258");
  std::mt19937_64 gen(258);
  for (int i = 0; i < 20000; ++i) {
    // Any millimetre value the reader can meet converts back exactly.
    const double mm = std::ldexp(std::uniform_real_distribution<double>(-1, 1)(gen), static_cast<int>(gen() % 60) - 30);
    const double si = mm_to_m(mm);
    const std::string text = toml_number_in_unit(si, si * 1e3, mm_to_m);
    ASSERT_EQ(mm_to_m(number_back(text)), si) << text << " for " << mm << " mm";
    ASSERT_LE(text.size(), toml_number(mm).size()) << text;
  }
}

}  // namespace
}  // namespace fourbar
