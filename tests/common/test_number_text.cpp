#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "common/number_text.hpp"
#include "common/units.hpp"

namespace fourbar {
namespace {

/// The fewest characters of a printf form of `v` that reads back to `v`:
/// scientific with 1..17 significant digits, and fixed with 0..25 decimals
/// where that can be short (1e-5 <= |v| < 1e22; outside, scientific is shorter).
std::size_t shortest_printf_length(double v) {
  char buf[400];
  std::size_t best = std::string::npos;
  for (int p = 0; p < 17; ++p) {
    std::snprintf(buf, sizeof buf, "%.*e", p, v);
    if (std::strtod(buf, nullptr) == v) {
      best = std::strlen(buf);
      break;
    }
  }
  if (std::abs(v) >= 1e-5 && std::abs(v) < 1e22)
    for (int d = 0; d <= 25; ++d) {
      std::snprintf(buf, sizeof buf, "%.*f", d, v);
      if (std::strtod(buf, nullptr) == v) {
        best = std::min(best, std::strlen(buf));
        break;
      }
    }
  return best;
}

/// Checks that `text` reads back to exactly `v` with two parsers (from_chars
/// and the C library's strtod), and that no printf form of it that reads back
/// is shorter.
void expect_shortest_round_trip(double v) {
  const std::string text = format_double(v);
  double back = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), back);
  ASSERT_EQ(ec, std::errc()) << text;
  ASSERT_EQ(end, text.data() + text.size()) << text;
  ASSERT_EQ(std::bit_cast<std::uint64_t>(back), std::bit_cast<std::uint64_t>(v)) << text;
  ASSERT_EQ(std::bit_cast<std::uint64_t>(std::strtod(text.c_str(), nullptr)), std::bit_cast<std::uint64_t>(v)) << text;
  if (v != 0) ASSERT_LE(text.size(), shortest_printf_length(v)) << text << " is not the shortest form";
}

TEST(NumberText, ShortestFormOfFamiliarValues) {
  EXPECT_EQ(format_double(0.0254), "0.0254");
  EXPECT_EQ(format_double(350.0), "350");
  EXPECT_EQ(format_double(0.0), "0");
  EXPECT_EQ(format_double(-0.0), "-0");
  EXPECT_EQ(format_double(1e-7), "1e-07");
  EXPECT_EQ(format_double(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(format_double(1.0 / 3.0), "0.3333333333333333");
  // The value itself, not its text, is what mm -> m -> mm changes:
  EXPECT_EQ(format_double(units::m_to_mm(units::mm_to_m(0.0254))), "0.025400000000000002");
}

TEST(NumberText, InputDecimalsComeBackAsTheFileWroteThem) {
  for (double mm : {0.0254, 0.254, 0.1, 0.35, 1.0, 12.5})
    EXPECT_EQ(format_input_decimal(units::m_to_mm(units::mm_to_m(mm))), format_double(mm)) << mm;
  for (double rpm : {250.0, 350.0, 100.5, 1200.0})
    EXPECT_EQ(format_input_decimal(units::rad_s_to_rpm(units::rpm_to_rad_s(rpm))), format_double(rpm)) << rpm;
}

TEST(NumberText, ExtremesRoundTripBitIdentical) {
  using L = std::numeric_limits<double>;
  const std::vector<double> values{0.0,
                                   -0.0,
                                   L::denorm_min(),
                                   -L::denorm_min(),
                                   2 * L::denorm_min(),
                                   std::nextafter(L::min(), 0.0),  // largest subnormal
                                   L::min(),
                                   std::nextafter(L::min(), 1.0),
                                   L::max(),
                                   L::lowest(),
                                   std::nextafter(L::max(), 0.0),
                                   L::epsilon(),
                                   1.0 + L::epsilon(),
                                   std::nextafter(1.0, 0.0),
                                   9007199254740992.0,  // 2^53
                                   9007199254740994.0,
                                   1e21,
                                   1e22,
                                   1e23,
                                   5e-324,
                                   2.2250738585072014e-308,
                                   1.7976931348623157e308,
                                   0.1,
                                   123456789012345680.0};
  for (double v : values) expect_shortest_round_trip(v);
  EXPECT_EQ(format_double(L::denorm_min()), "5e-324");
  EXPECT_EQ(format_double(L::max()), "1.7976931348623157e+308");
}

TEST(NumberText, RandomDoublesRoundTripBitIdentical) {
  std::mt19937_64 rng(20261124);
  // Every finite double alike (random bit patterns: subnormals, huge and tiny
  // exponents), then values of the sizes the tables hold.
  int tested = 0, subnormal = 0;
  for (int i = 0; i < 100000; ++i) {
    const double v = std::bit_cast<double>(rng());
    if (!std::isfinite(v)) continue;
    subnormal += std::fpclassify(v) == FP_SUBNORMAL;
    expect_shortest_round_trip(v);
    ++tested;
  }
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  for (int i = 0; i < 50000; ++i) expect_shortest_round_trip(std::ldexp(mantissa(rng), exponent(rng)));
  // Subnormals from their own range too (random bit patterns hit them rarely).
  std::uniform_int_distribution<std::uint64_t> sub(1, (std::uint64_t{1} << 52) - 1);
  for (int i = 0; i < 10000; ++i) {
    const std::uint64_t bits = sub(rng) | (rng() & (std::uint64_t{1} << 63));
    expect_shortest_round_trip(std::bit_cast<double>(bits));
    ++subnormal;
  }
  EXPECT_GT(tested, 99000);
  EXPECT_GE(subnormal, 10000);
}

}  // namespace
}  // namespace fourbar
