#pragma once
// Adaptive re-clustering as a team routing (issue 8): the plan the team agrees on before the
// run, and the TeamPlacement that gives every robot its own ReclusterAgentPlacement
// (agents/recluster/recluster_agent.h) over that plan.
#include <memory>
#include <string_view>
#include <vector>

#include "agents/algorithms/centroid_table.h"
#include "agents/algorithms/ids.h"
#include "agents/placement/agent_placement.h"
#include "agents/recluster/recluster.h"
#include "sim/sim_time.h"

namespace dvpr {

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

class ReclusterPlacement final : public TeamPlacement {
 public:
  explicit ReclusterPlacement(ReclusterPlan plan);  // validates the plan
  std::string_view name() const override { return "recluster"; }
  const ReclusterPlan& plan() const { return plan_; }
  // A ReclusterAgentPlacement over plan().
  std::unique_ptr<AgentPlacement> MakeAgentPlacement() const override;

 private:
  ReclusterPlan plan_;
};

}  // namespace dvpr
