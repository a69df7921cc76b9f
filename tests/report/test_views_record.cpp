// The recording views of the report (report/views_record.hpp) on a
// virtual-rig recording, each checked against a separate computation: the
// crank-speed points against acquire's revolutions, the excerpt's pulse
// markers against acquire's pulse times and the signal's own edges, the
// channel sheet against the manifest and acquire's statistics, and the
// deviation map against the analysis's per-revolution grids (kept by the
// analysis itself, not through the report's observer).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "acquire/acquisition.hpp"
#include "report/deviation_map.hpp"
#include "report/packed_numbers.hpp"
#include "report/recording_job.hpp"
#include "report/views_record.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"
#include "support/virtual_rig_scene.hpp"

namespace fourbar {
namespace {

using nlohmann::json;

class RecordingViews : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir;
    dir_->write("rig.toml", testing::thesis_rig_toml());
    dir_->write("scene.toml", R"(rig = "rig.toml"
model = "clearance"
crank_speed_rpm = 330
outputs = ["alpha3_rad_s2"]
[clearance]
radial_mm = 0.254
restitution = 0.5
tolerance = 1e-8
[recording]
sample_rate_hz = 8000
duration_s = 3.0
sample_format = "pcm24"
noise_snr_db = 50.0
seed = 11
[recording.pulse]
angle_deg = 20.0
)" + testing::tangential_sensors_toml(300.0, 300.0));
    rec_ = new std::filesystem::path(dir_->path() / "rec.flac");
    const auto r = testing::record_virtual(dir_->path() / "scene.toml", *rec_);
    ASSERT_EQ(r.status, 0) << r.err;
    AnalyzeOptions o;
    o.progress = false;
    TheorySettings t;
    t.warmup_revolutions = 5, t.averaged_revolutions = 5;
    record_ = new json(process_recording(*rec_, o, t));
    ASSERT_TRUE(record_->contains("views")) << record_->dump().substr(0, 2000);
    AcquireOptions ao;
    ao.progress = false;
    acquired_ = new Acquisition(acquire_revolutions(*rec_, {}, ao));
    o.keep_revolutions = true;
    o.setup_check = false;
    analysis_ = new RecordingAnalysis(analyze_recording(*rec_, {}, o));
  }
  static void TearDownTestSuite() {
    delete analysis_;
    delete acquired_;
    delete record_;
    delete rec_;
    delete dir_;
  }
  static const json& views() { return (*record_)["views"]; }
  static testing::TempDir* dir_;
  static std::filesystem::path* rec_;
  static json* record_;
  static Acquisition* acquired_;
  static RecordingAnalysis* analysis_;
};
testing::TempDir* RecordingViews::dir_ = nullptr;
std::filesystem::path* RecordingViews::rec_ = nullptr;
json* RecordingViews::record_ = nullptr;
Acquisition* RecordingViews::acquired_ = nullptr;
RecordingAnalysis* RecordingViews::analysis_ = nullptr;

TEST_F(RecordingViews, SpeedPointsAreAcquiresRevolutions) {
  const json& s = views()["speed"];
  const auto& revs = acquired_->revolutions;
  ASSERT_EQ(s["revolutions_per_point"], 1);
  ASSERT_EQ(s["rpm"].size(), revs.size());
  ASSERT_GE(revs.size(), 10u);
  double sum = 0;
  for (std::size_t i = 0; i < revs.size(); ++i) {
    EXPECT_DOUBLE_EQ(s["time_s"][i].get<double>(), revs[i].start_time_s);
    EXPECT_NEAR(s["rpm"][i].get<double>(), revs[i].speed_rpm(), 1e-9 * revs[i].speed_rpm());
    sum += s["rpm"][i].get<double>();
  }
  const SpeedStats& speed = acquired_->report.speed;
  EXPECT_NEAR(sum / static_cast<double>(revs.size()), speed.mean_rpm, 1e-9 * speed.mean_rpm);
  EXPECT_NEAR(s["mean_rpm"].get<double>(), speed.mean_rpm, 1e-9 * speed.mean_rpm);
  // The virtual rig turned the crank at 330 rpm with no wander.
  EXPECT_NEAR(speed.mean_rpm, 330.0, 0.5);
}

TEST_F(RecordingViews, ExcerptMarksAcquiresPulsesWhereTheSignalHasItsEdges) {
  const json& x = views()["excerpt"];
  ASSERT_TRUE(x.is_object());
  const double from = x["start_s"], to = x["end_s"];
  std::set<double> pulses;  // every pulse of acquire's revolutions inside the window
  for (const Revolution& r : acquired_->revolutions)
    for (double t : {r.start_time_s, r.start_time_s + r.period_s})
      if (t >= from && t <= to) pulses.insert(t);
  ASSERT_EQ(pulses.size(), kExcerptRevolutions + 1);
  ASSERT_EQ(x["pulse_s"].size(), pulses.size());
  std::size_t i = 0;
  for (double t : pulses) EXPECT_NEAR(x["pulse_s"][i++].get<double>(), t, 1e-9);
  // In the middle of the recording.
  const double duration = acquired_->report.recording.duration_s();
  EXPECT_GT(from, 0.2 * duration);
  EXPECT_LT(to, 0.8 * duration);
  // The crank trace crosses both thresholds (rising) within two buckets of every marker.
  const json* pulse = nullptr;
  for (const json& tr : x["traces"])
    if (tr["role"] == "crank_pulse") pulse = &tr;
  ASSERT_NE(pulse, nullptr);
  const double low = x["thresholds"]["low_V"], high = x["thresholds"]["high_V"];
  // The packed values: counts of a step, on a uniform time grid.
  const auto values = [](const json& tr) {
    std::vector<double> v;
    for (std::int32_t c : unpack_base64(tr["values_int16_base64"], 2)) v.push_back(c * tr["unit_per_count"].get<double>());
    return v;
  };
  std::vector<double> t;
  for (std::size_t k = 0; k < x["points"].get<std::size_t>(); ++k)
    t.push_back(x["time_first_s"].get<double>() + static_cast<double>(k) * x["time_step_s"].get<double>());
  EXPECT_NEAR(t.front(), from, 1e-12);
  EXPECT_NEAR(t.back(), to, 1.0 / acquired_->report.recording.sample_rate_hz * x["bucket_frames"].get<double>());
  const std::vector<double> crank = values(*pulse);
  EXPECT_DOUBLE_EQ(low, acquired_->report.thresholds.low);
  const double fs = acquired_->report.recording.sample_rate_hz;
  const double delta = 2.0 * x["bucket_frames"].get<double>() / fs + 2.0 / fs;
  ASSERT_EQ(t.size(), crank.size());
  for (double p : pulses) {
    bool below = false, above = false;
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double tk = t[k], v = crank[k];
      if (tk >= p - delta && tk <= p && v < low) below = true;
      if (tk >= p && tk <= p + delta && v > high) above = true;
    }
    EXPECT_TRUE(below && above) << "no rising edge at the pulse marker " << p << " s";
  }
  // Every accelerometer, every point, within the channel's recorded range.
  for (std::size_t c = 0; c < acquired_->report.channels.size(); ++c) {
    const json* tr = nullptr;
    for (const json& j : x["traces"])
      if (j["name"] == acquired_->report.channels[c].name) tr = &j;
    ASSERT_NE(tr, nullptr);
    EXPECT_EQ((*tr)["unit"], "m/s²");
    const ChannelStats& st = acquired_->report.channel_stats[c];
    const double half_step = 0.5 * (*tr)["unit_per_count"].get<double>() * (1 + 1e-9);
    const std::vector<double> v = values(*tr);
    ASSERT_EQ(v.size(), t.size());
    double lo = v[0], hi = v[0];
    for (double e : v) lo = std::min(lo, e), hi = std::max(hi, e);
    EXPECT_GE(lo, st.min - half_step);
    EXPECT_LE(hi, st.max + half_step);
    EXPECT_GT(hi - lo, 0.1 * (st.max - st.min));  // a real excerpt of the signal, not a flat line
  }
}

TEST_F(RecordingViews, ChannelSheetIsTheManifestAndAcquiresStatistics) {
  const json& sheet = views()["channels"];
  const Manifest& m = acquired_->manifest;
  ASSERT_EQ(sheet["channels"].size(), m.channels.size());
  for (std::size_t i = 0; i < m.channels.size(); ++i) {
    const ChannelSpec& c = m.channels[i];
    const json& row = sheet["channels"][i];
    EXPECT_EQ(row["name"], c.name);
    EXPECT_EQ(row["role"], to_string(c.role));
    if (is_accelerometer(c.role)) {
      EXPECT_DOUBLE_EQ(row["volts_per_m_s2"].get<double>(), c.volts_per_m_s2);
      EXPECT_DOUBLE_EQ(row["axis_sign"].get<double>(), c.axis_sign);
      EXPECT_NEAR(row["position_mm"].get<double>(), 1e3 * c.position_m, 1e-9);
      const auto& chans = acquired_->report.channels;
      const auto at = std::find_if(chans.begin(), chans.end(), [&](const AcquiredChannel& a) { return a.name == c.name; });
      ASSERT_NE(at, chans.end());
      const ChannelStats& st = acquired_->report.channel_stats[static_cast<std::size_t>(at - chans.begin())];
      EXPECT_DOUBLE_EQ(row["recorded"]["max"].get<double>(), st.max);
      EXPECT_DOUBLE_EQ(row["recorded"]["rms"].get<double>(), st.rms);
      EXPECT_EQ(row["recorded"]["clipped_samples"], st.clipped_samples);
      // pcm24: the input range is the converter's full scale.
      ASSERT_TRUE(row.contains("input_range"));
      EXPECT_NEAR(row["input_range"]["min"].get<double>(), -m.full_scale_V / c.volts_per_m_s2, 1e-9);
      EXPECT_EQ(row["setup_check"]["status"], "consistent") << row.dump();
      EXPECT_GT(row["setup_check"]["fit"].get<double>(), 0.5);
    }
    if (c.role == ChannelRole::crank_pulse) {
      EXPECT_DOUBLE_EQ(row["thresholds"]["high_V"].get<double>(), acquired_->report.thresholds.high);
      EXPECT_NEAR(row["crank_offset_deg"].get<double>(), 20.0, 1e-9);
    }
  }
}

TEST_F(RecordingViews, MapRowsAreTheRevolutionsDeviationFromNominal) {
  const json& map = views()["map"];
  ASSERT_TRUE(map.is_object());
  const LinkResult& coupler = *analysis_->coupler;
  const std::size_t n = analysis_->grid_points_per_rev, cols = map["columns"], m = n / cols;
  ASSERT_EQ(cols * m, n);
  EXPECT_LE(cols, kMapMaxColumns);
  const std::vector<double> nominal = (*record_)["series"]["alpha3_rad_s2"]["nominal"];
  ASSERT_EQ(nominal.size(), n);
  const std::vector<int> counts = decode_map_counts(map["deviation_int8_base64"]);
  const std::size_t rows = map["rows"];
  ASSERT_EQ(counts.size(), rows * cols);
  // Every averaged revolution (fewer than 200), in order.
  EXPECT_EQ(rows, analysis_->revolutions);
  const double step = map["rad_s2_per_count"];
  ASSERT_GT(step, 0);
  double largest = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    const std::size_t number = map["revolution"][r];
    const auto it = std::find(analysis_->revolution_numbers.begin(), analysis_->revolution_numbers.end(), number);
    ASSERT_NE(it, analysis_->revolution_numbers.end());
    const std::size_t row = static_cast<std::size_t>(it - analysis_->revolution_numbers.begin());
    double row_mean = 0, map_mean = 0;
    for (std::size_t c = 0; c < cols; ++c) {
      double cell = 0;
      for (std::size_t k = c * m; k < (c + 1) * m; ++k) cell += coupler.alpha_grid[row * n + k] - nominal[k];
      cell /= static_cast<double>(m);
      // Quantised to a count: half a count at most.
      EXPECT_LE(std::abs(counts[r * cols + c] * step - cell), 0.5 * step * (1 + 1e-9));
      largest = std::max(largest, std::abs(cell));
      row_mean += cell, map_mean += counts[r * cols + c] * step;
    }
    EXPECT_NEAR(map_mean / static_cast<double>(cols), row_mean / static_cast<double>(cols), 0.5 * step);
  }
  EXPECT_NEAR(map["largest_abs_rad_s2"].get<double>(), largest, 1e-9 * largest);
  // Rows start at the pulse: θ2 = 20° (the scene's pulse angle).
  EXPECT_NEAR(map["first_crank_deg"].get<double>(), 20.0, 1e-9);
  EXPECT_NEAR(map["crank_deg"][0].get<double>(), 20.0 + 360.0 * 0.5 * static_cast<double>(m - 1) / static_cast<double>(n), 1e-9);
  // Impacts: the deviation is not zero.
  EXPECT_GT(largest, 10.0);
}

TEST(DeviationMap, SubsamplesRowsAndColumnsByTheStatedRule) {
  RecordingAnalysis a;
  a.grid_points_per_rev = 700;  // largest divisor ≤ 180: 175 (4 points each)
  a.acquisition.revolutions = 450;  // every 3rd revolution: 150 rows
  a.coupler = LinkResult{};
  DeviationMapCollector c;
  c.on_start(a);
  std::vector<double> alpha(700);
  for (std::size_t r = 0; r < 450; ++r) {
    for (std::size_t k = 0; k < alpha.size(); ++k) alpha[k] = static_cast<double>(r) + (k % 4 == 0 ? 4.0 : 0.0);
    AnalyzedRevolution rev;
    rev.number = r;
    rev.averaged = r != 30;  // a clipped one: left out
    rev.alpha3_rad_s2 = alpha;
    c.on_revolution(rev);
  }
  const json m = c.map_json(std::vector<double>(700, 1.0), 0.0, 1.0);
  EXPECT_EQ(m["columns"], 175);
  EXPECT_EQ(m["grid_points_per_column"], 4);
  EXPECT_EQ(m["every_kth_revolution"], 3);
  EXPECT_EQ(m["rows"], 149);
  EXPECT_EQ(m["revolution"][10], 33);  // 0, 3, …, 27, then 33 (30 was not averaged)
  const std::vector<int> counts = decode_map_counts(m["deviation_int8_base64"]);
  ASSERT_EQ(counts.size(), 149u * 175u);
  // Cell = r + 1 − 1 = r (each column's mean: r + 4/4 − nominal 1); the largest, 447, is 127 counts.
  EXPECT_EQ(counts[148 * 175 + 7], 127);
  EXPECT_EQ(counts[10 * 175], static_cast<int>(std::lround(127.0 * 33 / 447)));
  EXPECT_NEAR(m["crank_deg"][0].get<double>(), 360.0 * 1.5 / 700, 1e-12);
}

}  // namespace
}  // namespace fourbar
