#pragma once
// Adaptive re-clustering (issue 8; agents/recluster/recluster.h) in the static protocol. The table of
// epoch e is computed from the frames seen before its boundary: the frames at step < e x period
// (index within the robot's stream, SplitSequence) on the sample stride. Frame i, taken at step
// t_i, belongs to epoch e_i = t_i / period and is searched by its owner under table e_i.
//
// Candidates: query i and frame j (outside the window) are compared iff they have the same owner
// under the table of epoch max(e_i, e_j): the later of the two is searched (or, if it is the
// earlier, searched against) after the earlier has been migrated to its owner under that table.
// For one fixed table this is the paper's rule. Worst balance ratio = max over robots of the
// searches served / (N / n), as EvaluatePlacement; stored per robot = where each frame ends up
// (its owner under the last table).
//
// Bytes: the static row has no network, so its wire_bytes stay 0 and bytes_per_query
// not-applicable; its messages and payload_bytes are the re-clustering traffic alone (queries and
// replies are not counted there), in LCM-encoded sizes:
// - per epoch, every robot but the leader uploads one sample batch: the sample frames it holds at
//   the boundary (its frames under table e - 1);
// - the table goes to the n - 1 other robots (one copy each, as on point-to-point links);
// - every (old owner, new owner) pair with frames to move sends one migration batch.
// The simulation counts the same messages plus what the idealisation hides: frames routed with
// an old table while the new one travels, forwarded by the robot that received them.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "agents/algorithms/centroid_table.h"
#include "agents/recluster/recluster.h"
#include "experiments/protocols/paper/static_protocol.h"

namespace dvpr {

struct StaticReclusterPlan {
  ReclusterParams params;
  int robots = 0;
  std::vector<std::shared_ptr<const CentroidTable>> tables;  // epochs 0..E
  std::vector<int> step;                       // per frame: index within its robot's stream
  std::vector<int> epoch;                      // per frame: step / period
  std::vector<std::vector<RobotId>> route;     // route[e][frame]: owner under table e
  int epochs() const { return static_cast<int>(tables.size()) - 1; }
  RobotId SearchedAt(std::size_t frame) const { return route[static_cast<std::size_t>(epoch[frame])][frame]; }
  RobotId FinalOwner(std::size_t frame) const { return route.back()[frame]; }
  bool Candidates(std::int64_t i, std::int64_t j) const;  // the max(e_i, e_j) rule
};

// Frames (ascending) in the sample of epoch `epoch`, given every frame's step.
std::vector<int> ReclusterSampleFrames(const std::vector<int>& step, int epoch, const ReclusterParams& params);

// The plan with given tables (tables[e] for e = 0..E, E = ReclusterEpochs of the longest stream;
// throws std::invalid_argument if the count differs): steps, epochs and routes.
StaticReclusterPlan MakeStaticReclusterPlan(const DescriptorMatrix& deployment, int robots,
                                            std::vector<std::shared_ptr<const CentroidTable>> tables,
                                            const ReclusterParams& params);

// The plan of a run: `initial` for epoch 0, then ReclusterTable on each epoch's sample (every
// robot live, leader robot 0).
StaticReclusterPlan PlanStaticRecluster(const DescriptorMatrix& deployment, std::shared_ptr<const CentroidTable> initial,
                                        const ReclusterParams& params);

struct ReclusterTraffic {
  std::int64_t sample_messages = 0, sample_bytes = 0;
  std::int64_t table_messages = 0, table_bytes = 0;
  std::int64_t migration_messages = 0, migration_bytes = 0;
  std::int64_t migrated = 0;  // descriptors moved
  std::int64_t messages() const { return sample_messages + table_messages + migration_messages; }
  std::int64_t bytes() const { return sample_bytes + table_bytes + migration_bytes; }
};

// The re-clustering messages of the plan (see the file comment), descriptors of `dim` floats.
ReclusterTraffic CountReclusterTraffic(const StaticReclusterPlan& plan, int dim, RobotId leader = RobotId(0));

// Fills the row as EvaluatePlacement does (protocol "paper", strategy `name`), plus messages and
// payload_bytes = the plan's re-clustering traffic; per_robot: searches served, stored at the
// end, comparisons (candidates of the queries it served).
PaperRunResult EvaluateRecluster(const PaperEvaluator& evaluator, const StaticReclusterPlan& plan,
                                 const std::string& name, bool keep_curve);

}  // namespace dvpr
