#pragma once
// Load a robot carried while serving (docs/design.md section 3, per-robot load), as every kind of
// team agent records it (RobotAgent, BowRobotAgent).
#include <cstdint>

#include "sim/sim_time.h"

namespace dvpr {

struct RobotLoad {
  std::int64_t searches = 0;               // queries served: remote and its own local ones
  std::int64_t remote_queries = 0;         // of which arrived over the network
  std::int64_t comparisons = 0;            // descriptors compared; BoW: postings visited
  std::int64_t stored = 0;                 // descriptors in the robot's store when read; BoW: parts
  std::int64_t verifications = 0;
  SimTime busy;                            // total service time
  std::int64_t max_queue = 0;              // longest wait line seen (the task in service excluded)
  // Messages ignored for naming a robot outside the team (a real network's garbage or another
  // team's traffic; none in a simulation).
  std::int64_t foreign_ids = 0;
};

}  // namespace dvpr
