#pragma once
// The words candidate selection and brokerage share: one robot's keyframe, and an edge between
// two robots' keyframes (an inter-robot loop closure, verified or a candidate).
#include <compare>
#include <cstdint>

#include "agents/algorithms/ids.h"

namespace dvpr {

// A keyframe of one robot: its index in that robot's own keyframe sequence (0, 1, ...; the
// odometry chain links k and k + 1), not a FrameId of the deployment sequence.
struct KeyframeRef {
  RobotId robot{};
  std::int32_t keyframe = 0;
  auto operator<=>(const KeyframeRef&) const = default;
};

// An edge between keyframes of two robots. For a candidate, `weight` is its similarity; verified
// (fixed) edges weigh MacParams::fixed_weight whatever `weight` says, as in Swarm-SLAM, which
// resets a verified edge's weight to its fixed weight.
struct KeyframeEdge {
  KeyframeRef a{};
  KeyframeRef b{};
  double weight = 1.0;
};

}  // namespace dvpr
