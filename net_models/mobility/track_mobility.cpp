#include "net_models/mobility/track_mobility.h"

#include <algorithm>
#include <string>

#include "net_models/core/param_checks.h"

namespace dvpr {

TrackMobility::TrackMobility(std::vector<std::vector<Waypoint>> tracks) : tracks_(std::move(tracks)) {
  if (tracks_.empty()) InvalidParam("tracks", "a network needs at least one node, got none");
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    const std::string track = "tracks[" + std::to_string(i) + "]";
    if (tracks_[i].empty()) InvalidParam(track, "a node's track needs at least one waypoint, got none");
    for (std::size_t k = 0; k < tracks_[i].size(); ++k) {
      const std::string field = track + "[" + std::to_string(k) + "]";
      CheckFinitePosition(field + ".where", tracks_[i][k].where);
      if (k > 0 && tracks_[i][k].at <= tracks_[i][k - 1].at) {
        InvalidParam(field + ".at", "waypoint times must strictly increase, got " + FormatDuration(tracks_[i][k].at) +
                                        " after " + FormatDuration(tracks_[i][k - 1].at));
      }
    }
  }
}

// Interpolated in double; the nanosecond counts convert exactly (any run is far below 2^53 ns).
Position TrackMobility::DoPositionOf(NodeId node, SimTime at) const {
  const std::vector<Waypoint>& track = tracks_[static_cast<std::size_t>(node.value)];
  const auto after = std::upper_bound(track.begin(), track.end(), at,
                                      [](SimTime t, const Waypoint& w) { return t < w.at; });
  if (after == track.begin()) return track.front().where;  // not started: waits at its first waypoint
  if (after == track.end()) return track.back().where;     // finished: stays where it stopped
  const Waypoint& a = *(after - 1);
  const Waypoint& b = *after;
  const double f = static_cast<double>((at - a.at).ns()) / static_cast<double>((b.at - a.at).ns());
  return Position{a.where.x + f * (b.where.x - a.where.x), a.where.y + f * (b.where.y - a.where.y),
                  a.where.z + f * (b.where.z - a.where.z)};
}

}  // namespace dvpr
