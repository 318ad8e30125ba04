#pragma once
// Online metrics of one simulation run (docs/design.md section 3), as pure
// functions of what the agents and the network recorded.
#include <cstdint>
#include <optional>
#include <vector>

#include "agents/algorithms/frame_window.h"
#include "agents/algorithms/ids.h"
#include "agents/algorithms/query_record.h"
#include "experiments/domain/data/dataset.h"
#include "experiments/domain/evaluation/metrics.h"
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
// or before it (by any robot), outside its suppression window (frame_window.h),
// lies within `radius_m`. A query whose returned match is correct is
// relevant too: that frame was in a store when the query was served, even if
// network delay let it be taken after the query.
// capture_time[j] is when frame j was taken, taker[j] the robot that took it.
//
// A relevant query is inter-robot when one of its true matches is another robot's frame (a
// frame that makes it relevant, as above, taken by another robot; or its correct returned match,
// when another robot took that frame), intra-robot when they are all the querying robot's own:
// multi-robot SLAM needs the first kind (a robot recognising where another robot has been).
enum class QueryClass : std::uint8_t { kNotRelevant, kIntraRobot, kInterRobot };

struct OnlineTruth {
  std::vector<bool> relevant;          // per query, in `queries` order
  std::vector<bool> correct;
  std::vector<QueryClass> query_class;
};
OnlineTruth ComputeOnlineTruth(const std::vector<QueryRecord>& queries, const Positions& positions,
                               const std::vector<SimTime>& capture_time, const std::vector<RobotId>& taker,
                               double radius_m, const FrameWindow& window);

// What a query got back, as the PR evaluation ranks it (metrics.h): its best match and distance.
MatchOutcome OutcomeOf(const QueryRecord& q);

// "inter" or "intra" (queries.csv's class column), "" when not relevant.
const char* QueryClassName(QueryClass c);

// A pair of robots a < b and when the first inter-robot loop closure between them was found:
// the sending time of the first query (by either robot) whose verified match is the other's frame.
struct PairClosure {
  RobotId a;
  RobotId b;
  std::optional<SimTime> first;  // empty: none in the run
};

// Inter- and intra-robot place recognition and loop closures of one run (docs/design.md section
// 3, "Inter-robot loop closures").
struct ClosureStats {
  std::int64_t inter_queries = 0;     // relevant queries of each class
  std::int64_t intra_queries = 0;
  std::int64_t inter_recognised = 0;  // of which the returned match is correct (the class's recall: / queries)
  std::int64_t intra_recognised = 0;
  double inter_auc = 0.0;             // PR AUC over the class's queries (R: the class's count)
  double intra_auc = 0.0;
  // Verification exchanges asked for with a frame another robot took, and of them those the
  // verification accepted: inter-robot loop closures found. Their precision is closures /
  // candidates (every accepted one is true: the oracle verifies against the ground truth).
  std::int64_t inter_candidates = 0;
  std::int64_t inter_closures = 0;
  std::vector<PairClosure> pairs;     // every pair a < b of the team, by a, then b
};

// From the run's queries and their truth (ComputeOnlineTruth over the same queries).
ClosureStats ComputeClosures(const std::vector<QueryRecord>& queries, const OnlineTruth& truth,
                             const Positions& positions, const std::vector<RobotId>& taker, double radius_m,
                             int robots);

// The median over the pairs that found one of the time to their first closure (the mean of the
// two middle ones when even); empty when no pair did.
std::optional<SimTime> MedianFirstClosure(const std::vector<PairClosure>& pairs);

}  // namespace dvpr
