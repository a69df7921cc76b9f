#pragma once
// Numbers in messages and text outputs for people: one formatter, so every
// error and warning writes a value the same way.

#include <string>

namespace fourbar {

/// Significant digits in messages: enough to tell two set-up values apart,
/// short enough to read.
inline constexpr int kMessageDigits = 6;

/// `value` with `significant_digits` significant digits, shortest form
/// (std::ostream's default float format): 0.25, 1.5e-07, 350.
std::string format_number(double value, int significant_digits = kMessageDigits);

}  // namespace fourbar
