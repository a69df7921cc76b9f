// An index that coincides with an edge, virtual rig → acquire: a standard
// encoder's Z gated to one A/B state (it rises with line 0's A edge) and a
// tooth wheel's index pickup rising with tooth 0's edge, 20 to 40 dB SNR,
// with the crank's speed changing within the turn. Every turn between the
// first and last index mark is counted right (none cut), and the crank angle
// per sample is checked against the drive's own kinematics — which also
// checks that position 0 is the edge the index coincides with (a turn named
// one edge early or late would be off by a whole pitch).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "acquire/acquisition.hpp"
#include "common/statistics.hpp"
#include "virtual_rig/wheel_signal.hpp"
#include "wheel_setup.hpp"

namespace fourbar {
namespace {

using testing::Crank;
using testing::VirtualSetup;

struct IndexCase {
  const char* name;
  bool encoder;
  double offset_pitch;  ///< index leading edge after position 0's edge, in pitches (lines)
  double snr_db;
  double tooth_error_deg;
  double sample_rate_hz = 0;  ///< encoder: 51.2 kHz unless given
};

VirtualSetup index_setup(const IndexCase& c, double revolutions) {
  VirtualSetup v;
  v.spec.revolutions = revolutions;
  v.spec.seed = 11;
  testing::in_turn_speed_change(v);
  v.spec.noise_snr_db = c.snr_db;
  v.spec.pulse.noise_V = 2.5 / std::pow(10.0, c.snr_db / 20);
  WheelSpec& w = v.spec.wheel;
  w.index = true;
  w.index_offset_pitch = c.offset_pitch;
  w.tooth_error_rad = units::deg_to_rad(c.tooth_error_deg);
  if (c.encoder) {
    // 1024 lines at 51.2 kHz: 2.1 samples per quadrature edge at 350 rpm.
    w.encoder_lines = 1024;
    v.spec.sample_rate_hz = c.sample_rate_hz > 0 ? c.sample_rate_hz : 51200;
    v.spec.pulse.rise_s = 1.0 / v.spec.sample_rate_hz;
  } else {
    w.teeth = 60;
  }
  return v;
}

/// Index marks whose leading edge lies inside the recording (a pitch clear of
/// both ends, so that whether the recording holds them is not a matter of
/// noise): the complete turns between them are what acquire must count.
std::size_t index_marks_inside(const VirtualSetup& v, double duration_s) {
  const CrankDrive d = v.drive();
  const std::vector<EdgeChannel> ch =
      wheel_channels(v.spec.wheel, d, v.spec.pulse.angle_rad, duration_s, v.spec.pulse.rise_s, "crank", v.spec.seed);
  const int P = v.spec.wheel.encoder_lines > 0 ? v.spec.wheel.encoder_lines : v.spec.wheel.teeth;
  const double pitch_s = 2 * units::kPi / P / d.mean_speed_rad_s;
  std::size_t n = 0;
  for (const auto& [lead, trail] : ch.back().pulses) {
    EXPECT_TRUE(std::abs(lead) > pitch_s && std::abs(lead - duration_s) > pitch_s)
        << "an index mark at the recording's end: choose another length";
    n += lead > 0 && lead < duration_s;
  }
  return n;
}

struct IndexRun {
  AcquisitionReport report;
  std::size_t expected_turns = 0;
  double angle_rms_deg = 0, speed_rms_rel = 0;
};

IndexRun run(const VirtualSetup& v) {
  const VirtualRigResult vr = v.write("wheel.wav", false);
  AcquireOptions o;
  o.progress = false;
  OpenedRecording rec = open_with_manifest(vr.recording, {});
  Crank out;
  IndexRun r;
  r.report = acquire(*rec.reader, rec.manifest, o, out);
  const RecordingInfo& info = r.report.recording;
  r.expected_turns = index_marks_inside(v, static_cast<double>(info.frames) / info.sample_rate_hz) - 1;
  const CrankDrive drive = v.drive();
  std::vector<double> angle, speed;
  const std::size_t step = std::max<std::size_t>(1, out.time.size() / 20000);
  for (std::size_t i = 0; i < out.time.size(); i += step) {
    const CrankState t = drive.at(out.time[i]);
    angle.push_back(std::remainder(out.crank[i] - t.angle_rad, units::kTwoPi));
    speed.push_back((out.omega[i] - t.speed_rad_s) / drive.mean_speed_rad_s);
  }
  r.angle_rms_deg = units::rad_to_deg(rms(angle));
  r.speed_rms_rel = rms(speed);
  return r;
}

class IndexOnEdge : public ::testing::TestWithParam<IndexCase> {};

TEST_P(IndexOnEdge, EveryTurnCountedAndPositionZeroIsTheEdge) {
  const IndexCase c = GetParam();
  const IndexRun r = run(index_setup(c, c.encoder ? 12 : 40));
  std::printf("  %-34s %3zu turns (expected %3zu), %zu cut, angle %.5f deg RMS, speed %.5f %% RMS\n", c.name,
              r.report.revolutions, r.expected_turns, r.report.wheel.turns_cut, r.angle_rms_deg,
              100 * r.speed_rms_rel);
  EXPECT_EQ(r.report.wheel.turns_cut, 0u);
  EXPECT_EQ(r.report.revolutions, r.expected_turns);
  // A whole pitch off (a turn named one edge early or late) would be 6° for
  // the wheel, 0.088° for the encoder's quarter line.
  EXPECT_LE(r.angle_rms_deg, c.encoder ? 0.02 : 0.01 + 0.5 * c.tooth_error_deg);
  EXPECT_LE(r.speed_rms_rel, c.tooth_error_deg > 0 ? 0.01 : 0.002);
}

INSTANTIATE_TEST_SUITE_P(
    Wheels, IndexOnEdge,
    ::testing::Values(IndexCase{"encoder 1024, Z gated, 20 dB 409.6k", true, 0.0, 20, 0, 409600},
                      IndexCase{"encoder 1024, Z gated, 30 dB", true, 0.0, 30, 0},
                      IndexCase{"encoder 1024, Z gated, 40 dB", true, 0.0, 40, 0},
                      IndexCase{"encoder 1024, Z an eighth early, 30 dB", true, -0.125, 30, 0},
                      IndexCase{"60 teeth, index on tooth 0, 20 dB", false, 0.0, 20, 0},
                      IndexCase{"60 teeth, index on tooth 0, 30 dB", false, 0.0, 30, 0},
                      IndexCase{"60 teeth, index on tooth 0, 40 dB", false, 0.0, 40, 0},
                      IndexCase{"60 teeth +-0.2 deg, index on edge", false, 0.0, 30, 0.2},
                      IndexCase{"60 teeth, index 0.75 pitch early", false, -0.75, 30, 0},
                      IndexCase{"60 teeth, index half a pitch early", false, -0.5, 30, 0},
                      IndexCase{"60 teeth, index 0.2 pitch late", false, 0.2, 30, 0}),
    [](const ::testing::TestParamInfo<IndexCase>& i) { return "case" + std::to_string(i.index); });

}  // namespace
}  // namespace fourbar

#include "acquire/index_marks.hpp"

namespace fourbar {
namespace {

// The race itself, on edge times alone: 60 edges per turn, each mark a
// sample (1/40 pitch) before or after its edge in a random pattern, or at any
// fixed phase within the pitch: every mark names the edge of its turn.
TEST(IndexMarks, OneSampleRaceNeverChangesTheEdgeNamed) {
  const int P = 60, turns = 50;
  std::vector<double> edges;
  for (int i = 0; i < P * turns; ++i) edges.push_back(1.0 + i);  // one pitch = 1 s, 40 samples
  const double sample = 1.0 / 40;
  unsigned state = 12345;
  for (double phase : {0.0, 0.1, 0.24, 0.3, 0.5, 0.7, 0.9}) {
    std::vector<double> marks;
    for (int t = 0; t < turns; ++t) {
      state = state * 1103515245u + 12345u;
      const double race = (state >> 16) % 3 == 0 ? -sample : (state >> 16) % 3 == 1 ? sample : 0.0;
      marks.push_back(edges[static_cast<std::size_t>(t * P + 7)] + phase + race);
    }
    const IndexPlacement p = place_index_marks(edges, marks);
    ASSERT_EQ(p.reference_edges.size(), static_cast<std::size_t>(turns) - (phase > 0.25 && marks.back() > edges.back() ? 1 : 0))
        << phase;
    // Coinciding (up to a quarter pitch after): the edge; else the first after.
    const std::size_t first = phase <= 0.25 ? 7 : 8;
    for (std::size_t t = 0; t < p.reference_edges.size(); ++t)
      EXPECT_EQ(p.reference_edges[t], first + t * P) << "phase " << phase << " turn " << t;
    EXPECT_NEAR(std::remainder(p.phase_pitch - phase, 1.0), 0.0, 0.02) << phase;
  }
}

}  // namespace
}  // namespace fourbar
