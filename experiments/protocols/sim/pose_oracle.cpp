#include "experiments/protocols/sim/pose_oracle.h"

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

}  // namespace dvpr
