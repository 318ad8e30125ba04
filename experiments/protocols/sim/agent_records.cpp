#include "experiments/protocols/sim/agent_records.h"

#include <cmath>

namespace dvpr {

GeometricVerifier PoseOracle(const Positions& positions, double radius_m) {
  return [&positions, radius_m](FrameId query, FrameId match) {
    const auto rows = positions.rows();
    VerifyVerdict v;
    if (query.value < 0 || query.value >= rows || match.value < 0 || match.value >= rows) return v;
    const double d = (positions.row(query.value) - positions.row(match.value)).norm();
    v.accepted = d < radius_m;
    v.inliers = static_cast<int>(std::lround(100.0 * std::exp(-d / radius_m)));
    return v;
  };
}

QueryRecord ToQueryRecord(RobotId robot, const QueryOutcome& o) {
  QueryRecord q;
  q.robot = robot;
  q.frame = o.frame;
  q.sent = o.sent;
  if (o.best) {
    q.match_robot = o.best->robot;
    q.match_frame = o.best->frame;
    q.distance = o.best->distance;
  }
  if (o.Complete() && o.last_reply) q.latency = *o.last_reply - o.sent;
  return q;
}

}  // namespace dvpr
