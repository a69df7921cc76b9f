// The raw-signal excerpt acquire keeps for the report (signal_excerpt.hpp):
// its window, pulses and edges are acquire's own, its points every frame's
// extremes; a tooth wheel's edges come with it; none is kept unless asked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "acquire/acquisition.hpp"
#include "wheel_setup.hpp"

namespace fourbar {
namespace {

using testing::VirtualSetup;
using testing::WheelKind;

AcquisitionReport acquire_with_excerpt(const VirtualRigResult& vr, std::size_t revolutions) {
  AcquireOptions o;
  o.progress = false;
  o.excerpt_revolutions = revolutions;
  OpenedRecording rec = open_with_manifest(vr.recording, {});
  AcquisitionSink none;
  return acquire(*rec.reader, rec.manifest, o, none);
}

TEST(SignalExcerpt, OnlyWhenAsked) {
  VirtualSetup v;
  const VirtualRigResult vr = v.write("plain.wav", false);
  EXPECT_FALSE(acquire_with_excerpt(vr, 0).excerpt.has_value());
}

TEST(SignalExcerpt, WindowPulsesAndBucketsOfOncePerTurnPulses) {
  VirtualSetup v;
  v.spec.revolutions = 12;
  const VirtualRigResult vr = v.write("pulses.wav", false);
  const AcquisitionReport r = acquire_with_excerpt(vr, 3);
  ASSERT_TRUE(r.excerpt.has_value());
  const SignalExcerpt& x = *r.excerpt;
  // 3 turns from the middle: 4 of acquire's pulses, all inside, the window a
  // tenth of a period wider on each side.
  std::vector<double> inside;
  for (const auto& s : r.pulses.segments)
    for (const Pulse& p : s)
      if (p.time_s >= x.start_s && p.time_s <= x.end_s) inside.push_back(p.time_s);
  ASSERT_EQ(inside.size(), 4u);
  EXPECT_EQ(x.pulse_s, inside);
  const double period = (inside.back() - inside.front()) / 3;
  const double fs = r.recording.sample_rate_hz;
  EXPECT_NEAR(inside.front() - x.start_s, 0.1 * period, 1.0 / fs);
  EXPECT_NEAR(x.end_s - inside.back(), 0.1 * period, 1.0 / fs);
  // ⌈frames / 600⌉ frames per bucket, two points per bucket.
  const std::size_t bucket = static_cast<std::size_t>((x.frames + 599) / 600);
  EXPECT_EQ(x.bucket_frames, bucket);
  const std::size_t buckets = static_cast<std::size_t>((x.frames + bucket - 1) / bucket);
  ASSERT_EQ(x.time_s.size(), 2 * buckets);
  // The angle channel first (volts), then the accelerometers (m/s²), manifest order.
  ASSERT_EQ(x.traces.size(), 1 + r.channels.size());
  EXPECT_EQ(x.traces[0].unit, "V");
  for (std::size_t c = 0; c < r.channels.size(); ++c) {
    EXPECT_EQ(x.traces[1 + c].name, r.channels[c].name);
    const auto [lo, hi] = std::minmax_element(x.traces[1 + c].values.begin(), x.traces[1 + c].values.end());
    EXPECT_GE(*lo, r.channel_stats[c].min);
    EXPECT_LE(*hi, r.channel_stats[c].max);
  }
  // The crank signal reaches both levels within the excerpt.
  const auto [plo, phi] = std::minmax_element(x.traces[0].values.begin(), x.traces[0].values.end());
  EXPECT_LT(*plo, r.thresholds.low);
  EXPECT_GT(*phi, r.thresholds.high);
}

TEST(SignalExcerpt, ToothWheelEdgesInTheWindow) {
  VirtualSetup v;
  v.spec.revolutions = 10;
  testing::fit_wheel(v, WheelKind::teeth_with_index);
  const VirtualRigResult vr = v.write("wheel.wav", false);
  const AcquisitionReport r = acquire_with_excerpt(vr, 3);
  ASSERT_TRUE(r.excerpt.has_value());
  const SignalExcerpt& x = *r.excerpt;
  EXPECT_EQ(x.pulse_s.size(), 4u);
  // 60 teeth a turn, one polarity: 3 turns and two tenths of one.
  EXPECT_GE(x.wheel_edge_s.size(), 180u);
  EXPECT_LE(x.wheel_edge_s.size(), 180u + 14u);
  EXPECT_TRUE(std::is_sorted(x.wheel_edge_s.begin(), x.wheel_edge_s.end()));
  // Index and tooth channels, both in volts.
  EXPECT_GE(std::count_if(x.traces.begin(), x.traces.end(), [](const ExcerptTrace& t) { return t.unit == "V"; }), 2);
}

}  // namespace
}  // namespace fourbar
