#pragma once
// Adaptive re-clustering in the robots' protocol (issue 8; the shared rules are in
// agents/recluster.h). The agent finds it through the routing object it is given: a
// ReclusterRouting carries the team's plan, and every RobotAgent built with one keeps its own
// current table (tables differ between robots while a new one travels).
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
// table. A robot searches every query it receives; at store time it keeps the descriptor if its
// own table says it owns it, else forwards it (one migration message). A migration batch from a
// newer epoch than the receiver's is kept as is (the receiver re-routes it when the table
// arrives), so descriptors never bounce between robots with different tables; once every table
// has arrived every descriptor sits at its owner under the newest table.
//
// Limitation: if the leader drops out, re-clustering stops and the team keeps its last table.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <dvpr/centroid_table_t.hpp>
#include <dvpr/descriptor_batch_t.hpp>

#include "agents/centroid_table.h"
#include "agents/recluster.h"
#include "agents/routing.h"
#include "sim/sim_time.h"

namespace dvpr {

namespace channels {
inline std::string Sample(RobotId leader) { return "DVPR_SAMPLE_" + std::to_string(leader.value); }
inline std::string Migrate(RobotId dst) { return "DVPR_MIGRATE_" + std::to_string(dst.value); }
inline const std::string kTable = "DVPR_TABLE";
}  // namespace channels

// LCM-encoded sizes (fingerprint included), worked out from LCM's rules and pinned against
// Encode() in tests/agents/test_lcm_messages.cpp. The static protocol counts bytes with them.
// descriptor_batch_t: 8 + utime 8 + epoch 4 + sender 2 + count 4 + dim 2 = 28, then per
// descriptor robot 2 + frame 4 + dim floats.
inline std::int64_t DescriptorBatchBytes(std::int64_t count, int dim) { return 28 + count * (6 + 4 * std::int64_t{dim}); }
// centroid_table_t: 8 + utime 8 + epoch 4 + leader 2 + k 2 + dim 2 = 26, then k x dim floats and
// k int16 owners.
inline std::int64_t CentroidTableBytes(int k, int dim) { return 26 + std::int64_t{k} * (4 * std::int64_t{dim} + 2); }

// What the team agrees on before the run.
struct ReclusterPlan {
  ReclusterParams params;
  std::shared_ptr<const CentroidTable> initial;  // epoch 0 (trained before deployment)
  std::vector<FrameId> stream_first;  // per robot: the first frame of its stream (steps from it)
  int epochs = 0;                     // re-clusterings e = 1..epochs (ReclusterEpochs)
  RobotId leader{0};
  SimTime sample_timeout = SimTime::Seconds(1.0);  // the leader's wait for samples
  // Epoch e starts when the robots take frame e x period of their streams (FrameStream::TimeOf).
  void Validate() const;              // throws std::invalid_argument
  int StepOf(RobotId robot, FrameId frame) const {
    return frame.value - stream_first.at(static_cast<std::size_t>(robot.value)).value;
  }
};

// The routing every agent of a re-clustering team is given. As a RoutingStrategy it routes with
// the initial table (nearest owner searches and stores); the agents route with their own current
// table instead (RobotAgent detects this class).
class ReclusterRouting final : public RoutingStrategy {
 public:
  explicit ReclusterRouting(ReclusterPlan plan);
  std::string_view name() const override { return "recluster"; }
  const ReclusterPlan& plan() const { return plan_; }

 private:
  void DoRoute(RobotId, const float* descriptor, RoutingDecision& out) const override {
    const RobotId owner = plan_.initial->RouteOf(descriptor);
    out.search_at.push_back(owner);
    out.store_at.push_back(owner);
  }
  ReclusterPlan plan_;
};

// One robot's re-clustering state (owned by RobotAgent).
struct ReclusterState {
  struct Pending {  // the leader's collection of one epoch's samples
    bool own_taken = false;
    bool done = false;
    std::map<int, descriptor_batch_t> from;  // by sender
  };
  const ReclusterPlan* plan = nullptr;
  std::shared_ptr<const CentroidTable> table;
  int epoch = 0;
  std::map<int, Pending> pending;  // leader only, by epoch
};

}  // namespace dvpr
