// The fit's numbers when the model family is rejected (fit/family_judgement.hpp,
// session_fit.hpp reject_model_family): nothing identifiable, no zero-width
// interval, the flag first in fit.json.
#include <gtest/gtest.h>

#include "fit/family_judgement.hpp"
#include "fit/fit_json.hpp"
#include "fit/session_fit.hpp"

namespace fourbar {
namespace {

/// A sharp profile (χ² 90/term-like misfit) whose surrogate interval was zero-width.
ParameterEstimate sharp_e() {
  ParameterEstimate p;
  p.name = "restitution";
  p.value = p.low = p.high = 0.976;
  p.identifiable = true;
  p.profile_at = {0.0, 0.143, 0.286, 0.429, 0.571, 0.714, 0.857, 1.0};
  p.profile_chi2 = {5000, 4000, 3100, 2500, 2000, 1500, 1000, 800};
  return p;
}

TEST(FamilyJudgement, WidenedIntervalIsNeverZeroWidthNorIdentifiable) {
  ParameterEstimate p = sharp_e();
  widen_for_model_error(p, 4.0, 1.0, 0.0, 1.0);
  EXPECT_FALSE(p.identifiable);
  EXPECT_LT(p.low, p.value);
  EXPECT_GE(p.high, p.value);
  EXPECT_NEAR(p.low, 0.857, 1e-12);  // out to the next grid point below the lowest
  EXPECT_NEAR(p.high, 1.0, 1e-12);
}

TEST(FamilyJudgement, ModelErrorScaleWidensFurther) {
  ParameterEstimate narrow = sharp_e(), wide = sharp_e();
  widen_for_model_error(narrow, 4.0, 1.0, 0.0, 1.0);
  widen_for_model_error(wide, 4.0, std::sqrt(100.0), 0.0, 1.0);  // χ²/ν = 100: Δ 400 above the bottom
  EXPECT_LT(wide.low, narrow.low);
  EXPECT_NEAR(wide.low, 0.714, 1e-12);  // 1000 (at 0.857) within 800 + 400, 1500 not: out to the grid point 0.714
}

FitResult rejected_fit() {
  FitResult f;
  f.parameters = {sharp_e()};
  ParameterEstimate mu;
  mu.name = "friction_coefficient";
  mu.value = mu.low = mu.high = 0.268;
  mu.profile_at = {0.0, 0.125, 0.25, 0.375, 0.5};
  mu.profile_chi2 = {900, 850, 800, 820, 870};
  f.parameters.push_back(mu);
  f.chi2 = 9000, f.terms = 100, f.interval_delta = 4.0;
  f.best = {0.976, ContactLaw::stick_slip, 0.268};
  return f;
}

TEST(FamilyJudgement, RejectionMarksEveryParameterAndTheJson) {
  FitResult f = rejected_fit();
  FitOptions o;
  reject_model_family(f, "rec.flac holds energy the model lacks", o);
  EXPECT_TRUE(f.model_family.rejected);
  EXPECT_NEAR(f.model_family.error_scale, std::sqrt(90.0), 1e-12);
  for (const ParameterEstimate& p : f.parameters) {
    EXPECT_FALSE(p.identifiable) << p.name;
    EXPECT_GT(p.high - p.low, 0) << p.name;
  }
  const nlohmann::json j = fit_to_json(f, {}, {1.0, ContactLaw::smooth, 0.0}, o);
  EXPECT_EQ(j["model_family"]["verdict"], "rejected");
  EXPECT_EQ(j["model_family"]["reasons"][0], "rec.flac holds energy the model lacks");
  EXPECT_FALSE(j["parameters"]["restitution"]["identifiable"].get<bool>());
  EXPECT_FALSE(j["parameters"]["friction_coefficient"]["identifiable"].get<bool>());
  EXPECT_LT(j["parameters"]["restitution"]["low"].get<double>(), j["parameters"]["restitution"]["high"].get<double>());
}

TEST(FamilyJudgement, AcceptedFamilyKeepsItsNumbers) {
  FitResult f = rejected_fit();
  FitOptions o;
  const nlohmann::json j = fit_to_json(f, {}, {1.0, ContactLaw::smooth, 0.0}, o);
  EXPECT_EQ(j["model_family"]["verdict"], "not rejected");
  EXPECT_TRUE(j["parameters"]["restitution"]["identifiable"].get<bool>());
}

// A rejection's note names the recordings whose turns repeat (a periodic
// motion the model's runs may not take), and only those.
TEST(FamilyJudgement, APeriodicRecordingIsNamedInTheNote) {
  std::vector<RecordingTarget> targets(2);
  targets[0].name = "rec_250rpm_0254mm.flac";
  targets[1].name = "rec_350rpm_0254mm.flac";
  for (RecordingTarget& t : targets) t.measured[0] = StatisticValues{};
  EXPECT_EQ(periodic_recordings_note(targets, {}), "");
  targets[0].repeat[0] = TurnRepeat{2, {1.41, 0.14, 1.41, 0.14}};
  targets[1].repeat[1] = TurnRepeat{3, {1.2, 1.2, 0.1, 1.2}};  // the rocker, which this recording has no channel of
  // The model's run at the best point: irregular.
  std::array<TurnRepeat, 2> irregular;
  irregular[0].by_lag = {1.0, 0.98, 1.01, 1.0};
  const std::string note = periodic_recordings_note(targets, {irregular, std::nullopt});
  EXPECT_NE(note.find("rec_250rpm_0254mm.flac's alpha3 repeats every 2 turns"), std::string::npos) << note;
  EXPECT_NE(note.find("0.14 of what irregular turns give"), std::string::npos) << note;
  EXPECT_NE(note.find("the model's run at the best point does not (0.98)"), std::string::npos) << note;
  EXPECT_NE(note.find("not reach it from the recording's start"), std::string::npos) << note;
  EXPECT_EQ(note.find("rec_350rpm"), std::string::npos) << note;
  // With Newton shooting on the model at the best point: a stable orbit found ...
  OrbitSearchResult found;
  found.starts = 7, found.converged = 2, found.stable_from = 1;
  found.orbits = {FoundOrbit{Eigen::Vector4d(5, 1, 2, 3), false, 8.0}, FoundOrbit{Eigen::Vector4d(0.15, -0.9, 9.2, 1.4), true, 4.5e-8}};
  const std::string with_orbit = periodic_recordings_note(targets, {irregular, std::nullopt}, {found, std::nullopt});
  EXPECT_NE(with_orbit.find("the model's run at the best point does not (0.98); Newton shooting on the model at the best "
                            "point (its turn map at the recording's mean speed, started from its own turn starts) finds a "
                            "stable period-2 motion from start 7 (a run on it repeats to 4.5e-08 of the clearance's scale)"),
            std::string::npos)
      << with_orbit;
  EXPECT_NE(with_orbit.find("So the rejection may come from the motion the runs took rather than from a wrong model"),
            std::string::npos)
      << with_orbit;
  EXPECT_EQ(with_orbit.find("A model may have"), std::string::npos) << with_orbit;
  // ... or none.
  OrbitSearchResult none;
  none.starts = 60, none.converged = 3;
  none.orbits = {FoundOrbit{Eigen::Vector4d(5, 1, 2, 3), false, 8.0}, FoundOrbit{Eigen::Vector4d(1, 1, 2, 3), false, 6.0}};
  const std::string without = periodic_recordings_note(targets, {irregular, std::nullopt}, {none, std::nullopt});
  EXPECT_NE(without.find("finds no stable period-2 motion from 60 starts (3 converged, onto 2 unstable orbits)"),
            std::string::npos)
      << without;
  EXPECT_NE(without.find("The search covers the best point only: a model with other parameters may hold the motion"),
            std::string::npos)
      << without;
  // A model that repeats at the same period: named, without the start's hint.
  std::array<TurnRepeat, 2> periodic = irregular;
  periodic[0].by_lag = {1.4, 0.05, 1.4, 0.05};
  const std::string both = periodic_recordings_note(targets, {periodic, std::nullopt});
  EXPECT_NE(both.find("repeats too (0.05)"), std::string::npos) << both;
  EXPECT_EQ(both.find("not reach it"), std::string::npos) << both;
}

// The orbit scan's note (fourbar fit --orbit-scan): per contact law, the e
// where a stable motion of the period was found, of those checked.
TEST(FamilyJudgement, OrbitScanNoteNamesWhereTheModelHoldsTheMotion) {
  EXPECT_EQ(orbit_scan_note("r.flac", 2, {}), "");
  std::vector<OrbitScanPoint> scan;
  for (double e : {0.7, 0.75, 0.8, 0.85}) scan.push_back({ContactParameters{e, ContactLaw::smooth, 0}, e == 0.8, e == 0.8 ? 49 : 60});
  for (double e : {0.7, 0.8}) scan.push_back({ContactParameters{e, ContactLaw::stick_slip, 0.25}, false, e == 0.8 ? 0 : 60});
  const std::string note = orbit_scan_note("rec_250rpm_0254mm.flac", 2, scan);
  EXPECT_NE(note.find("orbit scan of rec_250rpm_0254mm.flac: the model holds a stable period-2 motion (smooth) at e = 0.8 of "
                      "e = 0.7, 0.75, 0.8, 0.85; (stick-slip, mu 0.25) at none of e = 0.7, 0.8 (model run failed) (Newton shooting "
                      "from up to 60"),
            std::string::npos)
      << note;
  EXPECT_NE(note.find("may still hold one with a small basin"), std::string::npos) << note;
}

}  // namespace
}  // namespace fourbar
