#pragma once
// The start barrier and the clean end of a team of real agent processes,
// built on the agent_status_t heartbeats every agent announces on
// DVPR_STATUS (see docs in README, "Running real agents").
//
// Start: every agent announces READY with the wall-clock instant it became
// ready. Once an agent has heard all n robots of its team (same team key: each launch
// puts a nonce of its own into it, so two teams of one config on one URL stay apart), it
// knows every ready instant and computes start = latest of them + margin:
// every agent computes the same instant without a leader, and the margin lets
// the others hear the last announcement before anyone starts.
//
// End: an agent announces DONE when all its own queries are answered (or it
// gave up on them). It keeps serving until every robot has announced DONE, so
// no robot leaves while another may still query it; a robot that died never
// announces DONE, so the others leave at their deadline instead.
//
// Members: a heartbeat names its sender (the socket it came from, an opaque number the
// transport gives). The first sender heard for a robot is that robot's; a heartbeat for it
// from another sender, or one sender speaking for two robots, is foreign (a second process
// started for the same robot, a copy of the team). Messages are then taken only from the
// sender of the robot they claim to come from (FromMember).
//
// Pure state: no transport, no clock, so it is tested without a network.
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <dvpr/agent_status_t.hpp>

#include "agents/algorithms/ids.h"
#include "lcmtypes/channels/channels.h"

namespace dvpr {

namespace channels {
inline const std::string kStatus = ChannelName(ChannelKind::kStatus);
}  // namespace channels

class TeamSync {
 public:
  // team_key: hash of everything the agents must agree on (agents with
  // another key are a different team, e.g. another experiment on the group).
  TeamSync(RobotId self, int robots, std::int64_t team_key);

  // Takes a heartbeat from `sender` (0: unknown, e.g. the agent's own, taken directly).
  // Returns false for one that is not of this team (wrong key or team size, robot out of
  // range, unknown state, another sender than the robot's): counted as foreign.
  bool OnStatus(const agent_status_t& s, std::uint64_t sender = 0);
  // Whether `sender` is the one whose heartbeats announce `robot`.
  bool FromMember(RobotId robot, std::uint64_t sender) const;

  // The heartbeat this agent announces.
  agent_status_t Announce(std::int64_t utime, std::int8_t state, std::int64_t ready_utime,
                          std::int32_t frames_taken) const;

  int HeardCount() const;                           // robots heard (self included once announced)
  // The agreed start (wall clock, us since the Unix epoch), once all are heard.
  std::optional<std::int64_t> StartUtime(std::int64_t margin_us) const;
  bool AllDone() const;
  bool IsDone(RobotId r) const { return done_.at(static_cast<std::size_t>(r.value)); }
  std::uint64_t foreign() const { return foreign_; }

 private:
  RobotId self_;
  int robots_;
  std::int64_t team_key_;
  std::vector<std::optional<std::int64_t>> ready_utime_;  // per robot, once heard
  std::vector<bool> done_;
  std::vector<std::uint64_t> sender_;                 // per robot, once heard from the network
  std::unordered_map<std::uint64_t, int> robot_of_;  // the other way round
  std::uint64_t foreign_ = 0;
};

// 64-bit FNV-1a, to build team keys from bytes that must agree across agents.
class Fnv1a {
 public:
  void Add(const void* data, std::size_t size);
  template <typename T>
  void AddValue(const T& v) { Add(&v, sizeof v); }
  std::int64_t value() const { return static_cast<std::int64_t>(h_); }

 private:
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

}  // namespace dvpr
