// Property: a manifest written by manifest_to_toml (what the virtual rig
// writes beside each recording) loads again to the same manifest. Seeded
// generators over every key: strings with control characters, quotes,
// backslashes, non-ASCII and empty text; numbers at the edges of each key's
// range, subnormal, huge, and with all 17 significant digits.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "acquire/manifest.hpp"
#include "common/units.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

using testing::TempDir;
using Limits = std::numeric_limits<double>;

class Generator {
 public:
  explicit Generator(unsigned seed) : gen_(seed) {}

  int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(gen_); }
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen_); }

  /// Valid UTF-8: ASCII controls, quotes and backslashes, 2- to 4-byte
  /// characters; empty when `may_be_empty` and the dice say so.
  std::string text(bool may_be_empty, bool word = false) {
    static const char* pieces[] = {"\xC3\xA9", "\xCE\xB1", "\xE2\x80\x93", "\xE6\xB8\xAC", "\xF0\x9F\x94\xA7",
                                   "\\",       "'",        "\\u0041",      "#",            "="};
    std::string s;
    const int n = may_be_empty && below(5) == 0 ? 0 : 1 + below(24);
    while (static_cast<int>(s.size()) < n) {
      std::string piece;
      if (below(3) == 0) piece = pieces[below(static_cast<int>(std::size(pieces)))];
      else piece = std::string(1, static_cast<char>(below(0x80)));
      if (!word && below(8) == 0) piece = "\"";
      if (word && piece.find_first_of(std::string(",;\"\t\n \0", 8)) != std::string::npos) continue;
      if (!word && piece == std::string(1, '\0') && below(2)) continue;
      s += piece;
    }
    return s;
  }

  /// A positive finite double: any exponent, subnormals, the extremes.
  double positive() {
    switch (below(6)) {
      case 0: return Limits::denorm_min() * (1 + below(1000));
      case 1: return std::array{Limits::min(), Limits::max(), Limits::denorm_min(), 1.0}[below(4)];
      case 2: return std::ldexp(uniform(0.5, 1), below(2000) - 1000);
      default: return std::ldexp(uniform(0.5, 1), below(60) - 30);
    }
  }
  double finite() { return below(2) ? positive() : -positive(); }
  double in(double lo, double hi) {
    switch (below(5)) {
      case 0: return lo;
      case 1: return hi;
      default: return uniform(lo, hi);
    }
  }

 private:
  std::mt19937_64 gen_;
};

/// A manifest as load_manifest could return it. With `as_read`, every value
/// stored in SI but written in another unit is what the reader makes of a
/// number in that unit (as it always is in use); otherwise any SI double in
/// the key's range.
Manifest generate(Generator& g, const std::filesystem::path& rig_file, bool as_read) {
  auto mm = [&](double lo_mm, double hi_mm) {
    return as_read ? units::mm_to_m(g.in(lo_mm, hi_mm)) : g.in(units::mm_to_m(lo_mm), units::mm_to_m(hi_mm));
  };
  Manifest m;
  m.rig_file = rig_file;
  m.clearance_m = g.below(4) == 0 ? 0.0 : as_read ? units::mm_to_m(g.positive()) : g.positive();
  if (!std::isfinite(units::m_to_mm(m.clearance_m))) m.clearance_m = 1e-4;
  m.full_scale_V = g.in(1e-9, 1e9);
  if (g.below(2)) m.adc_range_V = g.positive();
  if (g.below(2)) m.sample_rate_hz = g.positive();
  if (g.below(2)) m.time_column = g.text(true);
  m.crank_direction = g.below(2) ? 1.0 : -1.0;
  if (g.below(2)) m.notes = g.text(false);
  const int n = 1 + g.below(6), pulse = g.below(n);
  for (int i = 0; i < n; ++i) {
    ChannelSpec c;
    if (g.below(2)) c.index = i;
    else c.column = g.text(true);
    const ChannelRole accel[] = {ChannelRole::coupler_tangential, ChannelRole::coupler_normal,
                                 ChannelRole::rocker_tangential, ChannelRole::rocker_normal, ChannelRole::ignore};
    c.role = i == pulse ? ChannelRole::crank_pulse : accel[g.below(5)];
    do c.name = g.text(false, true) + "_" + std::to_string(i);  // unique
    while (!is_channel_name(c.name));
    if (is_accelerometer(c.role)) {
      c.volts_per_m_s2 = g.positive();
      c.axis_sign = g.below(2) ? 1.0 : -1.0;
      c.position_m = mm(-1e5, 1e5);
      c.offset_m = g.below(3) == 0 ? 0.0 : mm(-1e5, 1e5);
      c.ac_coupled = g.below(2);
      if (c.ac_coupled) c.highpass_hz = g.positive();
    }
    if (c.role == ChannelRole::crank_pulse) {
      c.polarity = g.below(2) ? PulsePolarity::rising : PulsePolarity::falling;
      if (g.below(2)) {
        double a = g.finite(), b = g.finite();
        if (a == b) b = a + 1;
        c.threshold_low_V = std::min(a, b), c.threshold_high_V = std::max(a, b);
      }
      c.crank_offset_rad = as_read ? units::deg_to_rad(g.in(-360, 360)) : g.in(-2 * units::kPi, 2 * units::kPi);
      if (std::abs(units::rad_to_deg(c.crank_offset_rad)) > 360) c.crank_offset_rad = 0;
      if (g.below(2)) c.debounce_s = as_read ? g.in(0, 1e6) * 1e-3 : g.in(0, 1e3);
      if (c.debounce_s * 1e3 > 1e6) c.debounce_s = 1e3;
      if (g.below(3) == 0) c.smoothing_period_turns = g.in(6, 1e6);  // crank_smoothing = "spline"
    }
    if (g.below(2)) c.notes = g.text(false);
    m.channels.push_back(c);
  }
  return m;
}

/// Relative distance in units of 2^-52 (0 when equal).
double ulps_apart(double a, double b) {
  if (a == b) return 0;
  return std::abs(a - b) / std::max({std::abs(a), std::abs(b), Limits::denorm_min()}) / Limits::epsilon();
}

/// Every field equal, SI values converted through the file's unit within
/// `ulps` (0: exactly).
void expect_same(const Manifest& a, const Manifest& b, double ulps, const std::string& text) {
  EXPECT_TRUE(std::filesystem::equivalent(a.rig_file, b.rig_file)) << text;
  EXPECT_LE(ulps_apart(a.clearance_m, b.clearance_m), ulps) << text;
  EXPECT_EQ(a.full_scale_V, b.full_scale_V) << text;
  EXPECT_EQ(a.adc_range_V, b.adc_range_V) << text;
  EXPECT_EQ(a.sample_rate_hz, b.sample_rate_hz) << text;
  EXPECT_EQ(a.time_column, b.time_column) << text;
  EXPECT_EQ(a.crank_direction, b.crank_direction) << text;
  EXPECT_EQ(a.notes, b.notes) << text;
  ASSERT_EQ(a.channels.size(), b.channels.size()) << text;
  for (std::size_t i = 0; i < a.channels.size(); ++i) {
    const ChannelSpec &x = a.channels[i], &y = b.channels[i];
    EXPECT_EQ(x.name, y.name) << text;
    EXPECT_EQ(x.index, y.index) << text;
    EXPECT_EQ(x.column, y.column) << text;
    EXPECT_EQ(x.role, y.role) << text;
    EXPECT_EQ(x.volts_per_m_s2, y.volts_per_m_s2) << text;
    EXPECT_EQ(x.axis_sign, y.axis_sign) << text;
    EXPECT_LE(ulps_apart(x.position_m, y.position_m), ulps) << x.position_m << " " << y.position_m << "\n" << text;
    EXPECT_LE(ulps_apart(x.offset_m, y.offset_m), ulps) << text;
    EXPECT_EQ(x.ac_coupled, y.ac_coupled) << text;
    EXPECT_EQ(x.highpass_hz, y.highpass_hz) << text;
    EXPECT_EQ(x.polarity, y.polarity) << text;
    EXPECT_EQ(x.threshold_low_V, y.threshold_low_V) << text;
    EXPECT_EQ(x.threshold_high_V, y.threshold_high_V) << text;
    EXPECT_LE(ulps_apart(x.crank_offset_rad, y.crank_offset_rad), ulps) << text;
    EXPECT_LE(ulps_apart(x.debounce_s, y.debounce_s), ulps) << text;
    EXPECT_EQ(x.smoothing_period_turns, y.smoothing_period_turns) << text;
    EXPECT_EQ(x.notes, y.notes) << text;
  }
}

Manifest write_and_load(const TempDir& dir, const Manifest& m, std::string& text) {
  text = manifest_to_toml(m, dir.path());
  return load_manifest(dir.write("again.toml", text));
}

TEST(ManifestRoundTrip, ValuesAsReadComeBackExactly) {
  TempDir dir;
  const auto rig = dir.write("rig.toml", testing::thesis_rig_toml());
  Generator g(20261124);
  for (int trial = 0; trial < 300; ++trial) {
    const Manifest m = generate(g, rig, true);
    std::string text;
    Manifest back;
    ASSERT_NO_THROW(back = write_and_load(dir, m, text)) << "trial " << trial << ":\n" << text;
    expect_same(m, back, 0, "trial " + std::to_string(trial) + ":\n" + text);
    if (HasFailure()) return;
  }
}

TEST(ManifestRoundTrip, AnySiValueComesBackWithinAnUlpAndThenStays) {
  // Not every double in metres is 1e-3 times a double in millimetres: such a
  // value may move by an ulp once, and is then stable.
  TempDir dir;
  const auto rig = dir.write("rig.toml", testing::thesis_rig_toml());
  Generator g(7);
  for (int trial = 0; trial < 300; ++trial) {
    const Manifest m = generate(g, rig, false);
    std::string text, text2, text3;
    Manifest back;
    ASSERT_NO_THROW(back = write_and_load(dir, m, text)) << "trial " << trial << ":\n" << text;
    expect_same(m, back, 1, "trial " + std::to_string(trial) + ":\n" + text);
    const Manifest again = write_and_load(dir, back, text2);
    expect_same(back, again, 0, "trial " + std::to_string(trial) + " (second round):\n" + text2);
    write_and_load(dir, again, text3);
    EXPECT_EQ(text2, text3);
    if (HasFailure()) return;
  }
}

}  // namespace
}  // namespace fourbar
