// Adaptive re-clustering's shared rules (agents/recluster/recluster.h) and the index removal it moves
// descriptors with, on 1-D cases whose clusters and owners can be read off by hand.
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "agents/algorithms/descriptor_index.h"
#include "agents/recluster/recluster.h"
#include "tests/descriptor_support.h"

namespace dvpr {
namespace {

using dvpr::testing_support::Column;
using dvpr::testing_support::Robots;

TEST(Recluster, SampleTakesTheStrideOfTheStepsBeforeTheBoundary) {
  ReclusterParams p;
  p.period = 5;
  p.sample_stride = 4;
  // Epoch 1 (steps 0..4 taken): steps 0 and 4; epoch 2 (steps 0..9): 0, 4, 8.
  EXPECT_TRUE(InReclusterSample(0, 1, p));
  EXPECT_TRUE(InReclusterSample(4, 1, p));
  EXPECT_FALSE(InReclusterSample(1, 1, p));
  EXPECT_FALSE(InReclusterSample(8, 1, p));  // taken after the boundary
  EXPECT_TRUE(InReclusterSample(8, 2, p));
  EXPECT_FALSE(InReclusterSample(12, 2, p));
  EXPECT_EQ(ReclusterEpochOf(4, p), 0);
  EXPECT_EQ(ReclusterEpochOf(5, p), 1);
  // Epochs that a frame falls in: streams of 10 frames (steps 0..9) reach epoch 1 only; 11 frames
  // reach epoch 2 (step 10); 5 frames none after the first.
  EXPECT_EQ(ReclusterEpochs(10, p), 1);
  EXPECT_EQ(ReclusterEpochs(11, p), 2);
  EXPECT_EQ(ReclusterEpochs(5, p), 0);
  EXPECT_EQ(ReclusterEpochs(0, p), 0);
}

TEST(Recluster, InvalidParametersNameTheField) {
  ReclusterParams p;
  p.clusters_per_robot = 0;
  EXPECT_THROW(
      {
        try {
          p.Validate();
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("clusters_per_robot"), std::string::npos);
          throw;
        }
      },
      std::invalid_argument);
  p.clusters_per_robot = 1;
  p.period = 0;
  EXPECT_THROW(p.Validate(), std::invalid_argument);
}

TEST(Recluster, TableClustersTheSampleAndPacksByLpt) {
  // Sample 0 0 0 100 100 200, 3 robots x 1 cluster: k-means++ never seeds on a point already
  // chosen (D^2 = 0), so the centroids are 0, 100 and 200 whatever the seed. Loads (counts + 1):
  // 4, 3, 2; LPT: 4 -> robot 0, 3 -> robot 1, 2 -> robot 2.
  ReclusterParams p;
  p.clusters_per_robot = 1;
  const DescriptorMatrix sample = Column({0, 0, 0, 100, 100, 200});
  for (int epoch : {1, 2}) {  // another seed, the same table
    const CentroidTable t = ReclusterTable(sample, Robots({0, 1, 2}), 3, p, epoch);
    ASSERT_EQ(t.num_centroids(), 3);
    const float a = 10, b = 90, c = 190;
    EXPECT_EQ(t.RouteOf(&a), RobotId(0));
    EXPECT_EQ(t.RouteOf(&b), RobotId(1));
    EXPECT_EQ(t.RouteOf(&c), RobotId(2));
  }
  // Robot 1 sent no sample (dropped out): LPT over robots 0 and 2: 4 -> 0, 3 -> 2, then 2 goes to
  // the less loaded robot 2 (3 < 4). Robot 1 owns nothing.
  const CentroidTable live = ReclusterTable(sample, Robots({0, 2}), 3, p, 1);
  const float a = 10, b = 90, c = 190;
  EXPECT_EQ(live.RouteOf(&a), RobotId(0));
  EXPECT_EQ(live.RouteOf(&b), RobotId(2));
  EXPECT_EQ(live.RouteOf(&c), RobotId(2));
  EXPECT_TRUE(live.CentroidsOf(RobotId(1)).empty());
}

TEST(Recluster, KIsCappedByTheSampleRows) {
  // 2 robots x 4 clusters = 8 > 2 sample rows: k = 2, one centroid on each row.
  ReclusterParams p;
  p.clusters_per_robot = 4;
  const CentroidTable t = ReclusterTable(Column({0, 100}), Robots({0, 1}), 2, p, 1);
  EXPECT_EQ(t.num_centroids(), 2);
  const float a = 1, b = 99;
  EXPECT_NE(t.RouteOf(&a), t.RouteOf(&b));
  EXPECT_THROW(ReclusterTable(DescriptorMatrix(0, 1), Robots({0, 1}), 2, p, 1), std::invalid_argument);
  EXPECT_THROW(ReclusterTable(Column({0, 100}), {}, 2, p, 1), std::invalid_argument);
}

TEST(IncrementalIndexRemoveIf, KeepsTheOthersInOrder) {
  IncrementalIndex index(1);
  for (int f = 0; f < 4; ++f) {
    const float d = 10.0f * static_cast<float>(f);  // 0 10 20 30
    index.Add(RobotId(f % 2), FrameId(f), &d);
  }
  index.RemoveIf([](std::size_t i) { return i == 1 || i == 2; });
  ASSERT_EQ(index.size(), 2u);
  EXPECT_EQ(index.entries()[0].frame, FrameId(0));
  EXPECT_EQ(index.entries()[1].frame, FrameId(3));
  EXPECT_EQ(index.entries()[1].robot, RobotId(1));
  EXPECT_EQ(*index.Descriptor(1), 30.0f);
  // A query at 18 (frame 100, no window): frames 0 (distance 324) and 3 (144) are left.
  const float q = 18;
  const IndexSearchResult r = index.Search(&q, FrameId(100), 0);
  ASSERT_TRUE(r.best);
  EXPECT_EQ(r.best->frame, FrameId(3));
  EXPECT_FLOAT_EQ(r.best->distance, 144.0f);
  EXPECT_EQ(r.comparisons, 2);
}

}  // namespace
}  // namespace dvpr
