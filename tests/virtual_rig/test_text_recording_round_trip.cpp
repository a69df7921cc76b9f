// Property: a text recording written by the virtual rig (time_s column, one
// column per channel, shortest round-trip numbers) reads back through
// open_recording with the same column names and the same numbers to the last
// bit: subnormal, huge, negative zero, 17 significant digits. The names are
// any the manifest accepts as a channel name (the virtual rig's manifest
// refers to its columns by name), drawn from all of ASCII and non-ASCII; a
// name with a control character is refused (the CSV reader trims a leading
// vertical tab, so it would not come back).

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "acquire/manifest.hpp"
#include "acquire/reader.hpp"
#include "common/error.hpp"
#include "support/temp_dir.hpp"
#include "virtual_rig/recording_writer.hpp"

namespace fourbar {
namespace {

using testing::TempDir;

/// A channel name load_manifest accepts, drawn from every ASCII character
/// and some non-ASCII ones (drawing again while is_channel_name refuses).
std::string channel_name(std::mt19937_64& gen) {
  static const char* pieces[] = {"\xC3\xA9", "\xCE\xB1", "\xE2\x80\x93", "\xF0\x9F\x94\xA7", "_", "-", "'", "#"};
  std::string s;
  do {
    s.clear();
    for (int n = 1 + static_cast<int>(gen() % 6); n > 0; --n)
      s += gen() % 3 == 0 ? std::string(pieces[gen() % 8]) : std::string(1, static_cast<char>(gen() % 0x80));
  } while (!is_channel_name(s));
  return s;
}

double any_double(std::mt19937_64& gen) {
  switch (gen() % 4) {
    case 0: {
      double v;
      do {
        const std::uint64_t bits = gen();
        std::memcpy(&v, &bits, sizeof v);
      } while (!std::isfinite(v));
      return v;
    }
    case 1: return std::numeric_limits<double>::denorm_min() * static_cast<double>(gen() % 100000);
    case 2: {
      const double edges[] = {std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
                              std::numeric_limits<double>::min(), -0.0, 1.0 / 3, -1e-310};
      return edges[gen() % 6];
    }
    default: return std::ldexp(std::uniform_real_distribution<double>(-1, 1)(gen), static_cast<int>(gen() % 20) - 10);
  }
}

void round_trip(unsigned seed) {
  TempDir dir;
  std::mt19937_64 gen(seed);
  for (int trial = 0; trial < 100; ++trial) {
    const int channels = 1 + static_cast<int>(gen() % 4);
    std::vector<std::string> names;
    for (int c = 0; c < channels; ++c) names.push_back(channel_name(gen) + std::to_string(c));
    const std::size_t frames = 2 + gen() % 50;  // one row gives no sample rate
    std::vector<double> data(frames * static_cast<std::size_t>(channels));
    for (double& v : data) v = any_double(gen);
    const auto file = dir.path() / ("r" + std::to_string(trial) + ".csv");
    auto w = open_recording_writer(file, channels, 1000, names, "", {"round trip"});
    w->write(data);
    w->commit();

    std::string where = "trial " + std::to_string(trial) + ", names:";
    for (const auto& n : names) where += " [" + n + "]";
    std::unique_ptr<Reader> r;
    ASSERT_NO_THROW(r = open_recording(file)) << where;
    const RecordingInfo& info = r->info();
    ASSERT_EQ(info.channels, channels) << where;  // time_s is the time column
    ASSERT_EQ(info.frames, frames) << where;
    EXPECT_NEAR(info.sample_rate_hz, 1000, 1e-9) << where;  // from the time column
    EXPECT_EQ(info.channel_names, names) << where;
    std::vector<double> block(static_cast<std::size_t>(channels) * frames);
    ASSERT_EQ(r->read(block), frames) << where;
    for (std::size_t f = 0; f < frames; ++f)
      for (int c = 0; c < channels; ++c) {
        const double want = data[f * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)];
        const double got = block[f * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)];
        ASSERT_TRUE(got == want && std::signbit(got) == std::signbit(want))
            << where << ": frame " << f << " channel " << c << ": wrote " << want << " read " << got;
      }
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(TextRecordingRoundTrip, AnyChannelNameAndAnyNumber) {
  round_trip(11);
  round_trip(12);
}

TEST(TextRecordingRoundTrip, ControlCharactersAreNoChannelNames) {
  for (const char* bad : {"\va", "a\r", "a\x7f", "a\bb", "a b", "a,b", "a;b", "a\"b", "a\tb", ""})
    EXPECT_FALSE(is_channel_name(bad)) << bad;
  for (const char* good : {"\xC3\xA9_1", "#x", "'q'", "a-b", "rocker\xE2\x80\x93t"}) EXPECT_TRUE(is_channel_name(good)) << good;
}

}  // namespace
}  // namespace fourbar
