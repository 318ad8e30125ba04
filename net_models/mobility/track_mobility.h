#pragma once
// "track": each node follows its own piecewise-linear track of timed waypoints (ns-3's
// WaypointMobilityModel): between two waypoints it moves in a straight line at constant speed,
// before its first waypoint it waits at it, after its last it stays where it stopped
// (docs/design.md section 4.1). A robot's track is the poses of the frames it takes, at their
// capture times; per-robot trajectories are tracks of their own.
#include <vector>

#include "net_models/mobility/mobility_model.h"

namespace dvpr {

struct Waypoint {
  SimTime at;
  Position where;
  bool operator==(const Waypoint&) const = default;
};

class TrackMobility final : public MobilityModel {
 public:
  // tracks[i] is node i's track. Throws std::invalid_argument naming the track and waypoint
  // ("tracks[1][3].at: ...") for no node, a node without a waypoint, times that do not strictly
  // increase, or a coordinate that is not finite.
  explicit TrackMobility(std::vector<std::vector<Waypoint>> tracks);

  const std::vector<Waypoint>& TrackOf(NodeId node) const { return tracks_.at(static_cast<std::size_t>(node.value)); }

 private:
  int DoNodes() const override { return static_cast<int>(tracks_.size()); }
  Position DoPositionOf(NodeId node, SimTime at) const override;
  std::string_view DoName() const override { return "track"; }

  std::vector<std::vector<Waypoint>> tracks_;
};

}  // namespace dvpr
