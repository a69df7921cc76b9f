// round_numbers (the report page's six significant digits) against the
// printf/strtod round trip it replaced, number for number.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>

#include "report/html_text.hpp"

namespace fourbar {
namespace {

using nlohmann::json;

double printf_rounded(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return std::strtod(buf, nullptr);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(RoundNumbers, EqualsPrintfAndStrtodBitForBit) {
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
  std::uniform_int_distribution<int> exponent(-310, 308);
  std::uniform_int_distribution<std::uint64_t> bits;
  json values = json::array();
  for (double v : {0.0, -0.0, 1.0, -1.0, 0.5, 123456.5, 1234565.0, 9.999995, 9.9999949999, 1e-320, 5e-324,
                   std::numeric_limits<double>::max(), std::numeric_limits<double>::min(), 0.1, 2.0 / 3.0})
    values.push_back(v);
  for (double v : {-std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min(), 1.79769e308})
    values.push_back(v);
  for (int i = 0; i < 100000; ++i)
    if (const double v = mantissa(rng) * std::pow(10.0, exponent(rng)); std::isfinite(v)) values.push_back(v);
  for (int i = 0; i < 100000; ++i) {  // any bit pattern that is a finite number
    std::uint64_t b = bits(rng);
    double v = 0;
    std::memcpy(&v, &b, sizeof v);
    if (std::isfinite(v)) values.push_back(v);
  }
  json rounded = values;
  round_numbers(rounded);
  ASSERT_EQ(rounded.size(), values.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double v = values[i].get<double>(), want = printf_rounded(v), got = rounded[i].get<double>();
    if (!same_bits(want, got) && ++differ <= 5) ADD_FAILURE() << "%.6g of " << v << ": " << got << ", want " << want;
  }
  EXPECT_EQ(differ, 0u);
}

TEST(RoundNumbers, NonFiniteBecomeNullAndStructureIsKept) {
  json j = {{"a", std::numeric_limits<double>::infinity()},
            {"b", json::array({std::nan(""), 1.23456789, 7, "text"})},
            {"c", {{"d", -0.000123456789}}}};
  round_numbers(j);
  EXPECT_TRUE(j["a"].is_null());
  EXPECT_TRUE(j["b"][0].is_null());
  EXPECT_EQ(j["b"][1].get<double>(), 1.23457);
  EXPECT_TRUE(j["b"][2].is_number_integer());
  EXPECT_EQ(j["b"][3], "text");
  EXPECT_EQ(j["c"]["d"].get<double>(), -0.000123457);
}

}  // namespace
}  // namespace fourbar
