#pragma once
// How a robot notices that a teammate is gone (issue 14, docs/failover.md): every robot
// announces a heartbeat (agent_status_t on DVPR_STATUS) every heartbeat_period; a robot not
// heard for longer than `timeout` is declared lost. The failure model is crash-stop: a robot
// declared lost stays lost (its store died with it, and taking it back would need the team to
// agree on when), so a false suspicion costs recall, never consistency of the suspecting robot.
//
// Pure state: no transport, no clock, so it is tested without a network.
#include <vector>

#include "agents/algorithms/ids.h"
#include "sim/sim_time.h"

namespace dvpr {

struct FailoverParams {
  // The valid ranges (docs/config.md): a period of at least 1 ms keeps the heartbeats a small
  // share of the traffic; a timeout must span more than one period, or a robot is lost between
  // two heartbeats of a healthy teammate.
  static constexpr SimTime kMinPeriod = SimTime::Millis(1);
  static constexpr SimTime kMaxTimeout = SimTime::Millis(3600LL * 1000);  // 1 h

  bool enabled = false;                              // off: a lost robot's clusters stay lost
  SimTime heartbeat_period = SimTime::Millis(250);   // simulation; real agents announce every 50 ms wall
  SimTime timeout = SimTime::Seconds(1);             // silence after which a robot is lost
  void Validate() const;  // throws std::invalid_argument naming the field
  bool operator==(const FailoverParams&) const = default;
};

struct LostRobot {
  RobotId robot;
  SimTime detected;  // the observer's clock when it declared the robot lost
  bool operator==(const LostRobot&) const = default;
};

class FailureDetector {
 public:
  // Every robot counts as heard at `start` (the team starts together).
  FailureDetector(RobotId self, int robots, SimTime timeout, SimTime start);

  // A heartbeat of `robot` at `at`. Ignored for robots out of range, self and lost robots.
  void Heard(RobotId robot, SimTime at);
  // Declares lost every robot silent for longer than the timeout at `now`; returns those newly
  // lost, ascending.
  std::vector<RobotId> Check(SimTime now);

  bool IsLive(RobotId robot) const { return !lost_flag_.at(static_cast<std::size_t>(robot.value)); }
  const std::vector<bool>& lost_flags() const { return lost_flag_; }  // per robot
  const std::vector<LostRobot>& lost() const { return lost_; }        // in order of detection

 private:
  RobotId self_;
  SimTime timeout_;
  std::vector<SimTime> last_heard_;
  std::vector<bool> lost_flag_;
  std::vector<LostRobot> lost_;
};

}  // namespace dvpr
