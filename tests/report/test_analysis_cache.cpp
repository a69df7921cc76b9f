// Property: a record written to the analysis cache reads back equal — the
// same numbers to the last bit (subnormal, huge, -0), the same text (control
// characters, quotes, non-ASCII, empty). Records JSON cannot hold exactly
// (NaN, infinity, text that is not UTF-8) are not cached at all.

#include "report/analysis_cache.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

using nlohmann::json;
using testing::TempDir;

class Generator {
 public:
  explicit Generator(unsigned seed) : gen_(seed) {}
  int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(gen_); }

  double number() {
    switch (below(5)) {
      case 0: {
        double v;
        do {
          const std::uint64_t bits = gen_();
          std::memcpy(&v, &bits, sizeof v);
        } while (!std::isfinite(v));
        return v;
      }
      case 1: return std::numeric_limits<double>::denorm_min() * below(1 << 20);
      case 2: {
        const double edges[] = {std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::min(), -0.0, 0.0, 1e-300, 0.1, 1.0 / 3};
        return edges[below(8)];
      }
      default: return std::ldexp(std::uniform_real_distribution<double>(-1, 1)(gen_), below(80) - 40);
    }
  }
  std::string text() {
    static const char* pieces[] = {"\xC3\xA9", "\xCF\x89", "\xE2\x80\x93", "\xF0\x9F\x94\xA7", "\"", "\\", "/", "\x7F"};
    std::string s;
    for (int n = below(4) == 0 ? 0 : below(30); n > 0; --n)
      s += below(3) ? std::string(1, static_cast<char>(below(0x80))) : std::string(pieces[below(8)]);
    return s;
  }
  json value(int depth) {
    switch (depth > 3 ? below(5) : below(7)) {
      case 0: return number();
      case 1: return text();
      case 2: return below(2) == 0;
      case 3: return below(2) ? json(static_cast<std::int64_t>(gen_())) : json(static_cast<std::uint64_t>(gen_()));
      case 4: return nullptr;
      case 5: {
        json a = json::array();
        for (int n = below(6); n > 0; --n) a.push_back(value(depth + 1));
        return a;
      }
      default: {
        json o = json::object();
        for (int n = below(6); n > 0; --n) o[text()] = value(depth + 1);
        return o;
      }
    }
  }
  json record() {
    json r = json::object();
    for (int n = 1 + below(8); n > 0; --n) r[text()] = value(0);
    r["status"] = below(2) ? "ok" : "check set-up";  // both are analysed records
    r["setup_check"] = value(0);
    r["views"] = value(0);
    r["model_family"] = value(0);
    return r;
  }

 private:
  std::mt19937_64 gen_;
};

TEST(AnalysisCache, GeneratedRecordsReadBackEqual) {
  TempDir dir;
  Generator g(20261124);
  for (int trial = 0; trial < 1000; ++trial) {
    const json record = g.record();
    const auto file = dir.path() / ("r" + std::to_string(trial) + ".json");
    ASSERT_TRUE(write_cached_record(file, record)) << record.dump();
    const auto back = read_cached_record(file);
    ASSERT_TRUE(back) << record.dump();
    ASSERT_EQ(*back, record) << record.dump();
    ASSERT_EQ(back->dump(), record.dump());  // -0.0 stays -0.0
  }
}

TEST(AnalysisCache, RecordsJsonCannotHoldAreNotCached) {
  TempDir dir;
  const auto file = dir.path() / "r.json";
  for (const double v : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    const json record = {{"status", "ok"}, {"series", {1.0, v}}};
    EXPECT_FALSE(write_cached_record(file, record));
    EXPECT_FALSE(std::filesystem::exists(file));
  }
  // A warning naming a file whose name is Latin-1, not UTF-8.
  const json latin1 = {{"status", "ok"}, {"warnings", {std::string("Messung_\xE4.wav: 3 revolutions clipped")}}};
  EXPECT_FALSE(write_cached_record(file, latin1));
  EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(AnalysisCache, DamagedOrFailedEntriesAreRecomputed) {
  TempDir dir;
  EXPECT_FALSE(read_cached_record(dir.path() / "none.json"));
  EXPECT_FALSE(read_cached_record(dir.write("cut.json", R"({"status": "ok", "series": [1, 2)")));
  EXPECT_FALSE(read_cached_record(dir.write("array.json", "[1, 2]")));
  EXPECT_FALSE(read_cached_record(dir.write("failed.json", R"({"status": "failed"})")));
  // Made before the set-up check existed: recomputed, so the report shows the check.
  EXPECT_FALSE(read_cached_record(dir.write("old.json", R"({"status": "ok"})")));
  // Made before the views existed: recomputed, so the report shows them.
  EXPECT_FALSE(read_cached_record(dir.write("no_views.json", R"({"status": "ok", "setup_check": {"findings": []}})")));
  // Made before the model-family check existed: recomputed, so the verdict has its part.
  EXPECT_FALSE(read_cached_record(dir.write("no_family.json", R"({"status": "ok", "setup_check": {"findings": []}, "views": {}})")));
  EXPECT_TRUE(read_cached_record(
      dir.write("ok.json", R"({"status": "ok", "setup_check": {"findings": []}, "views": {}, "model_family": {}})")));
  EXPECT_TRUE(read_cached_record(dir.write(
      "check.json",
      R"({"status": "check set-up", "setup_check": {"findings": [{"key": "axis_sign"}]}, "views": {}, "model_family": {}})")));
  // Made before the spectral magnification named its orders: recomputed, so the verdict has them.
  EXPECT_FALSE(read_cached_record(dir.write(
      "no_orders.json", R"({"status": "ok", "setup_check": {}, "views": {}, "model_family": {}, "metrics": {"alpha3_rad_s2": {"magnification": {"spectral": 0.2}}}})")));
  EXPECT_TRUE(read_cached_record(dir.write(
      "orders.json", R"({"status": "ok", "setup_check": {}, "views": {}, "model_family": {}, "metrics": {"alpha3_rad_s2": {"magnification": {"orders_used": [6]}}}})")));
}

}  // namespace
}  // namespace fourbar
