#pragma once
// The rows of closure_pairs.csv (docs/design.md section 3, "Inter-robot loop closures"), written
// when the sweep runs a team (the sim or lcm protocol): per pair of robots, when its first
// inter-robot loop closure was found. The run's counts are runs.csv's (RunClosures, results.h).
// Plain data, as results.h.
#include <cstdint>
#include <optional>

#include "experiments/results/results.h"

namespace dvpr {

// One row of closure_pairs.csv: one pair of robots a < b of one run of one strategy.
struct ClosurePairRow {
  RunKey key;
  int robot_a = 0;
  int robot_b = 0;
  std::optional<std::int64_t> first_closure_ns;  // sending time of the query that found it; empty: none
};

}  // namespace dvpr
