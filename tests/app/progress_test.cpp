// The words of the progress lines: durations a reader takes in at a glance, counts grouped by
// thousands, the estimate after the first measured frame and the line that says what runs.
#include <gtest/gtest.h>

#include "app/headless.h"
#include "base/progress.h"

using namespace tidepool;

TEST(ProgressText, DurationsReadAtAGlance) {
  EXPECT_EQ(durationText(0.42), "0.4 s");
  EXPECT_EQ(durationText(9.96), "10 s");
  EXPECT_EQ(durationText(59.4), "59 s");
  EXPECT_EQ(durationText(285), "4 min 45 s");
  EXPECT_EQ(durationText(35530), "9 h 52 min");
  EXPECT_EQ(durationText(-1), "0.0 s");
}

TEST(ProgressText, CountsAreGroupedByThousands) {
  EXPECT_EQ(groupedCount(0), "0");
  EXPECT_EQ(groupedCount(999), "999");
  EXPECT_EQ(groupedCount(4776), "4,776");
  EXPECT_EQ(groupedCount(262144), "262,144");
  EXPECT_EQ(groupedCount(100000000), "100,000,000");
}

TEST(ProgressText, TheEstimateGoesOnAtTheFirstFramesPace) {
  // Frame 0 (0.5 s with the set-up) and frame 1 (1.9 s) done: 148 more frames at 1.9 s.
  EXPECT_EQ(estimateText(1.9, 2.4, 2, 150, "frames"), "first frame 1.9 s, about 4 min 44 s for 150 frames");
  EXPECT_EQ(estimateText(0.1, 0.1, 1, 1, "frames"), "first frame 0.1 s, about 0.1 s for 1 frame");
}

TEST(ProgressText, TheRunSaysItsCountInTheModelsUnit) {
  StageIndicators balls;
  balls.particles = 262144;
  EXPECT_EQ(runText("cup", balls, 150, 1280, 720), "cup: 262,144 particles, 150 frames at 1280x720");
  StageIndicators grid;
  grid.particles = 65536;
  grid.countsCells = true;
  EXPECT_EQ(runText("ripples", grid, 1, 64, 64), "ripples: 65,536 cells, 1 frame at 64x64");
  EXPECT_EQ(runText("blank", StageIndicators{}, 3, 16, 16), "blank: 3 frames at 16x16");
}
