#include "experiments/domain/data/split.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace dvpr {
namespace {

FrameRange Range(int begin, int end) { return {FrameId(begin), FrameId(end)}; }

TEST(SplitTest, TenFramesThreeRobotsWorkedByHand) {
  // floor(0*10/3)=0, floor(10/3)=3, floor(20/3)=6, floor(30/3)=10.
  const SequenceSplit s = SplitSequence(10, 3);
  ASSERT_EQ(s.robots(), 3);
  EXPECT_EQ(s.ranges[0], Range(0, 3));
  EXPECT_EQ(s.ranges[1], Range(3, 6));
  EXPECT_EQ(s.ranges[2], Range(6, 10));
  const int expected_owner[10] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 2};
  ASSERT_EQ(s.frames(), 10);
  for (int f = 0; f < 10; ++f) EXPECT_EQ(s.OwnerOf(FrameId(f)), RobotId(expected_owner[f])) << f;
}

TEST(SplitTest, Kitti00TwentyRobots) {
  // 4541 / 20 = 227.05: robot 0 gets [0, 227), robot 19 gets [floor(19*4541/20), 4541) = [4313, 4541).
  const SequenceSplit s = SplitSequence(4541, 20);
  EXPECT_EQ(s.ranges[0], Range(0, 227));
  EXPECT_EQ(s.ranges[1], Range(227, 454));
  EXPECT_EQ(s.ranges[19], Range(4313, 4541));
  int total = 0;
  for (std::size_t r = 0; r < 20; ++r) {
    total += s.ranges[r].size();
    EXPECT_GE(s.ranges[r].size(), 227);
    EXPECT_LE(s.ranges[r].size(), 228);
    if (r > 0) {
      EXPECT_EQ(s.ranges[r].begin, s.ranges[r - 1].end);
    }
  }
  EXPECT_EQ(total, 4541);
  EXPECT_TRUE(s.ranges[1].Contains(FrameId(227)));
  EXPECT_FALSE(s.ranges[1].Contains(FrameId(454)));
}

TEST(SplitTest, OneRobotTakesAllAndEveryRobotAtLeastOneFrame) {
  EXPECT_EQ(SplitSequence(5, 1).ranges.at(0), Range(0, 5));
  const SequenceSplit s = SplitSequence(3, 3);
  EXPECT_EQ(s.ranges[2], Range(2, 3));
}

TEST(SplitTest, RejectsImpossibleSplits) {
  EXPECT_THROW(SplitSequence(10, 0), std::invalid_argument);
  EXPECT_THROW(SplitSequence(2, 3), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
