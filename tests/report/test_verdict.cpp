// The verdict (report/verdict.hpp) branch by branch on synthetic inputs, its
// reading of a record and a fit.json, and the terminal table's format.
#include <gtest/gtest.h>

#include <sstream>

#include "report/html_verdict.hpp"
#include "report/verdict.hpp"
#include "report/verdict_table.hpp"

namespace fourbar {
namespace {

using nlohmann::json;

/// A clean recording with a clearance effect the model matches.
VerdictInputs clean() {
  VerdictInputs in;
  in.setup_checked = true;
  in.revolutions = 40;
  in.speed_mean_rpm = 300;
  in.speed_std_rpm = 0.9;  // 0.3 %
  in.nominal_rms = 100;
  in.floor_rms = 2;  // 2 %
  in.clearance_mm = 0.254;
  in.effect_to_floor = 8;
  in.model_effect_to_floor = 9;
  in.spread_rms = 40, in.model_spread_rms = 45;
  in.nominal_band_orders = 5;
  in.a_time = 1.05, in.a_spectral = 1.1;
  in.orders_used = {6, 7, 9};
  in.restitution = 0.5, in.contact = "smooth";
  return in;
}

TEST(Verdict, CleanRecordingIsGoodInEveryPart) {
  const Verdict v = verdict_of(clean());
  EXPECT_EQ(v.setup.level, VerdictLevel::good);
  EXPECT_EQ(v.measurement.level, VerdictLevel::good) << v.measurement.sentence;
  EXPECT_EQ(v.effect.level, VerdictLevel::good);
  EXPECT_EQ(v.agreement.level, VerdictLevel::good);
  EXPECT_EQ(v.overall, VerdictLevel::good);
  EXPECT_NE(v.agreement.sentence.find("a (spectral) from orders 6, 7, 9 = 1.1"), std::string::npos) << v.agreement.sentence;
  EXPECT_NE(v.effect.sentence.find("A clearance effect is measured"), std::string::npos);
  EXPECT_EQ(v.effect.words, "seen (lines 8× floor)");
  EXPECT_EQ(v.a_from, "spectral");
}

TEST(Verdict, SetupFindingIsAProblemNamingTheKey) {
  VerdictInputs in = clean();
  in.findings = {{"axis_sign", "coupler_t", "[[channel]] name=\"coupler_t\" axis_sign", "1", "-1", 0.97},
                 {"position_mm", "rocker_t", "[[channel]] name=\"rocker_t\" position_mm", "300", "250", 0.6}};
  const Verdict v = verdict_of(in);
  EXPECT_EQ(v.setup.level, VerdictLevel::problem);
  EXPECT_EQ(v.overall, VerdictLevel::problem);
  EXPECT_NE(v.setup.sentence.find("change [[channel]] name=\"coupler_t\" axis_sign"), std::string::npos) << v.setup.sentence;
  EXPECT_NE(v.setup.sentence.find("1 more"), std::string::npos);
  in.findings.clear();
  in.setup_checked = false;
  in.setup_not_checked = "no accelerometer channel fits";
  EXPECT_EQ(verdict_of(in).setup.level, VerdictLevel::attention);
}

TEST(Verdict, MeasurementQualityBranches) {
  VerdictInputs in = clean();
  in.floor_rms = 10;  // 10 %: attention, and how many turns to reach 5 %: 40·(10/5)² = 160
  Verdict v = verdict_of(in);
  EXPECT_EQ(v.measurement.level, VerdictLevel::attention);
  EXPECT_NE(v.measurement.sentence.find("record about 160 turns (32 s at 300 rpm)"), std::string::npos) << v.measurement.sentence;
  in.floor_rms = 20;  // 20 %: problem
  EXPECT_EQ(verdict_of(in).measurement.level, VerdictLevel::problem);

  in = clean();
  in.revolutions = 4;  // no floor can be estimated
  EXPECT_EQ(verdict_of(in).measurement.level, VerdictLevel::problem);

  in = clean();
  in.revolutions_clipped = 2;  // 2 of 42
  v = verdict_of(in);
  EXPECT_EQ(v.measurement.level, VerdictLevel::attention);
  EXPECT_NE(v.measurement.sentence.find("2 of 42 turns clipped"), std::string::npos);
  in.revolutions_clipped = 20;  // 20 of 60 > 25 %
  EXPECT_EQ(verdict_of(in).measurement.level, VerdictLevel::problem);

  in = clean();
  in.speed_std_rpm = 6;  // 2 %
  EXPECT_EQ(verdict_of(in).measurement.level, VerdictLevel::attention);
  in.speed_std_rpm = 12;  // 4 %
  EXPECT_EQ(verdict_of(in).measurement.level, VerdictLevel::problem);

  in = clean();
  in.clipping_checked = false;
  v = verdict_of(in);
  EXPECT_EQ(v.measurement.level, VerdictLevel::good);
  EXPECT_NE(v.measurement.sentence.find("Clipping was not checked"), std::string::npos);
}

TEST(Verdict, ClearanceEffectBranches) {
  VerdictInputs in = clean();
  // Nothing above the floor while the model expects a strong effect: the manifest or the bearing is wrong.
  in.effect_to_floor = 1.1, in.spread_rms = 1.5;
  Verdict v = verdict_of(in);
  EXPECT_EQ(v.effect.level, VerdictLevel::problem);
  EXPECT_NE(v.effect.sentence.find("No clearance effect measurable above the noise floor"), std::string::npos);
  EXPECT_NE(v.effect.sentence.find("check clearance_mm"), std::string::npos);
  EXPECT_EQ(v.agreement.level, VerdictLevel::not_judged) << "a compares the model with noise";
  // Nothing expected either (a clearance-free rig described as such).
  in.model_effect_to_floor = 1.0, in.model_spread_rms = 1.0;
  v = verdict_of(in);
  EXPECT_EQ(v.effect.level, VerdictLevel::good);
  EXPECT_EQ(v.effect.words, "none");
  // Between: marginal, and how many turns would raise the lines to 3× (40·(3/2.5)² = 58).
  in = clean();
  in.effect_to_floor = 2.5, in.spread_rms = 7;
  v = verdict_of(in);
  EXPECT_EQ(v.effect.level, VerdictLevel::attention);
  EXPECT_NE(v.effect.sentence.find("record about 58 turns"), std::string::npos) << v.effect.sentence;
  // Scatter alone (chaotic impacts average out of the order lines) is an effect.
  in.effect_to_floor = 1.2, in.spread_rms = 30;
  EXPECT_EQ(verdict_of(in).effect.level, VerdictLevel::good);
  // No floor and no scatter: not judged.
  in.effect_to_floor.reset(), in.spread_rms = 0;
  EXPECT_EQ(verdict_of(in).effect.level, VerdictLevel::not_judged);
}

TEST(Verdict, ModelAgreementSaysHowToAct) {
  VerdictInputs in = clean();
  in.a_spectral = 1.6;
  Verdict v = verdict_of(in);
  EXPECT_EQ(v.agreement.level, VerdictLevel::attention);
  EXPECT_NE(v.agreement.sentence.find("more violent"), std::string::npos);
  EXPECT_NE(v.agreement.sentence.find("lower the restitution"), std::string::npos);
  EXPECT_NE(v.agreement.sentence.find("fourbar fit"), std::string::npos);
  in.a_spectral = 0.6;
  v = verdict_of(in);
  EXPECT_EQ(v.agreement.level, VerdictLevel::attention);
  EXPECT_NE(v.agreement.sentence.find("raise the restitution"), std::string::npos);
  in.a_spectral = 0.3;
  EXPECT_EQ(verdict_of(in).agreement.level, VerdictLevel::problem);
  in.a_spectral = 3.0;
  EXPECT_EQ(verdict_of(in).agreement.level, VerdictLevel::problem);
  // No order qualifies: the time-domain factor is used and named.
  in.orders_used.clear();
  in.a_time = 0.9;
  v = verdict_of(in);
  EXPECT_EQ(v.agreement.level, VerdictLevel::good);
  EXPECT_NE(v.agreement.sentence.find("a (time) = 0.9"), std::string::npos) << v.agreement.sentence;
  // Time and spectral far apart: a word on why.
  in = clean();
  in.a_time = 0.5;
  EXPECT_NE(verdict_of(in).agreement.sentence.find("a (time) = 0.5 differs"), std::string::npos);
}

TEST(Verdict, ChaoticEffectIsJudgedByTheScatter) {
  // Impacts that differ from turn to turn: the order lines of the average stand at the floor, the
  // turns scatter 40 % of the nominal response; the model scatters 44 %.
  VerdictInputs in = clean();
  in.effect_to_floor = 1.2, in.spread_rms = 40, in.model_spread_rms = 44;
  in.a_spectral = 0.33, in.a_time = 0.85;
  const Verdict v = verdict_of(in);
  EXPECT_EQ(v.effect.level, VerdictLevel::good);
  EXPECT_EQ(v.effect.words, "seen (scatter 40 %)");
  ASSERT_TRUE(v.a);
  EXPECT_DOUBLE_EQ(*v.a, 1.1);
  EXPECT_EQ(v.a_from, "scatter");
  EXPECT_EQ(v.agreement.level, VerdictLevel::good) << v.agreement.sentence;
  EXPECT_NE(v.agreement.sentence.find("chaotic"), std::string::npos);
  EXPECT_NE(v.agreement.sentence.find("a (spectral) = 0.33"), std::string::npos);
  EXPECT_EQ(verdict_json(v)["a_from"], "scatter");
}

// The sample session's complaint: a large chaotic clearance effect leaves
// its scatter in the averaged curve's floor (20 % there), which the
// measurement part read as noise ("problem"). When the model at this
// clearance scatters too, the floor is the effect's, and the measurement is
// judged by the standard error of the a the verdict judges by.
TEST(Verdict, ChaoticScatterIsNotAMeasurementFault) {
  VerdictInputs in = clean();
  in.effect_to_floor = 1.3, in.spread_rms = 80, in.model_spread_rms = 81;  // chaotic, model agrees
  in.floor_rms = 20;                                                        // 20 % floor in the average
  in.revolutions = 15;
  in.scatter_relative_error = 0.06;
  Verdict v = verdict_of(in);
  EXPECT_EQ(v.measurement.level, VerdictLevel::good) << v.measurement.sentence;
  EXPECT_EQ(v.measurement.words, "ok");
  EXPECT_NE(v.measurement.sentence.find("a (scatter) uncertain by 6 %"), std::string::npos) << v.measurement.sentence;
  EXPECT_NE(v.measurement.sentence.find("not a measurement fault"), std::string::npos) << v.measurement.sentence;
  EXPECT_EQ(v.overall, VerdictLevel::good);
  // Too few turns for the a it judges by: attention, and how many to record.
  in.scatter_relative_error = 0.2;
  v = verdict_of(in);
  EXPECT_EQ(v.measurement.level, VerdictLevel::attention) << v.measurement.sentence;
  EXPECT_EQ(v.measurement.words, "a ± 20 %");
  EXPECT_NE(v.measurement.sentence.find("record about 39 turns"), std::string::npos) << v.measurement.sentence;
  in.scatter_relative_error = 0.3;
  EXPECT_EQ(verdict_of(in).measurement.level, VerdictLevel::problem);
  // A noisy sensor scatters too, but the model does not: the floor stays a measurement problem.
  in.model_spread_rms = 5, in.scatter_relative_error = 0.06;
  v = verdict_of(in);
  EXPECT_EQ(v.measurement.level, VerdictLevel::problem) << v.measurement.sentence;
  EXPECT_EQ(v.measurement.words.rfind("floor 20 %", 0), 0u) << v.measurement.words;
}

// Every output iterates one list of parts: a part more is one entry there.
TEST(Verdict, PartsAreOneList) {
  const auto parts = verdict_parts();
  ASSERT_EQ(parts.size(), 5u);
  const Verdict v = verdict_of(clean());
  const json j = verdict_json(v);
  for (const VerdictPartInfo& p : parts) {
    EXPECT_EQ(j[p.key]["level"], to_string((v.*p.part).level)) << p.key;
    EXPECT_EQ(j[p.key]["words"], (v.*p.part).words) << p.key;
  }
  EXPECT_EQ(std::string(parts[0].label), "set-up");
  EXPECT_EQ(&(v.*parts[3].part), &v.family);
  EXPECT_EQ(&(v.*parts[4].part), &v.agreement);
}

// a (scatter) is said with its standard error, and the sentence says whether
// the turns recorded resolve a difference from 1.
TEST(Verdict, ScatterRatioCarriesItsErrorAndSaysWhatItResolves) {
  VerdictInputs in = clean();
  in.effect_to_floor = 1.2, in.spread_rms = 40, in.model_spread_rms = 28;  // a = 0.7
  in.scatter_relative_error = 0.1;                                          // ± 0.07: 1 is 4.3 SE away
  Verdict v = verdict_of(in);
  ASSERT_TRUE(v.a && v.a_standard_error);
  EXPECT_DOUBLE_EQ(*v.a_standard_error, 0.07);
  EXPECT_EQ(v.agreement.words, "a 0.7 ± 0.07 (scatter)");
  EXPECT_EQ(v.agreement.level, VerdictLevel::attention);
  EXPECT_NE(v.agreement.sentence.find("standard error of 0.07 from 40 measured turns"), std::string::npos)
      << v.agreement.sentence;
  EXPECT_EQ(v.agreement.sentence.find("do not resolve"), std::string::npos) << "0.7 ± 0.07 is resolved";
  EXPECT_DOUBLE_EQ(verdict_json(v)["a_standard_error"].get<double>(), 0.07);

  in.scatter_relative_error = 0.25;  // ± 0.175: 1 is within 2 SE
  v = verdict_of(in);
  EXPECT_EQ(v.agreement.level, VerdictLevel::attention) << "the level keeps its documented thresholds";
  EXPECT_NE(v.agreement.sentence.find("these turns do not resolve the difference; record more turns"), std::string::npos)
      << v.agreement.sentence;

  in.model_spread_rms = 44, in.scatter_relative_error = 0.2;  // a = 1.1 ± 0.22: agreement not resolved either
  v = verdict_of(in);
  EXPECT_EQ(v.agreement.level, VerdictLevel::good);
  EXPECT_NE(v.agreement.sentence.find("agreement is not resolved either"), std::string::npos) << v.agreement.sentence;

  in.model_spread_rms = 48, in.scatter_relative_error = 0.05;  // a = 1.2 ± 0.06: 3.3 SE from 1, inside 25 %
  v = verdict_of(in);
  EXPECT_EQ(v.agreement.level, VerdictLevel::good);
  EXPECT_NE(v.agreement.sentence.find("differs from 1 by more than 2 standard errors, though within 25 %"), std::string::npos)
      << v.agreement.sentence;

  in.scatter_relative_error.reset();  // an older record: no error, nothing claimed
  v = verdict_of(in);
  EXPECT_FALSE(v.a_standard_error);
  EXPECT_EQ(v.agreement.words, "a 1.2 (scatter)");
  EXPECT_EQ(v.agreement.sentence.find("standard error"), std::string::npos);
  EXPECT_TRUE(verdict_json(v)["a_standard_error"].is_null());
}

// A theory averaged over one turn has no scatter (a (scatter) = 0 would
// read "the model is infinitely gentler"): the agreement asks for turns.
TEST(Verdict, ScatterNeedsTheModelsTurns) {
  VerdictInputs in = clean();
  in.effect_to_floor = 1.2, in.spread_rms = 40, in.model_spread_rms = 0;
  in.model_revolutions = 1;
  Verdict v = verdict_of(in);
  EXPECT_FALSE(v.a);
  EXPECT_EQ(v.agreement.level, VerdictLevel::attention);
  EXPECT_EQ(v.agreement.words, "too few model turns");
  EXPECT_NE(v.agreement.sentence.find("averaged 1 turn, too few"), std::string::npos) << v.agreement.sentence;
  EXPECT_NE(v.agreement.sentence.find("averaged_revolutions = 20"), std::string::npos);
  in.model_revolutions = kMinModelTurnsForScatter, in.model_spread_rms = 44;
  v = verdict_of(in);
  ASSERT_TRUE(v.a);
  EXPECT_EQ(v.a_from, "scatter");
  // Not chaotic (the effect stands in the order lines): the model's turns do not matter.
  in = clean();
  in.model_revolutions = 1;
  EXPECT_EQ(verdict_of(in).a_from, "spectral");
}

// The e = 0.8 virtual-rig session's 250 rpm recording (docs/fit.md "A
// periodic recording"): its turns alternate between two patterns, the
// model's at the same settings are irregular. a (scatter) may then agree by
// chance: the verdict says so and does not read "good".
TEST(Verdict, APeriodicMeasuredMotionIsNamedAndWeighed) {
  VerdictInputs in = clean();
  in.effect_to_floor = 1.3, in.spread_rms = 80, in.model_spread_rms = 82;  // chaotic, a (scatter) 1.03
  in.scatter_relative_error = 0.06;
  in.model_revolutions = 20;
  Verdict v = verdict_of(in);
  ASSERT_EQ(v.a_from, "scatter");
  EXPECT_EQ(v.agreement.level, VerdictLevel::good);
  EXPECT_EQ(v.agreement.sentence.find("repeat"), std::string::npos) << v.agreement.sentence;

  in.repeat = VerdictInputs::Repeat{2, 0.14, 1.41, 0.98, 20};
  v = verdict_of(in);
  EXPECT_EQ(v.agreement.level, VerdictLevel::attention) << v.agreement.sentence;
  EXPECT_NE(v.agreement.words.find("(scatter), turns repeat every 2"), std::string::npos) << v.agreement.words;
  EXPECT_NE(v.agreement.sentence.find("The measured turns repeat every 2 turns (turn i against turn i + 2: 0.14 of what "
                                      "irregular turns give, against 1.4 for neighbouring turns)"),
            std::string::npos)
      << v.agreement.sentence;
  EXPECT_NE(v.agreement.sentence.find("the model's turns do not (0.98): a (scatter) compares a periodic motion with an "
                                      "irregular one"),
            std::string::npos)
      << v.agreement.sentence;
  EXPECT_EQ(v.overall, VerdictLevel::attention);

  // The model repeats at that lag too: the same kind of motion, judged as before.
  in.repeat->model_ratio = 0.12;
  v = verdict_of(in);
  EXPECT_EQ(v.agreement.level, VerdictLevel::good) << v.agreement.sentence;
  EXPECT_NE(v.agreement.sentence.find("the model's turns repeat at that lag too (0.12)"), std::string::npos) << v.agreement.sentence;

  // Too few model turns to tell: said, with the setting; the level is left alone.
  in.repeat->model_ratio.reset();
  in.repeat->model_turns = 6;
  v = verdict_of(in);
  EXPECT_EQ(v.agreement.level, VerdictLevel::good);
  EXPECT_NE(v.agreement.sentence.find("the model's 6 turns are too few to tell whether it repeats (at least 8)"), std::string::npos)
      << v.agreement.sentence;

  // Not chaotic (a from the order lines): the averages then hold two different motions.
  in = clean();
  in.repeat = VerdictInputs::Repeat{3, 0.2, 1.2, 0.9, 20};
  v = verdict_of(in);
  EXPECT_EQ(v.a_from, "spectral");
  EXPECT_EQ(v.agreement.level, VerdictLevel::attention);
  EXPECT_NE(v.agreement.sentence.find("repeat every 3 turns"), std::string::npos) << v.agreement.sentence;
  EXPECT_NE(v.agreement.sentence.find("a compares the averages of two different motions"), std::string::npos) << v.agreement.sentence;
}

// A 9-turn recording of a drive of period 2 (tests/cli AnalyzeCommand
// "may repeat"): 4 turns measured after the segment ends, ratio_2 0.17. The
// period is said with what to do, and not weighed: the level stays.
TEST(Verdict, AnUnconfirmedPeriodIsSaidNotWeighed) {
  VerdictInputs in = clean();
  in.effect_to_floor = 1.3, in.spread_rms = 80, in.model_spread_rms = 82;  // chaotic, a (scatter) 1.03
  in.scatter_relative_error = 0.06;
  in.model_revolutions = 20;
  const Verdict before = verdict_of(in);
  ASSERT_EQ(before.agreement.level, VerdictLevel::good);
  VerdictInputs::Repeat rep;
  rep.period = 2, rep.ratio = 0.17, rep.neighbours = 1.38, rep.confirmed = false, rep.turns = 4;
  in.repeat = rep;
  const Verdict v = verdict_of(in);
  EXPECT_EQ(v.agreement.level, VerdictLevel::good) << v.agreement.sentence;
  EXPECT_EQ(v.agreement.words, before.agreement.words);
  EXPECT_NE(v.agreement.sentence.find("The measured turns may repeat every 2 turns (turn i against turn i + 2: 0.17 of what "
                                      "irregular turns give, against 1.4 for neighbouring turns), but the 4 turns it compares "
                                      "(each pulse-train segment's first and last two stay out) are too few to tell (at "
                                      "least 8): record more turns."),
            std::string::npos)
      << v.agreement.sentence;
  EXPECT_EQ(v.agreement.sentence.find("do not ("), std::string::npos) << "no model comparison for an unconfirmed period";
}

TEST(Verdict, FitParametersAreNamed) {
  VerdictInputs in = clean();
  in.a_spectral = 1.6;
  in.fit = VerdictFit{"fit/fit.json", 0.35, 0.3, 0.41, true, "smooth", std::nullopt, 1.02};
  const Verdict v = verdict_of(in);
  EXPECT_NE(v.agreement.sentence.find("The fit (fit/fit.json) gives e = 0.35 [0.3, 0.41]"), std::string::npos)
      << v.agreement.sentence;
  EXPECT_NE(v.agreement.sentence.find("a = 1.02 for this recording"), std::string::npos);
  EXPECT_NE(v.agreement.sentence.find("set [theory] restitution = 0.35"), std::string::npos);
  EXPECT_EQ(v.agreement.sentence.find("`fourbar fit SESSION_DIR`"), std::string::npos) << "no advice to run what was run";
}

json record() {
  return json{{"name", "r.flac"},
              {"status", "ok"},
              {"setup_check", {{"status", "ok"}, {"findings", json::array()}, {"fit", 0.99}}},
              {"operating_point", {{"speed_rpm", 300.0}, {"clearance_mm", 0.254}, {"revolutions_averaged", 30}}},
              {"acquisition", {{"revolutions_clipped", 1}, {"clipping_checked", true}, {"speed_rpm", {{"mean", 300.0}, {"std", 0.6}}}}},
              {"theory", {{"settings", {{"restitution", 0.5}, {"contact", "smooth"}, {"averaged_revolutions", 20}}}}},
              {"series", {{"alpha3_rad_s2", {{"measured_std", {3.0, 4.0}}, {"clearance_std", {6.0, 8.0}}}}}},
              {"metrics",
               {{"alpha3_rad_s2",
                 {{"nominal_rms", 100.0},
                  {"magnification",
                   {{"time_domain", 0.9},
                    {"spectral", 1.1},
                    {"orders_used", {6, 8}},
                    {"nominal_band_orders", 5},
                    {"floor_rms", 2.0},
                    {"effect_to_floor", 7.0},
                    {"model_effect_to_floor", 8.0},
                    {"scatter_relative_error", 0.12}}}}}}}};
}

TEST(VerdictInputs, TurnsRepeatReadFromTheRecord) {
  json r = record();
  EXPECT_FALSE(verdict_inputs(r).repeat) << "older records have no turns_repeat";
  auto repeat = [](std::size_t turns, std::size_t period, double ratio, std::vector<double> lags) {
    return json{{"turns", turns}, {"period_turns", period}, {"ratio", ratio}, {"neighbours", lags[0]}, {"by_lag", lags}};
  };
  r["metrics"]["alpha3_rad_s2"]["turns_repeat"] = {{"measured", repeat(25, 0, 1.0, {0.98, 1.0, 1.02, 0.97})},
                                                   {"model", repeat(20, 0, 1.0, {1.0, 1.0, 1.0, 1.0})}};
  EXPECT_FALSE(verdict_inputs(r).repeat) << "no period measured";
  r["metrics"]["alpha3_rad_s2"]["turns_repeat"]["measured"] = repeat(25, 2, 0.14, {1.41, 0.14, 1.39, 0.15});
  VerdictInputs in = verdict_inputs(r);
  ASSERT_TRUE(in.repeat);
  EXPECT_EQ(in.repeat->period, 2u);
  EXPECT_DOUBLE_EQ(in.repeat->ratio, 0.14);
  EXPECT_DOUBLE_EQ(in.repeat->neighbours, 1.41);
  ASSERT_TRUE(in.repeat->model_ratio);
  EXPECT_DOUBLE_EQ(*in.repeat->model_ratio, 1.0);
  // The model's turns too few for lag 2 (2·2 + 4 = 8): no ratio read.
  r["metrics"]["alpha3_rad_s2"]["turns_repeat"]["model"]["turns"] = 7;
  in = verdict_inputs(r);
  ASSERT_TRUE(in.repeat);
  EXPECT_FALSE(in.repeat->model_ratio);
  EXPECT_EQ(in.repeat->model_turns, 7u);
  EXPECT_TRUE(in.repeat->confirmed);
  // A period these turns cannot confirm: read as unconfirmed, its ratio from by_lag.
  json unconfirmed = repeat(4, 0, 1.38, {1.38, 0.17, 1.0, 1.0});
  unconfirmed["unconfirmed_period_turns"] = 2;
  r["metrics"]["alpha3_rad_s2"]["turns_repeat"]["measured"] = unconfirmed;
  in = verdict_inputs(r);
  ASSERT_TRUE(in.repeat);
  EXPECT_FALSE(in.repeat->confirmed);
  EXPECT_EQ(in.repeat->period, 2u);
  EXPECT_DOUBLE_EQ(in.repeat->ratio, 0.17);
  EXPECT_DOUBLE_EQ(in.repeat->neighbours, 1.38);
  EXPECT_EQ(in.repeat->turns, 4u);
  unconfirmed["unconfirmed_period_turns"] = 0;
  r["metrics"]["alpha3_rad_s2"]["turns_repeat"]["measured"] = unconfirmed;
  EXPECT_FALSE(verdict_inputs(r).repeat) << "neither a period nor an unconfirmed one";
}

TEST(VerdictInputs, ReadFromTheRecordAndTheFit) {
  const json fit = {{"parameters", {{"restitution", {{"value", 0.4}, {"low", 0.3}, {"high", 0.5}, {"identifiable", false}}}}},
                    {"fitted", {{"restitution", 0.4}, {"contact", "stick-slip"}, {"friction_coefficient", 0.1}}},
                    {"recordings", {{{"file", "r.flac"}, {"magnification_fitted", 0.97}, {"magnification_fitted_standard_error", 0.2}}}}};
  const VerdictInputs in = verdict_inputs(record(), &fit, "fit/fit.json");
  EXPECT_TRUE(in.setup_checked);
  EXPECT_EQ(in.revolutions, 30u);
  EXPECT_EQ(in.revolutions_clipped, 1u);
  EXPECT_DOUBLE_EQ(in.speed_std_rpm, 0.6);
  EXPECT_DOUBLE_EQ(in.spread_rms, std::sqrt((9.0 + 16.0) / 2));
  EXPECT_DOUBLE_EQ(in.model_spread_rms, std::sqrt((36.0 + 64.0) / 2));
  EXPECT_EQ(in.orders_used, (std::vector<int>{6, 8}));
  EXPECT_EQ(*in.effect_to_floor, 7.0);
  EXPECT_EQ(*in.scatter_relative_error, 0.12);
  EXPECT_EQ(in.model_revolutions, 20u);
  ASSERT_TRUE(in.fit);
  EXPECT_DOUBLE_EQ(in.fit->restitution, 0.4);
  EXPECT_FALSE(in.fit->restitution_identifiable);
  EXPECT_EQ(*in.fit->friction, 0.1);
  EXPECT_EQ(*in.fit->magnification_fitted, 0.97);
  EXPECT_EQ(*in.fit->magnification_fitted_standard_error, 0.2);
  // a is said with its error: from a few dozen turns it is noise-limited.
  EXPECT_NE(verdict_of(in).agreement.sentence.find("with it a = 0.97 ± 0.2 for this recording"), std::string::npos)
      << verdict_of(in).agreement.sentence;
  EXPECT_FALSE(verdict_inputs(record()).fit);
  // The JSON carries levels and sentences.
  const json j = verdict_json(verdict_of(in));
  for (const char* p : {"setup", "measurement", "clearance_effect", "model_agreement"}) {
    EXPECT_TRUE(j[p]["level"].is_string()) << p;
    EXPECT_FALSE(j[p]["sentence"].get<std::string>().empty()) << p;
  }
  EXPECT_EQ(j["overall"], "attention");  // one clipped turn
}

TEST(VerdictTable, ColumnsAlignedInCharacters) {
  json a = record();
  a["verdict"] = verdict_json(verdict_of(verdict_inputs(a)));
  json failed = {{"name", "a_much_longer_recording_name.flac"}, {"status", "failed"}};
  const std::string t = verdict_text_table(json::array({a, failed}));
  std::istringstream lines(t);
  std::vector<std::string> l;
  for (std::string s; std::getline(lines, s);) l.push_back(s);
  ASSERT_EQ(l.size(), 3u) << t;
  EXPECT_EQ(l[0].rfind("recording", 0), 0u);
  // Every column starts at the same character in every line: "status" over "ok" over "failed".
  auto column = [](const std::string& line, const std::string& word) {
    const auto at = line.find(word);
    return at == std::string::npos ? std::string::npos : display_width(line.substr(0, at));
  };
  EXPECT_EQ(column(l[0], "status"), column(l[1], "ok"));
  EXPECT_EQ(column(l[0], "status"), column(l[2], "failed"));
  EXPECT_EQ(column(l[0], "set-up"), column(l[1], "good: matches"));
  // The a the verdict judges by comes right after the overall verdict, before the parts.
  EXPECT_EQ(column(l[0], "  a  ") + 2, column(l[1], "1.1 (spectral)")) << t;
  EXPECT_LT(column(l[1], "1.1 (spectral)"), column(l[1], "good: matches")) << t;
  EXPECT_EQ(column(l[0], "verdict"), column(l[1], "attention"));
  EXPECT_EQ(display_width("α3 ±×"), 5u);
}

TEST(HtmlVerdict, BoxAndSummaryTable) {
  json a = record();
  EXPECT_TRUE(verdict_box(a).empty());
  a["verdict"] = verdict_json(verdict_of(verdict_inputs(a)));
  const std::string box = verdict_box(a);
  EXPECT_NE(box.find("Verdict:"), std::string::npos);
  EXPECT_NE(box.find("v-attention"), std::string::npos);
  std::ostringstream h;
  verdict_summary_table(h, json::array({a, json{{"name", "bad.flac"}, {"status", "failed"}}}));
  EXPECT_NE(h.str().find("failed: not analysed"), std::string::npos);
  EXPECT_NE(h.str().find("href=\"#rec1\""), std::string::npos);
  const json mg = {{"orders_used", {6, 8}},
                   {"nominal_band_orders", 5},
                   {"orders", {{{"order", 12}, {"mains", true}}, {{"order", 6}, {"mains", false}}}}};
  EXPECT_EQ(spectral_orders_note(mg),
            "a (spectral) from orders 6, 8; left out: orders 1 … 5 (the nominal response's band); orders 12 (mains hum).");
}

}  // namespace
}  // namespace fourbar
