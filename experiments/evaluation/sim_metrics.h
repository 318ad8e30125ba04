#pragma once
// Online metrics of one simulation run (docs/design.md section 3), as pure
// functions of what the agents and the network recorded.
#include <cstdint>
#include <optional>
#include <vector>

#include "agents/algorithms/ids.h"
#include "agents/algorithms/query_record.h"
#include "experiments/data/dataset.h"
#include "sim/sim_time.h"

namespace dvpr {

struct LatencyStats {
  double mean_ms = 0.0;
  double p99_ms = 0.0;                 // nearest rank: the ceil(0.99 n)-th smallest
  std::int64_t complete = 0;           // queries whose every reply arrived
  std::int64_t incomplete = 0;
};

// Latency over the complete queries; zeros when there are none.
LatencyStats ComputeLatency(const std::vector<QueryRecord>& queries);

// Relevance in the online setting: query i is relevant when a frame taken at
// or before it (by any robot), more than `window` frames away in the
// sequence, lies within `radius_m`. A query whose returned match is correct is
// relevant too: that frame was in a store when the query was served, even if
// network delay let it be taken after the query.
// capture_time[j] is when frame j was taken.
struct OnlineTruth {
  std::vector<bool> relevant;          // per query, in `queries` order
  std::vector<bool> correct;
};
OnlineTruth ComputeOnlineTruth(const std::vector<QueryRecord>& queries, const Positions& positions,
                               const std::vector<SimTime>& capture_time, double radius_m, int window);

}  // namespace dvpr
