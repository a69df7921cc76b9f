// analyze_recording with the crank angle from a tooth wheel or an encoder,
// against the virtual rig's truth, when the crank speed changes within the
// turn (1 % slow drift, 0.5 % once- and 0.3 % twice-per-turn, 30 dB SNR):
// the conversion of tangential acceleration to α3 uses the crank's speed and
// acceleration per sample, which one pulse per turn cannot see.
// Targets: averaged α3 ≤ 0.5 % and ω3 ≤ 0.1 % relative RMS error.

#include <gtest/gtest.h>

#include <cstdio>

#include "acquire/wheel_setup.hpp"
#include "virtual_session.hpp"

namespace fourbar {
namespace {

using testing::rel_rms_error;
using testing::row_mean;
using testing::VirtualSetup;
using testing::WheelKind;

struct Errors {
  double alpha3 = 0, omega3 = 0, alpha4 = 0, omega4 = 0;
  std::size_t revolutions = 0;
};

Errors analyse(const VirtualSetup& v, const std::string& name) {
  const VirtualRigResult written = v.write(name, false);
  AnalyzeOptions o;
  o.keep_revolutions = true;
  o.progress = false;
  const RecordingAnalysis a = analyze_recording(written.recording, {}, o);
  const testing::GridTruth t = testing::grid_truth(v, written, a, a.revolution_numbers);
  const std::size_t N = a.grid_points_per_rev;
  return {rel_rms_error(a.coupler->alpha_rad_s2.mean, row_mean(t.alpha3, N)),
          rel_rms_error(a.coupler->omega_rad_s.mean, row_mean(t.omega3, N)),
          rel_rms_error(a.rocker->alpha_rad_s2.mean, row_mean(t.alpha4, N)),
          rel_rms_error(a.rocker->omega_rad_s.mean, row_mean(t.omega4, N)), a.revolutions};
}

VirtualSetup lab(double revolutions) {
  VirtualSetup v;
  testing::housing_sensors(v);
  v.spec.revolutions = revolutions;
  v.spec.seed = 77;
  testing::in_turn_speed_change(v);
  return v;
}

void print(const char* name, const Errors& e) {
  std::printf("  %-24s %4zu revs  a3 %7.4f %%  w3 %7.4f %%  a4 %7.4f %%  w4 %7.4f %%\n", name, e.revolutions,
              100 * e.alpha3, 100 * e.omega3, 100 * e.alpha4, 100 * e.omega4);
}

TEST(AnalyzeWheel, InTurnSpeedChangeAgainstVirtualRigTruth) {
  std::printf("\n  averaged RMS error / RMS of truth, speed 1 %% slow + 0.5 %% once + 0.3 %% twice per turn, 30 dB\n");
  // One pulse per turn: the baseline that cannot see the change within the turn.
  const Errors once = analyse(lab(40), "once.wav");
  print("one pulse per turn", once);
  for (WheelKind kind : {WheelKind::teeth_with_index, WheelKind::missing_teeth, WheelKind::encoder}) {
    VirtualSetup v = lab(kind == WheelKind::encoder ? 8 : 40);
    testing::fit_wheel(v, kind);
    const Errors e = analyse(v, "wheel.wav");
    print(testing::wheel_name(kind), e);
    EXPECT_LE(e.alpha3, 0.005) << testing::wheel_name(kind);
    EXPECT_LE(e.omega3, 0.001) << testing::wheel_name(kind);
    EXPECT_LT(e.alpha3, once.alpha3) << testing::wheel_name(kind);
  }
}

}  // namespace
}  // namespace fourbar
