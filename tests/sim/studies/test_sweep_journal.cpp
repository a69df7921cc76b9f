// What a sweep writes to read again: a point's encoded result (what travels
// between MPI ranks and what the journal keeps) decodes to the same bits for
// every double, subnormal, extreme and signed zero included, and every error
// text; the journal keeps complete lines only and forgets other inputs'.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>

#include "sim/studies/sweep.hpp"
#include "sim/studies/sweep_journal.hpp"
#include "support/temp_dir.hpp"

namespace fourbar {
namespace {

double random_double(std::mt19937_64& gen) {
  static const double special[] = {0.0,
                                   -0.0,
                                   std::numeric_limits<double>::denorm_min(),
                                   -std::numeric_limits<double>::denorm_min(),
                                   std::numeric_limits<double>::min(),
                                   std::numeric_limits<double>::max(),
                                   -std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::epsilon(),
                                   0.1,
                                   1.0 / 3.0};
  if (gen() % 4 == 0) return special[gen() % std::size(special)];
  for (;;) {  // any finite bit pattern
    const double v = std::bit_cast<double>(gen());
    if (std::isfinite(v)) return v;
  }
}

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

TEST(SweepResult, EncodedStatisticsDecodeToTheSameBits) {
  std::mt19937_64 gen(20261124);
  for (int trial = 0; trial < 2000; ++trial) {
    SweepPoint p;
    p.impacts_per_rev = random_double(gen);
    p.sum_normal_impulse_per_rev_Ns = random_double(gen);
    p.impact_index_Ns = random_double(gen);
    p.contact_losses_per_rev = random_double(gen);
    p.following_share = random_double(gen);
    p.energy_residual_rel = random_double(gen);
    p.max_penetration_rel = random_double(gen);
    const std::string line = encode_sweep_result(p);
    ASSERT_EQ(line.find('\n'), std::string::npos);
    SweepPoint q;
    ASSERT_TRUE(decode_sweep_result(line, q)) << line;
    EXPECT_FALSE(q.failed());
    for (auto m : {&SweepPoint::impacts_per_rev, &SweepPoint::sum_normal_impulse_per_rev_Ns,
                   &SweepPoint::impact_index_Ns, &SweepPoint::contact_losses_per_rev, &SweepPoint::following_share,
                   &SweepPoint::energy_residual_rel, &SweepPoint::max_penetration_rel})
      ASSERT_EQ(bits(q.*m), bits(p.*m)) << line;
  }
}

TEST(SweepResult, ErrorsDecodeToTheirTextOnOneLine) {
  std::mt19937_64 gen(5);
  for (int trial = 0; trial < 500; ++trial) {
    SweepPoint p;
    const int len = 1 + static_cast<int>(gen() % 60);
    for (int i = 0; i < len; ++i) p.error += static_cast<char>(1 + gen() % 255);  // controls, UTF-8 bytes, all
    const std::string line = encode_sweep_result(p);
    ASSERT_EQ(line.find('\n'), std::string::npos);
    SweepPoint q;
    ASSERT_TRUE(decode_sweep_result(line, q));
    ASSERT_TRUE(q.failed());
    std::string expected = p.error;  // line breaks become spaces: one journal line per point
    for (char& c : expected)
      if (c == '\n' || c == '\r') c = ' ';
    EXPECT_EQ(q.error, expected);
  }
}

TEST(SweepResult, DamagedLinesAreRefused) {
  SweepPoint q;
  for (const char* bad : {"", "ok", "ok 0x1p+0", "ok 0x1p+0 0x1p+0 0x1p+0 0x1p+0 0x1p+0 0x1p+0",
                          "ok 0x1p+0 0x1p+0 0x1p+0 0x1p+0 0x1p+0 0x1p+0 0x1p+0 junk", "ok inf 0 0 0 0 0 0", "failed ",
                          "fail x", "OK 0 0 0 0 0 0 0 0 0",
                          "ok 0 0 0 0 0 0 0"})  // a line of the seven fields before the standard errors: run again
    EXPECT_FALSE(decode_sweep_result(bad, q)) << "'" << bad << "'";
  EXPECT_TRUE(decode_sweep_result("ok 0 0 0 0 0 0 0 0 0", q));
  EXPECT_FALSE(decode_sweep_result("ok 0 0 0 0 0 0 0 0 0 0", q));
}

TEST(SweepJournal, KeepsCompleteLinesOfTheSameInputsOnly) {
  testing::TempDir dir;
  const auto path = dir.path() / "t.csv.journal";
  {
    SweepJournal j(path, "aaaa", 5);
    EXPECT_TRUE(j.finished().empty());
    EXPECT_FALSE(j.discarded_stale());
    j.append(3, "ok three");
    j.append(0, "failed zero");
  }
  { std::ofstream(path, std::ios::app) << "4\tok cut sho"; }  // a kill in the middle of a write
  {
    SweepJournal j(path, "aaaa", 5);
    ASSERT_EQ(j.finished().size(), 2u);
    EXPECT_EQ(j.finished().at(3), "ok three");
    EXPECT_EQ(j.finished().at(0), "failed zero");
    j.append(4, "ok four");
  }
  {
    SweepJournal j(path, "aaaa", 5);
    EXPECT_EQ(j.finished().size(), 3u) << "the torn line was dropped, the later append kept";
    EXPECT_EQ(j.finished().at(4), "ok four");
  }
  {
    SweepJournal j(path, "bbbb", 5);  // other inputs
    EXPECT_TRUE(j.discarded_stale());
    EXPECT_TRUE(j.finished().empty());
  }
  {
    SweepJournal j(path, "bbbb", 6);  // same fingerprint, another grid size
    EXPECT_TRUE(j.discarded_stale());
    j.remove();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_NE(fingerprint_of("a"), fingerprint_of("b"));
  EXPECT_EQ(fingerprint_of("sweep"), fingerprint_of("sweep"));
}

}  // namespace
}  // namespace fourbar
