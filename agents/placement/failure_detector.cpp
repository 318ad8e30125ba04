#include "agents/placement/failure_detector.h"

#include <stdexcept>
#include <string>

namespace dvpr {

void FailoverParams::Validate() const {
  if (heartbeat_period < kMinPeriod || heartbeat_period > kMaxTimeout) {
    throw std::invalid_argument("heartbeat_period: " + std::to_string(heartbeat_period.ns()) +
                                " ns is outside [1 ms, 1 h]");
  }
  if (timeout <= heartbeat_period || timeout > kMaxTimeout) {
    throw std::invalid_argument("timeout: " + std::to_string(timeout.ns()) +
                                " ns must be longer than heartbeat_period and at most 1 h");
  }
}

FailureDetector::FailureDetector(RobotId self, int robots, SimTime timeout, SimTime start)
    : self_(self),
      timeout_(timeout),
      last_heard_(static_cast<std::size_t>(robots), start),
      lost_flag_(static_cast<std::size_t>(robots), false) {
  if (robots < 1) throw std::invalid_argument("FailureDetector: no robots");
  if (timeout <= SimTime::Zero()) throw std::invalid_argument("FailureDetector: timeout must be positive");
}

void FailureDetector::Heard(RobotId robot, SimTime at) {
  if (robot.value < 0 || robot.value >= static_cast<int>(last_heard_.size()) || robot == self_) return;
  const auto i = static_cast<std::size_t>(robot.value);
  if (lost_flag_[i]) return;
  if (at > last_heard_[i]) last_heard_[i] = at;
}

std::vector<RobotId> FailureDetector::Check(SimTime now) {
  std::vector<RobotId> newly;
  for (std::size_t i = 0; i < last_heard_.size(); ++i) {
    if (static_cast<int>(i) == self_.value || lost_flag_[i] || now - last_heard_[i] <= timeout_) continue;
    lost_flag_[i] = true;
    newly.push_back(RobotId(static_cast<int>(i)));
    lost_.push_back(LostRobot{newly.back(), now});
  }
  return newly;
}

}  // namespace dvpr
