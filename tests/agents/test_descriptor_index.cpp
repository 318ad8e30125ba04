// The incremental index against distances worked out by hand.
#include <gtest/gtest.h>

#include <array>

#include "agents/algorithms/descriptor_index.h"

namespace dvpr {
namespace {

class IndexTest : public ::testing::Test {
 protected:
  // Three stored 2-D points, frames 0, 10 and 20.
  void SetUp() override {
    const std::array<float, 2> a{0.0f, 0.0f}, b{3.0f, 4.0f}, c{1.0f, 1.0f};
    index_.Add(RobotId(0), FrameId(0), a.data());
    index_.Add(RobotId(1), FrameId(10), b.data());
    index_.Add(RobotId(2), FrameId(20), c.data());
  }
  IncrementalIndex index_{2};
};

TEST_F(IndexTest, NearestOutsideWindow) {
  const std::array<float, 2> q{3.0f, 3.0f};  // to a: 18, to b: 1, to c: 8
  const auto r = index_.Search(q.data(), FrameId(100), 5);
  ASSERT_TRUE(r.best.has_value());
  EXPECT_EQ(r.best->frame, FrameId(10));
  EXPECT_EQ(r.best->robot, RobotId(1));
  EXPECT_FLOAT_EQ(r.best->distance, 1.0f);
  EXPECT_EQ(r.comparisons, 3);
}

TEST_F(IndexTest, SuppressionWindowIsInclusive) {
  const std::array<float, 2> q{3.0f, 3.0f};
  // |10 - 15| = 5 <= 5: b is suppressed, c (distance 8) wins; |20 - 15| = 5 suppressed too -> a (18).
  auto r = index_.Search(q.data(), FrameId(15), 5);
  ASSERT_TRUE(r.best.has_value());
  EXPECT_EQ(r.best->frame, FrameId(0));
  EXPECT_FLOAT_EQ(r.best->distance, 18.0f);
  // Window 4: |10 - 15| = 5 > 4, b is a candidate again.
  r = index_.Search(q.data(), FrameId(15), 4);
  EXPECT_EQ(r.best->frame, FrameId(10));
}

// A planned team's window (agents/algorithms/frame_window.h): a stream beginning at frame 12 cuts
// the window of a query at 15 there, so frame 10 (another robot's) is a candidate again while 20
// (the query's own stream, 5 away) is not.
TEST_F(IndexTest, AStreamCutsTheWindowAtItsStart) {
  const std::array<float, 2> q{3.0f, 3.0f};  // to a: 18, to b (frame 10): 1, to c (frame 20): 8
  auto r = index_.Search(q.data(), FrameId(15), FrameWindow(5, {FrameId(12)}));
  ASSERT_TRUE(r.best.has_value());
  EXPECT_EQ(r.best->frame, FrameId(10));
  EXPECT_EQ(r.comparisons, 3);
  EXPECT_EQ(index_.SearchFullScan(q.data(), FrameId(15), FrameWindow(5, {FrameId(12)})).best->frame, FrameId(10));
  // A stream from 11 to 19 (the next from 20): frame 20 is someone else's; 10 too. b wins.
  r = index_.Search(q.data(), FrameId(15), FrameWindow(5, {FrameId(11), FrameId(20)}));
  EXPECT_EQ(r.best->frame, FrameId(10));
  // A query at 8 in a stream [0, 20) with window 12: 0 and 10 suppressed; 20, 12 away, is the next
  // stream's -> c.
  r = index_.Search(q.data(), FrameId(8), FrameWindow(12, {FrameId(20)}));
  EXPECT_EQ(r.best->frame, FrameId(20));
  EXPECT_FLOAT_EQ(r.best->distance, 8.0f);
}

TEST_F(IndexTest, NothingOutsideWindowGivesNoMatchButCountsComparisons) {
  const std::array<float, 2> q{0.0f, 0.0f};
  const auto r = index_.Search(q.data(), FrameId(10), 10);
  EXPECT_FALSE(r.best.has_value());
  EXPECT_EQ(r.comparisons, 3);
}

// changes() counts the calls that change the store, a RemoveIf that removes nothing included;
// searching changes nothing.
TEST_F(IndexTest, ChangesCountsAddsAndRemovals) {
  EXPECT_EQ(index_.changes(), 3u);  // the three Adds of SetUp
  const std::array<float, 2> q{3.0f, 3.0f};
  (void)index_.Search(q.data(), FrameId(100), 5);
  EXPECT_EQ(index_.changes(), 3u);
  index_.RemoveIf([](std::size_t i) { return i == 1; });
  EXPECT_EQ(index_.changes(), 4u);
  index_.RemoveIf([](std::size_t) { return false; });
  EXPECT_EQ(index_.changes(), 5u);
  index_.Add(RobotId(3), FrameId(30), q.data());
  EXPECT_EQ(index_.changes(), 6u);
}

TEST(Index, TiesGoToTheEntryAddedFirst) {
  IncrementalIndex index(1);
  const float x = 2.0f, y = -2.0f, q = 0.0f;
  index.Add(RobotId(5), FrameId(40), &x);
  index.Add(RobotId(6), FrameId(30), &y);
  const auto r = index.Search(&q, FrameId(0), 0);
  EXPECT_EQ(r.best->frame, FrameId(40));
  EXPECT_FLOAT_EQ(r.best->distance, 4.0f);
}

TEST(Index, EmptyIndexAndBadDimension) {
  IncrementalIndex index(3);
  const std::array<float, 3> q{1, 2, 3};
  const auto r = index.Search(q.data(), FrameId(0), 0);
  EXPECT_FALSE(r.best.has_value());
  EXPECT_EQ(r.comparisons, 0);
  EXPECT_THROW(IncrementalIndex(0), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
