#pragma once
// A simulated team, built in one place from what it physically is (ns-3's helpers): n robots
// driving their sub-sequences of the deployment (docs/design.md section 3) with their agents,
// over a network whose stack (net_models/network/network_stack.h) places each robot on its track. What
// is measured and written is not the scenario's: the ground-truth oracle comes in with the agent
// factory, and recorders subscribe to network() before Run (simulation.cpp attaches the run's).
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "agents/agent_core.h"
#include "agents/agent_params.h"
#include "agents/algorithms/ids.h"
#include "agents/messages/decoded_messages.h"
#include "agents/messages/sim_transport.h"
#include "agents/team_agent.h"
#include "experiments/domain/data/dataset.h"
#include "experiments/domain/data/split.h"
#include "net_models/helper/link_factory.h"
#include "net_models/link_state/daemon/link_state_daemon.h"
#include "net_models/mobility/track_mobility.h"
#include "net_models/network/network.h"
#include "sim/simulator.h"

namespace dvpr {

struct RobotDropout {
  RobotId robot;
  SimTime at;  // from this time on the robot is offline
};

// The robot talks only inside its windows (Network::SetTalkWindows), ascending and disjoint.
struct RobotTalkWindows {
  RobotId robot;
  std::vector<TalkWindow> windows;
};

// The physics of a run, nothing about evaluation or outputs.
struct ScenarioParams {
  int robots = 2;
  std::uint64_t seed = 1;        // seeds the network's random streams (loss)
  AgentParams agent;
  NetworkModelParams network;
  std::vector<RobotDropout> dropouts;
  std::vector<RobotTalkWindows> talk_windows;  // robots not named talk all the time
  std::int64_t start_utime = 0;  // virtual time 0 in microseconds since 1970 (messages' utime)
  // Throws std::invalid_argument naming the field: fewer than 2 robots, more robots than frames
  // or than int16 robot ids, descriptors wider than query_t's int16 dim, a trajectory without a
  // pose per frame, bad agent or network parameters, a dropout of a robot outside the team.
  void Validate(const Dataset& data) const;
};

// Makes robot setup.id's agent, talking through `transport` (both outlive the agent).
using AgentFactory = std::function<std::unique_ptr<TeamAgent>(const AgentSetup& setup, Transport& transport)>;

// Where each robot is: robot r's track is the poses of its frames at their capture times
// (FrameStream::TimeOf), from `split` (TeamSplit of `data`); a robot is at its first pose until
// it takes its first frame and stays at its last after its last.
TrackMobility RobotTracks(const Dataset& data, const SequenceSplit& split);

class Scenario {
 public:
  // Builds the simulator, the network and one transport and one agent per robot. Throws
  // std::invalid_argument from ScenarioParams::Validate.
  Scenario(const Dataset& data, const ScenarioParams& params, const AgentFactory& make_agent);
  Scenario(const Scenario&) = delete;
  Scenario& operator=(const Scenario&) = delete;

  // Subscribe observers here before Run; they must not outlive the scenario.
  Network& network() { return network_; }
  const Network& network() const { return network_; }
  // Starts every robot's routing daemon (link_state routing) and agent, sets the dropouts, runs
  // the simulator until no event is left.
  void Run();

  const ScenarioParams& params() const { return params_; }
  const Simulator& simulator() const { return sim_; }
  const SequenceSplit& split() const { return split_; }
  const std::vector<std::unique_ptr<TeamAgent>>& agents() const { return agents_; }
  // One per robot with link_state routing (sending its beacons until the team's last frame),
  // else none.
  const std::vector<std::unique_ptr<LinkStateDaemon>>& daemons() const { return daemons_; }
  bool IsDropped(RobotId robot) const;
  // Per frame of the sequence, when the robot that drives it takes it.
  std::vector<SimTime> CaptureTimes() const;

 private:
  const Dataset& data_;
  ScenarioParams params_;
  SequenceSplit split_;
  Simulator sim_;
  Network network_;
  DecodedMessages decoded_;  // shared by the transports: a broadcast is decoded once, not once a robot
  std::vector<std::unique_ptr<SimTransport>> transports_;
  std::vector<std::unique_ptr<TeamAgent>> agents_;
  std::vector<std::unique_ptr<LinkStateDaemon>> daemons_;  // after the transports: destroyed first
};

}  // namespace dvpr
