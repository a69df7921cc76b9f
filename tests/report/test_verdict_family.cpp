// The verdict's model-family part (report/verdict_family.hpp): the
// unmodelled band named, the agreement judged below it only, "cannot be
// judged" instead of "good", and the record's JSON read back.
#include <gtest/gtest.h>

#include "report/verdict.hpp"
#include "report/verdict_family.hpp"

namespace fourbar {
namespace {

using nlohmann::json;

/// A chaotic clearance effect whose whole-band scatter the (wrong) model
/// happens to match: a (scatter) = 42/40 = 1.05, "good" without the check.
VerdictInputs chaotic_match() {
  VerdictInputs in;
  in.setup_checked = true;
  in.revolutions = 25;
  in.speed_mean_rpm = 250;
  in.speed_std_rpm = 0.5;
  in.nominal_rms = 100;
  in.floor_rms = 2;
  in.clearance_mm = 0.254;
  in.effect_to_floor = 1.5, in.model_effect_to_floor = 1.6;
  in.spread_rms = 40, in.model_spread_rms = 42;
  in.nominal_band_orders = 5;
  in.a_time = 1.0, in.a_spectral = 1.0;
  in.orders_used = {6, 7};
  in.restitution = 1.0, in.contact = "smooth";
  in.model_revolutions = 20;
  return in;
}

VerdictFamily ringing(std::optional<double> a_below) {
  VerdictFamily f;
  f.checked = true;
  f.checked_up_to_hz = 950;
  f.unmodelled = {{"narrow resonance", 575, 625, 600, 0.62, 40}};
  f.judged_below_hz = 575;
  f.a_scatter_below = a_below;
  return f;
}

TEST(VerdictFamily, WithoutTheCheckTheWrongModelLooksGood) {
  const Verdict v = verdict_of(chaotic_match());
  EXPECT_EQ(v.agreement.level, VerdictLevel::good);  // the failure the check exists for
  EXPECT_EQ(v.family.level, VerdictLevel::not_judged);
}

TEST(VerdictFamily, UnmodelledBandIsNamedAndAgreementJudgedBelowIt) {
  VerdictInputs in = chaotic_match();
  in.family = ringing(3.4);
  const Verdict v = verdict_of(in);
  EXPECT_EQ(v.family.level, VerdictLevel::attention);
  EXPECT_NE(v.family.sentence.find("narrow resonance at 575–625 Hz"), std::string::npos) << v.family.sentence;
  EXPECT_NE(v.family.sentence.find("62 % of the measured RMS"), std::string::npos) << v.family.sentence;
  EXPECT_EQ(v.agreement.level, VerdictLevel::problem) << v.agreement.sentence;
  ASSERT_TRUE(v.a);
  EXPECT_DOUBLE_EQ(*v.a, 3.4);
  EXPECT_EQ(v.a_from, "scatter below 575 Hz");
  EXPECT_NE(v.agreement.sentence.find("Judged below 575 Hz only"), std::string::npos) << v.agreement.sentence;
  EXPECT_EQ(v.overall, VerdictLevel::problem);
  const json j = verdict_json(v);
  EXPECT_EQ(j["model_family"]["level"], "attention");
}

TEST(VerdictFamily, AgreementBelowTheBandOnlyIsNeverGood) {
  VerdictInputs in = chaotic_match();
  in.family = ringing(1.05);
  const Verdict v = verdict_of(in);
  EXPECT_EQ(v.agreement.level, VerdictLevel::attention) << v.agreement.sentence;
  EXPECT_EQ(v.agreement.words, "a 1.1 (below 575 Hz), partial");  // two digits
  EXPECT_NE(v.agreement.sentence.find("but only there"), std::string::npos) << v.agreement.sentence;
}

TEST(VerdictFamily, NothingLeftBelowTheBandIsNotJudgedNeverGood) {
  VerdictInputs in = chaotic_match();
  in.family = ringing(std::nullopt);
  in.family->cannot_judge = "no turn-to-turn scatter is left below the band";
  const Verdict v = verdict_of(in);
  EXPECT_EQ(v.agreement.level, VerdictLevel::not_judged);
  EXPECT_EQ(v.agreement.words, "cannot be judged");
  EXPECT_FALSE(v.a);
  EXPECT_NE(v.agreement.sentence.find("cannot be judged"), std::string::npos);
}

TEST(VerdictFamily, CheckedWithNothingFoundHoldsAndChangesNothing) {
  VerdictInputs in = chaotic_match();
  VerdictFamily f;
  f.checked = true;
  f.checked_up_to_hz = 950;
  in.family = f;
  const Verdict v = verdict_of(in);
  EXPECT_EQ(v.family.level, VerdictLevel::good);
  EXPECT_EQ(v.family.words, "holds");
  EXPECT_EQ(v.agreement.level, VerdictLevel::good);
  EXPECT_EQ(v.a_from, "scatter");
}

// "Holds" claims no link vibration only when the elastic-link reference ran
// (the rig file gives the links' modes); without it, only a narrow line was
// looked for, and the sentence says so and how to give the modes.
TEST(VerdictFamily, HoldsSaysWhatWasNotLookedForWithoutModalData) {
  VerdictInputs in = chaotic_match();
  VerdictFamily f;
  f.checked = true;
  f.checked_up_to_hz = 950;
  in.family = f;
  const Verdict without = verdict_of(in);
  EXPECT_EQ(without.family.words, "holds");
  EXPECT_EQ(without.family.sentence.find("no link vibration"), std::string::npos) << without.family.sentence;
  EXPECT_NE(without.family.sentence.find("fourbar tap"), std::string::npos) << without.family.sentence;
  in.family->link_vibration_checked = true;
  const Verdict with = verdict_of(in);
  EXPECT_NE(with.family.sentence.find("no link vibration or sensor resonance found"), std::string::npos);
  // read from a record: the reference's object says it ran
  const json record = {{"model_family", {{"checked", true}, {"checked_up_to_hz", 950.0}, {"link_vibration", {{"checked", true}, {"present", false}}}}}};
  ASSERT_TRUE(verdict_family(record));
  EXPECT_TRUE(verdict_family(record)->link_vibration_checked);
  const json bare = {{"model_family", {{"checked", true}, {"checked_up_to_hz", 950.0}}}};
  EXPECT_FALSE(verdict_family(bare)->link_vibration_checked);
}

TEST(VerdictFamily, RecordJsonReadsBack) {
  ModelFamilyCheck c;
  c.checked = true;
  c.crank_hz = 250.0 / 60;
  c.checked_up_to_hz = 950;
  c.typical_ratio = 1.2;
  c.unmodelled = {{"broad ringing", 400, 700, 520, 0.3, 9}};
  c.judged_below_hz = 400;
  c.a_scatter_below = 2.5;
  json record = {{"model_family", model_family_json(c)}};
  const auto f = verdict_family(record);
  ASSERT_TRUE(f);
  EXPECT_TRUE(f->checked);
  ASSERT_EQ(f->unmodelled.size(), 1u);
  EXPECT_EQ(f->unmodelled[0].kind, "broad ringing");
  EXPECT_DOUBLE_EQ(f->unmodelled[0].peak_hz, 520);
  EXPECT_DOUBLE_EQ(*f->a_scatter_below, 2.5);
  EXPECT_DOUBLE_EQ(*f->judged_below_hz, 400);
  EXPECT_FALSE(verdict_family(json::object()));
  // Through verdict_inputs, as the report reads a record.
  EXPECT_TRUE(verdict_inputs(record).family);
}

}  // namespace
}  // namespace fourbar
