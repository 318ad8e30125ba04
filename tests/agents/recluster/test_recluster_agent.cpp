// One robot's re-clustering component on its own (no RobotAgent), on a hand-made 1-D table:
// centroid 0 owned by robot 1, centroid 100 by robot 0, two robots on an ideal network. Where a
// frame goes under the robot's current table, and what Store keeps or forwards. The protocol as a
// whole (samples, tables, migrations) is tested in tests/protocols/sim/test_sim_recluster.cpp.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agents/algorithms/descriptor_index.h"
#include "agents/algorithms/frame_stream.h"
#include "agents/messages/sim_transport.h"
#include "agents/recluster/recluster_agent.h"
#include "agents/recluster/recluster_messages.h"
#include "net_models/medium/ideal_link.h"
#include "sim/simulator.h"
#include "tests/descriptor_support.h"

namespace dvpr {
namespace {

using dvpr::testing_support::Column;
using dvpr::testing_support::Robots;

class ReclusterAgentTest : public ::testing::Test {
 protected:
  ReclusterAgentTest() : network_(sim_, 2, std::make_unique<IdealLink>()) {
    CentroidMatrix c(2, 1);
    c << 0, 100;
    ReclusterPlan plan;
    plan.params.clusters_per_robot = 1;
    plan.initial = std::make_shared<const CentroidTable>(c, Robots({1, 0}), 2);
    plan.stream_first = {FrameId(0), FrameId(4)};
    plan.epochs = 0;  // no re-clustering: the initial table throughout
    routing_ = std::make_unique<ReclusterPlacement>(std::move(plan));
    for (int r = 0; r < 2; ++r) {
      transports_.push_back(std::make_unique<SimTransport>(network_, NodeId(r)));
      stores_.push_back(std::make_unique<IncrementalIndex>(1));
      components_.push_back(std::make_unique<ReclusterAgentPlacement>(routing_->plan()));
    }
  }
  void Start() {
    for (int r = 0; r < 2; ++r) {
      const auto i = static_cast<std::size_t>(r);
      components_[i]->Start(AgentContext{RobotId(r), *transports_[i], *stores_[i], frames_});
    }
  }

  Simulator sim_;
  Network network_;
  DescriptorMatrix x_ = Column({1, 99});
  FrameStream frames_{&x_, FrameId(0), 0, 10.0};
  std::unique_ptr<ReclusterPlacement> routing_;
  std::vector<std::unique_ptr<SimTransport>> transports_;
  std::vector<std::unique_ptr<IncrementalIndex>> stores_;
  std::vector<std::unique_ptr<ReclusterAgentPlacement>> components_;
};

TEST_F(ReclusterAgentTest, FramesGoToTheOwnerUnderTheRobotsTableToSearchAndStore) {
  Start();
  const ReclusterAgentPlacement& robot0 = *components_[0];
  EXPECT_EQ(robot0.epoch(), 0);
  EXPECT_EQ(&robot0.table(), routing_->plan().initial.get());
  const float near_0 = 1, near_100 = 99;
  const QueryPlan away = robot0.Plan(&near_0);  // robot 1's
  EXPECT_EQ(away.channels, std::vector<std::string>{"DVPR_QUERY_1"});
  EXPECT_EQ(away.searches, 1);
  EXPECT_FALSE(away.search_here);
  const QueryPlan own = robot0.Plan(&near_100);
  EXPECT_TRUE(own.channels.empty());
  EXPECT_TRUE(own.search_here);
  EXPECT_TRUE(own.store_here);
}

TEST_F(ReclusterAgentTest, StoreKeepsWhatTheRobotOwnsAndForwardsTheRestToItsOwner) {
  Start();
  int batches = 0;
  Subscription spy = transports_[1]->Subscribe<descriptor_batch_t>(channels::Migrate(RobotId(1)), [&](const descriptor_batch_t& b) {
    ++batches;
    EXPECT_EQ(b.count, 1);
    EXPECT_EQ(b.sender, 0);
    EXPECT_EQ(b.epoch, 0);
  });
  const float near_0 = 1, near_100 = 99;
  components_[0]->Store(RobotId(1), FrameId(5), &near_100);  // robot 0 owns it: kept
  components_[0]->Store(RobotId(1), FrameId(6), &near_0);    // robot 1's: one migration batch
  sim_.Run();
  ASSERT_EQ(stores_[0]->size(), 1u);
  EXPECT_EQ(stores_[0]->entries()[0].frame, FrameId(5));
  EXPECT_EQ(batches, 1);
  ASSERT_EQ(stores_[1]->size(), 1u);  // robot 1's component kept the migrated descriptor
  EXPECT_EQ(stores_[1]->entries()[0].frame, FrameId(6));
  EXPECT_EQ(stores_[1]->entries()[0].robot, RobotId(1));
}

TEST_F(ReclusterAgentTest, AStoppedRobotKeepsNoMigration) {
  Start();
  components_[1]->Stop();
  const float near_0 = 1;
  components_[0]->Store(RobotId(0), FrameId(6), &near_0);
  sim_.Run();
  EXPECT_EQ(stores_[0]->size(), 0u);
  EXPECT_EQ(stores_[1]->size(), 0u);
}

TEST_F(ReclusterAgentTest, StartRefusesDescriptorsOfAnotherDimension) {
  IncrementalIndex wide(3);
  ReclusterAgentPlacement component(routing_->plan());
  EXPECT_THROW(component.Start(AgentContext{RobotId(0), *transports_[0], wide, frames_}), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
