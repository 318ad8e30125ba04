#pragma once
// Geometric verification as the simulated team (experiments/protocols/sim/simulation.h) and the
// real agent processes (experiments/protocols/lcm/agent_process.h) both run it, so both verify
// the same way.
#include "agents/robot_agent.h"
#include "experiments/domain/data/dataset.h"

namespace dvpr {

// Geometric verification as an oracle on the ground-truth poses: a real
// verifier accepts a match when enough keypoints agree, which for a true
// revisit (within the radius) they do. Inliers fall with the distance. A frame
// id outside the sequence (a foreign or corrupt request) is rejected.
GeometricVerifier PoseOracle(const Positions& positions, double radius_m);

}  // namespace dvpr
