#pragma once
// When each node of a network can talk (network.h): offline in one interval [from, until)
// (Network::SetOffline: a robot that drops out), and inside its talk windows only when it has any
// (Network::SetTalkWindows: Swarm-SLAM's connectivity schedule). The network asks it for every
// transmission and every arrival.
#include <vector>

#include "net_models/core/node_id.h"
#include "sim/sim_time.h"

namespace dvpr {

// An interval [from, until) of virtual time in which a node can talk (Network::SetTalkWindows).
struct TalkWindow {
  SimTime from;
  SimTime until;
  bool operator==(const TalkWindow&) const = default;
};

class Availability {
 public:
  // Nodes [0, nodes), each always online until told otherwise; nodes are the caller's to check.
  explicit Availability(int nodes);

  void SetOffline(NodeId node, SimTime from, SimTime until);
  // Windows ascending, disjoint, from < until; throws std::invalid_argument naming the window
  // otherwise. No windows: always talks.
  void SetTalkWindows(NodeId node, std::vector<TalkWindow> windows);

  bool IsOnline(NodeId node, SimTime at) const { return !DroppedOut(node, at) && InTalkWindow(node, at); }
  bool InTalkWindow(NodeId node, SimTime at) const;
  // Inside its [from, until) of SetOffline.
  bool DroppedOut(NodeId node, SimTime at) const {
    const auto i = static_cast<std::size_t>(node.value);
    return offline_from_[i] <= at && at < offline_until_[i];
  }

 private:
  int nodes_;
  std::vector<SimTime> offline_from_;
  std::vector<SimTime> offline_until_;
  std::vector<std::vector<TalkWindow>> talk_windows_;  // by node; empty until the first window is set
};

}  // namespace dvpr
