#pragma once
// One robot's routing component: where the robot sends its own frames and how it keeps the
// queries it is told to store. The agent (RobotAgent) knows only this interface; a strategy
// with per-robot state (re-clustering, agents/recluster/) keeps that state here, a stateless
// strategy is wrapped by StatelessPlacement (agents/placement/stateless_placement.h).
//
// What a received query asks of its receiver comes with it (its channel, QueryRole in
// agents/messages/channels.h): the agent searches when told to and hands what it must store to Store().
//
// TeamPlacement is what a run's agents are built from: one shared, immutable object per run that
// makes each robot's component.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "agents/algorithms/ids.h"
#include "agents/placement/failure_detector.h"

namespace dvpr {

class IncrementalIndex;
class Transport;
struct FrameStream;

// The parts of its robot a routing component works with. All outlive the component.
struct AgentContext {
  RobotId self;
  Transport& transport;
  IncrementalIndex& store;    // the descriptors the robot keeps and searches
  const FrameStream& frames;  // when the robot takes its frames
};

// Where one of the robot's own frames goes.
struct QueryPlan {
  bool search_here = false;           // the robot searches its own store too
  bool store_here = false;            // and keeps the frame
  int searches = 0;                   // replies to wait for, the local search included
  std::vector<std::string> channels;  // the query is published once on each
};

class AgentPlacement {
 public:
  virtual ~AgentPlacement() = default;

  // The robot starts (before its first frame): the component keeps `robot`, subscribes to the
  // channels of its own messages and schedules its own timers.
  virtual void Start(const AgentContext& robot) = 0;
  // The robot went offline: the component sends and keeps nothing from now on.
  virtual void Stop() = 0;
  // Where the robot's frame with this descriptor goes.
  virtual QueryPlan Plan(const float* descriptor) const = 0;
  // Keeps a query the robot was told to store (its own frame or a remote one), `querier` being
  // the robot that took it.
  virtual void Store(RobotId querier, FrameId frame, const float* descriptor) = 0;
  // The robots this component has declared lost (failover, agents/placement/failover_placement.h), in order
  // of detection; none for a component without failover.
  virtual std::vector<LostRobot> Lost() const { return {}; }
};

class TeamPlacement {
 public:
  virtual ~TeamPlacement() = default;

  virtual std::string_view name() const = 0;
  int num_robots() const { return num_robots_; }
  // A new component for one robot of the team; the team routing outlives it.
  virtual std::unique_ptr<AgentPlacement> MakeAgentPlacement() const = 0;

 protected:
  explicit TeamPlacement(int num_robots) : num_robots_(num_robots) {}

 private:
  int num_robots_;
};

}  // namespace dvpr
