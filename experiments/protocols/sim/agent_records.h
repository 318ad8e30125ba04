#pragma once
// Pieces shared by the simulated team (experiments/protocols/sim/simulation.h) and the real
// agent processes (experiments/protocols/lcm/agent_process.h), so both verify and record
// queries the same way.
#include <vector>

#include "agents/robot_agent.h"
#include "experiments/data/dataset.h"
#include "experiments/evaluation/sim_metrics.h"

namespace dvpr {

// Geometric verification as an oracle on the ground-truth poses: a real
// verifier accepts a match when enough keypoints agree, which for a true
// revisit (within the radius) they do. Inliers fall with the distance. A frame
// id outside the sequence (a foreign or corrupt request) is rejected.
GeometricVerifier PoseOracle(const Positions& positions, double radius_m);

// The agent's outcome of one frame as a query record; latency is measured on
// the agent's clock (from publishing to the last reply) when every reply came.
QueryRecord ToQueryRecord(RobotId robot, const QueryOutcome& outcome);

}  // namespace dvpr
