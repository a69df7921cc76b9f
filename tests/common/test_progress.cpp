// The progress line (common/progress.hpp): share, elapsed time and the
// estimate of the time left; nothing drawn when stderr is not a terminal.
#include <gtest/gtest.h>

#include <unistd.h>

#include "common/progress.hpp"

namespace fourbar {
namespace {

TEST(Progress, LineWithElapsedTimeAndEstimate) {
  EXPECT_EQ(progress_line("sweep", 25, 100, 30.0),
            "sweep [#######                       ]  25%  0:30 elapsed, ~1:30 left");
  // Nothing done yet: no estimate; all done: none needed.
  EXPECT_EQ(progress_line("sim", 0, 10, 2.0), "sim [                              ]   0%  0:02 elapsed");
  EXPECT_EQ(progress_line("sim", 10, 10, 62.4), "sim [##############################] 100%  1:02 elapsed");
  // A total of 0 is one step; more done than the total is full.
  EXPECT_EQ(progress_line("x", 3, 0, 1.0), "x [##############################] 100%  0:01 elapsed");
}

TEST(Progress, ClockText) {
  EXPECT_EQ(clock_text(0), "0:00");
  EXPECT_EQ(clock_text(7.4), "0:07");
  EXPECT_EQ(clock_text(754), "12:34");
  EXPECT_EQ(clock_text(3723), "1:02:03");
  EXPECT_EQ(clock_text(-5), "0:00");
}

TEST(Progress, DrawsOnlyOnATerminal) {
  Progress p("x", 10);
  EXPECT_EQ(p.active(), ::isatty(2) != 0);
  Progress off("x", 10, false);
  EXPECT_FALSE(off.active());
  p.finish();
  EXPECT_FALSE(p.active());
}

}  // namespace
}  // namespace fourbar
