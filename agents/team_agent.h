#pragma once
// What a run's team code needs of one robot agent, whatever it matches with: the simulation
// (experiments/protocols/sim/simulation.h) and a real agent process
// (experiments/protocols/lcm/agent_process.h) drive a RobotAgent (global descriptors) and a
// BowRobotAgent (bag-of-words) through this interface alone.
#include <string>
#include <vector>

#include "agents/algorithms/ids.h"
#include "agents/algorithms/index.h"
#include "agents/algorithms/query_record.h"
#include "agents/algorithms/robot_load.h"
#include "agents/placement/failure_detector.h"

namespace dvpr {

class TeamAgent {
 public:
  virtual ~TeamAgent() = default;

  // Subscribes to the robot's channels and schedules its first frame at t = 0.
  virtual void Start() = 0;
  // The channels Start() subscribes to (a real agent holds them from before its start barrier:
  // LcmTransport::HoldUntilSubscribed).
  virtual std::vector<std::string> Inbox() const = 0;
  // From now on the robot takes no frames and serves nothing (dropout).
  virtual void GoOffline() = 0;

  virtual RobotId id() const = 0;
  // One record per frame of the stream, in order; a frame never taken (the robot went offline
  // first) is not Taken().
  virtual const std::vector<QueryRecord>& outcomes() const = 0;
  virtual RobotLoad load() const = 0;
  // The robots this agent declared lost (failover), in order of detection.
  virtual std::vector<LostRobot> Lost() const { return {}; }
  // The frames whose whole vector this agent stores, as another robot would hold a copy of one
  // (replication: what a dropout loses). None for an agent that keeps only parts of vectors
  // (BoW: no other robot holds the same part).
  virtual std::vector<IndexEntry> WholeFramesStored() const { return {}; }
};

}  // namespace dvpr
