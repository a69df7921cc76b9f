// report/family_across_speeds: a model-family finding no recording at another
// crank speed shows at the same Hz is set aside (it moves with the speed: the
// clearance's own rhythm, not a structure).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/family_across_speeds.hpp"
#include "report/verdict.hpp"
#include "report/verdict_family.hpp"

namespace fourbar {
namespace {

using nlohmann::json;

/// 20 Hz bands from 100 Hz to `top_hz`, each standing `rtn` above its
/// neighbours except those in `[hot_lo, hot_hi)`, which stand `hot_rtn`.
json bands(double top_hz, double hot_lo = 0, double hot_hi = 0, double hot_rtn = 0, double rtn = 1.5) {
  json b = json::array();
  for (double lo = 100; lo + 20 <= top_hz + 1e-9; lo += 20) {
    const bool hot = lo >= hot_lo && lo < hot_hi;
    b.push_back({{"low_hz", lo}, {"high_hz", lo + 20}, {"measured_ms", 1.0}, {"model_ms", 1.0},
                 {"ratio_to_neighbours", hot ? hot_rtn : rtn}, {"prominence", 1.0}, {"unmodelled", hot && hot_rtn >= kExcessRatio}});
  }
  return b;
}

json finding(double lo, double hi, double judged_below_hz, double a) {
  return {{"kind", "narrow resonance"}, {"low_hz", lo}, {"high_hz", hi}, {"peak_hz", (lo + hi) / 2}, {"rms_share", 0.2},
          {"excess_ratio", 20.0}, {"judged_below_hz", judged_below_hz}, {"measured_scatter_below", 2.0},
          {"model_scatter_below", 2.0 * a}, {"a_scatter_below", a}};
}

json record(const std::string& name, double rpm, json found, json b, double top_hz = 940) {
  json mf = {{"checked", true}, {"crank_hz", rpm / 60}, {"checked_up_to_hz", top_hz}, {"bands", std::move(b)}, {"unmodelled", found}};
  if (!found.empty()) {
    const json& u = found.front();
    mf["judged_below_hz"] = u["judged_below_hz"];
    mf["a_scatter_below"] = u["a_scatter_below"];
    mf["measured_scatter_below"] = u["measured_scatter_below"];
    mf["model_scatter_below"] = u["model_scatter_below"];
  }
  return {{"name", name}, {"model_family", mf}};
}

TEST(FamilyAcrossSpeeds, LinkVibrationPlacedByTheRigsModesStays) {
  // The same lone finding, but placed by the elastic-link reference: the
  // rig's modal data, not this record's spectrum, says where it lies.
  json u = finding(560, 940, 420, 3.6);
  u["kind"] = "link vibration";
  std::vector<json> r = {record("a_350.flac", 350, json::array({u}), bands(940)),
                         record("b_250.flac", 250, json::array(), bands(940))};
  EXPECT_EQ(set_aside_findings_that_move_with_speed(r), 0u);
  ASSERT_EQ(r[0]["model_family"]["unmodelled"].size(), 1u);
  EXPECT_FALSE(r[0]["model_family"].contains("moves_with_speed"));
}

TEST(FamilyAcrossSpeeds, AFindingTheOtherSpeedLacksIsSetAside) {
  // 350 rpm: energy at 140-180 Hz; 250 rpm: nothing there (1.7x, as the
  // hold-out's false alarm's partners).
  std::vector<json> r = {record("a_350.flac", 350, json::array({finding(140, 180, 105, 3.6)}), bands(940, 140, 180, 133)),
                         record("b_250.flac", 250, json::array(), bands(940, 140, 180, 1.7))};
  EXPECT_EQ(set_aside_findings_that_move_with_speed(r), 1u);
  const json& mf = r[0]["model_family"];
  EXPECT_TRUE(mf["unmodelled"].empty());
  ASSERT_EQ(mf["moves_with_speed"].size(), 1u);
  EXPECT_TRUE(mf["judged_below_hz"].is_null());
  EXPECT_TRUE(mf["a_scatter_below"].is_null());
  for (const json& b : mf["bands"]) EXPECT_FALSE(b["unmodelled"].get<bool>()) << b.dump();
  const std::string text = mf["moves_with_speed_text"];
  EXPECT_NE(text.find("b_250.flac (250 rpm)"), std::string::npos) << text;
  EXPECT_NE(text.find("moves with the crank speed"), std::string::npos) << text;
  // The verdict's part then holds and says what was set aside.
  const auto f = verdict_family(r[0]);
  ASSERT_TRUE(f);
  EXPECT_TRUE(f->unmodelled.empty());
  EXPECT_EQ(f->moves_with_speed.size(), 1u);
  VerdictInputs in;
  in.family = f;
  const VerdictPart p = family_part(in);
  EXPECT_EQ(p.level, VerdictLevel::good);
  EXPECT_NE(p.sentence.find("set aside"), std::string::npos) << p.sentence;
  // The 250 rpm record had nothing to set aside.
  EXPECT_FALSE(r[1]["model_family"].contains("moves_with_speed"));
}

TEST(FamilyAcrossSpeeds, AFindingAtTheSameHzAtAnotherSpeedStays) {
  std::vector<json> r = {record("a_350.flac", 350, json::array({finding(560, 640, 420, 1.0)}), bands(940, 560, 640, 28)),
                         record("b_250.flac", 250, json::array({finding(560, 640, 420, 1.0)}), bands(940, 580, 620, 9.7))};
  EXPECT_EQ(set_aside_findings_that_move_with_speed(r), 0u);
  EXPECT_EQ(r[0]["model_family"]["unmodelled"].size(), 1u);
  EXPECT_EQ(r[1]["model_family"]["unmodelled"].size(), 1u);
  EXPECT_DOUBLE_EQ(r[0]["model_family"]["judged_below_hz"].get<double>(), 420);
}

TEST(FamilyAcrossSpeeds, TheNextFindingDecidesWhenTheFirstIsSetAside) {
  // The independent generator's 350 rpm recording: 137-177 Hz (moves) and
  // 557-617 Hz (a coupler mode, at 250 rpm too).
  std::vector<json> r = {record("a_350.flac", 350, json::array({finding(140, 180, 105, 0.4), finding(560, 620, 420, 1.3)}),
                                json(bands(940, 560, 620, 14.5))),
                         record("b_250.flac", 250, json::array({finding(560, 640, 420, 1.0)}), bands(940, 560, 640, 15.4))};
  EXPECT_EQ(set_aside_findings_that_move_with_speed(r), 1u);
  const json& mf = r[0]["model_family"];
  ASSERT_EQ(mf["unmodelled"].size(), 1u);
  EXPECT_DOUBLE_EQ(mf["unmodelled"][0]["low_hz"].get<double>(), 560);
  EXPECT_DOUBLE_EQ(mf["judged_below_hz"].get<double>(), 420);
  EXPECT_DOUBLE_EQ(mf["a_scatter_below"].get<double>(), 1.3);
}

TEST(FamilyAcrossSpeeds, OneSpeedOrNoRecordingCoveringTheBandKeepsEveryFinding) {
  // Same speed (within 10 %): nothing can confirm or set aside.
  std::vector<json> same = {record("a.flac", 350, json::array({finding(140, 180, 105, 3.6)}), bands(940, 140, 180, 133)),
                            record("b.flac", 340, json::array(), bands(940))};
  EXPECT_EQ(set_aside_findings_that_move_with_speed(same), 0u);
  EXPECT_EQ(same[0]["model_family"]["unmodelled"].size(), 1u);
  // Another speed whose check stops below the band (a lower sample rate).
  std::vector<json> low = {record("a.flac", 350, json::array({finding(760, 800, 570, 1.0)}), bands(940, 760, 800, 30)),
                           record("b.flac", 250, json::array(), bands(700), 700)};
  EXPECT_EQ(set_aside_findings_that_move_with_speed(low), 0u);
  EXPECT_EQ(low[0]["model_family"]["unmodelled"].size(), 1u);
  // A record without a check (failed recording) is no partner.
  std::vector<json> failed = {record("a.flac", 350, json::array({finding(140, 180, 105, 3.6)}), bands(940, 140, 180, 133)),
                              json{{"name", "b.flac"}, {"error", "could not read"}}};
  EXPECT_EQ(set_aside_findings_that_move_with_speed(failed), 0u);
}

}  // namespace
}  // namespace fourbar
