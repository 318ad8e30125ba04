#pragma once
// Step 5 of the method: geometric verification of a match by the robot that observed the
// matched frame. The simulation supplies a verifier that checks the poses (PoseOracle).
#include <functional>

#include "agents/algorithms/ids.h"

namespace dvpr {

struct VerifyVerdict {
  bool accepted = false;
  int inliers = 0;
};
// Geometric verification as the robot that saw `match` runs it against the
// query's keypoints.
using GeometricVerifier = std::function<VerifyVerdict(FrameId query, FrameId match)>;

}  // namespace dvpr
