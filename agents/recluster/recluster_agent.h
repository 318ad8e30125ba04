#pragma once
// One robot's part in adaptive re-clustering (issue 8; the shared rules are in
// agents/recluster/recluster.h): its routing component, which keeps the robot's current table
// (tables differ between robots while a new one travels) and runs the re-clustering messages.
//
// Per epoch e (virtual time e x period / fps):
// - every robot sends the leader its sample: the descriptors it stores whose frame is in the
//   epoch's sample (descriptor_batch_t on DVPR_SAMPLE_<leader>, also when empty);
// - the leader (robot 0), once it has its own and every other robot's sample, or when the sample
//   timeout runs out, computes the table (ReclusterTable; instantaneous in virtual time: k-means
//   on a few hundred rows is milliseconds next to a period of seconds) and publishes it
//   (centroid_table_t on DVPR_TABLE). Only robots whose sample arrived get clusters: a robot
//   that dropped out sends none, so it is left out after the timeout;
// - a robot that receives a newer table switches to it and sends each stored descriptor it no
//   longer owns to its owner under that table (descriptor_batch_t on DVPR_MIGRATE_<dst>, one
//   message per destination).
// Between tables, a frame goes to the owner of its nearest centroid under the taking robot's
// table, on that owner's search-and-store channel. At store time a robot keeps the descriptor if
// its own table says it owns it, else forwards it (one migration message). A migration batch
// from a newer epoch than the receiver's is kept as is (the receiver re-routes it when the table
// arrives), so descriptors never bounce between robots with different tables; once every table
// has arrived every descriptor sits at its owner under the newest table.
//
// Limitation: if the leader drops out, re-clustering stops and the team keeps its last table.
#include <map>
#include <memory>

#include <dvpr/centroid_table_t.hpp>
#include <dvpr/descriptor_batch_t.hpp>

#include "agents/algorithms/centroid_table.h"
#include "agents/messages/transport.h"
#include "agents/placement/agent_placement.h"
#include "agents/recluster/recluster_placement.h"

namespace dvpr {

class ReclusterAgentPlacement final : public AgentPlacement {
 public:
  explicit ReclusterAgentPlacement(const ReclusterPlan& plan);  // `plan` outlives the component

  void Start(const AgentContext& robot) override;  // throws if the table's dimension is not the store's
  void Stop() override { online_ = false; }
  QueryPlan Plan(const float* descriptor) const override;
  void Store(RobotId querier, FrameId frame, const float* descriptor) override;

  // The robot's current epoch and table (epoch 0: the plan's initial table).
  int epoch() const { return epoch_; }
  const CentroidTable& table() const { return *table_; }

 private:
  struct Pending {  // the leader's collection of one epoch's samples
    bool own_taken = false;
    bool done = false;
    std::map<int, descriptor_batch_t> from;  // by sender
  };

  void OnEpochBoundary(int epoch);
  void OnSample(const descriptor_batch_t& b);
  void LeaderCompute(int epoch, bool timed_out);
  void PublishTable(std::shared_ptr<const CentroidTable> table, int epoch);
  void OnTable(const centroid_table_t& t);
  void AdoptTable(std::shared_ptr<const CentroidTable> table, int epoch);
  void OnMigration(const descriptor_batch_t& b);
  descriptor_batch_t NewBatch(int epoch) const;

  const ReclusterPlan& plan_;
  std::shared_ptr<const CentroidTable> table_;
  int epoch_ = 0;
  std::map<int, Pending> pending_;  // leader only, by epoch
  bool online_ = true;
  // The robot (Start).
  RobotId self_;
  Transport* transport_ = nullptr;
  IncrementalIndex* store_ = nullptr;
  std::vector<Subscription> subscriptions_;
};

}  // namespace dvpr
