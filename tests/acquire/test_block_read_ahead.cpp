// Reading ahead on a thread of its own (acquire/block_read_ahead.hpp, and
// AcquireOptions::threads > 1, which also splits the scan pass over two
// threads): the same blocks in the same order as a plain read, a read error
// where the plain read has it, and acquire's results bit for bit the ones
// of one thread.

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

#include "acquire/acquisition.hpp"
#include "acquire/block_read_ahead.hpp"
#include "common/error.hpp"
#include "virtual_recording.hpp"

namespace fourbar {
namespace {

/// Frames whose values count up: frame f, channel c holds f * channels + c.
/// Optionally throws on the read that would start at `fail_at_frame`.
class CountingReader final : public Reader {
 public:
  CountingReader(std::uint64_t frames, int channels, std::uint64_t fail_at_frame = UINT64_MAX)
      : fail_at_(fail_at_frame) {
    info_.channels = channels, info_.frames = frames, info_.sample_rate_hz = 1000;
  }
  std::size_t read(std::span<double> out) override {
    if (position_ >= fail_at_) throw InputError("damaged at frame " + std::to_string(position_));
    const auto ch = static_cast<std::uint64_t>(info_.channels);
    const std::uint64_t n = std::min<std::uint64_t>(out.size() / ch, info_.frames - position_);
    for (std::uint64_t i = 0; i < n * ch; ++i) out[i] = static_cast<double>(position_ * ch + i);
    position_ += n;
    return static_cast<std::size_t>(n);
  }
  void rewind() override { position_ = 0; }

 private:
  std::uint64_t position_ = 0, fail_at_;
};

TEST(BlockReadAhead, SameValuesInTheSameOrderAsAPlainRead) {
  CountingReader reader(10007, 3);  // the last block is short
  std::vector<double> some(30);
  reader.read(some);  // left mid-way: the read-ahead rewinds
  BlockReadAhead ahead(reader, 64);
  std::uint64_t expected = 0;
  std::size_t blocks = 0;
  for (std::span<const double> b; !(b = ahead.next()).empty(); ++blocks)
    for (double v : b) ASSERT_EQ(v, static_cast<double>(expected++));
  EXPECT_EQ(expected, 10007u * 3);
  EXPECT_EQ(blocks, 157u);  // 156 full blocks of 64 frames and one of 23
  EXPECT_TRUE(ahead.next().empty());
}

TEST(BlockReadAhead, AReadErrorComesAfterTheBlocksBeforeIt) {
  CountingReader reader(10000, 2, 640);  // the read of block 10 throws
  BlockReadAhead ahead(reader, 64);
  for (int k = 0; k < 10; ++k) ASSERT_EQ(ahead.next().size(), 128u) << k;
  try {
    ahead.next();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "damaged at frame 640");
  }
}

TEST(BlockReadAhead, StoppedHalfWayEndsCleanly) {
  CountingReader reader(1000000, 2);
  {
    BlockReadAhead ahead(reader, 64);
    ASSERT_EQ(ahead.next().size(), 128u);
  }  // joins the reading thread, which waits for a free slot
  SUCCEED();
}

/// Keeps what acquire streams, to compare bit for bit.
struct CollectValues : AcquisitionSink {
  std::vector<double> values;
  std::vector<std::int64_t> revolutions;
  void on_samples(const SampleBlock& b) override {
    for (const auto* v : {&b.time_s, &b.crank_rad, &b.omega2_rad_s, &b.alpha2_rad_s2})
      values.insert(values.end(), v->begin(), v->end());
    for (const auto& c : b.channels_m_s2) values.insert(values.end(), c.begin(), c.end());
    revolutions.insert(revolutions.end(), b.revolution.begin(), b.revolution.end());
  }
};

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same_stats(const ChannelStats& a, const ChannelStats& b) {
  for (auto [x, y] : {std::pair{a.min, b.min}, {a.max, b.max}, {a.mean, b.mean}, {a.rms, b.rms}})
    EXPECT_TRUE(same_bits(x, y)) << x << " " << y;
  EXPECT_EQ(a.clipped_samples, b.clipped_samples);
}

TEST(BlockReadAhead, AcquireOnTwoThreadsGivesTheNumbersOfOne) {
  testing::VirtualSetup v;
  v.spec.revolutions = 30;
  const auto written = v.write("read_ahead.wav", false);
  AcquisitionReport report[2];
  CollectValues out[2];
  for (unsigned t : {1u, 2u}) {
    OpenedRecording o = open_with_manifest(written.recording, {});
    AcquireOptions options;
    options.progress = false;
    options.block_frames = 1000;  // many blocks
    options.threads = t;
    report[t - 1] = acquire(*o.reader, o.manifest, options, out[t - 1]);
  }
  ASSERT_EQ(report[0].channel_stats.size(), report[1].channel_stats.size());
  for (std::size_t c = 0; c < report[0].channel_stats.size(); ++c)
    expect_same_stats(report[0].channel_stats[c], report[1].channel_stats[c]);
  expect_same_stats(report[0].pulse_stats, report[1].pulse_stats);
  const PulseThresholds &a = report[0].thresholds, &b = report[1].thresholds;
  for (auto [x, y] : {std::pair{a.low, b.low}, {a.high, b.high}, {a.bottom_level, b.bottom_level},
                      {a.top_level, b.top_level}, {a.noise, b.noise}})
    EXPECT_TRUE(same_bits(x, y)) << x << " " << y;
  EXPECT_TRUE(same_bits(report[0].edge_level_V, report[1].edge_level_V));
  EXPECT_EQ(report[0].revolutions, report[1].revolutions);
  ASSERT_GT(report[0].revolutions, 20u);
  ASSERT_EQ(out[0].values.size(), out[1].values.size());
  EXPECT_EQ(std::memcmp(out[0].values.data(), out[1].values.data(), out[0].values.size() * sizeof(double)), 0);
  EXPECT_EQ(out[0].revolutions, out[1].revolutions);
}

}  // namespace
}  // namespace fourbar
