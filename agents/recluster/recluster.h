#pragma once
// Adaptive re-clustering during the run (issue 8): the team starts from a table trained before
// deployment and, every `period` frames of each robot's stream, re-clusters descriptor space from
// a sample of the descriptors seen so far, so the clusters follow where the deployment actually
// is. Epoch e starts after every robot has taken e x period frames (robots advance in lockstep);
// frame k of a robot's stream belongs to epoch k / period.
//
// This file holds what both protocols share, with no LCM: which frames are sampled and how the
// leader turns the sample into the table of an epoch. The static protocol
// (experiments/protocols/paper/static_recluster.h) and the agents
// (agents/recluster/recluster_agent.h) call the same ReclusterTable, so the same sample gives the
// same table in both.
#include <cstdint>
#include <vector>

#include "agents/algorithms/centroid_table.h"
#include "agents/algorithms/descriptors.h"
#include "agents/algorithms/ids.h"
#include "agents/algorithms/kmeans.h"

namespace dvpr {

// Every kReclusterSampleStride-th frame of each robot's stream is in the re-clustering sample.
inline constexpr int kReclusterSampleStride = 4;

struct ReclusterParams {
  int clusters_per_robot = 4;   // k = clusters_per_robot x robots (at most the sample's rows)
  int period = 50;              // frames of each robot's stream per epoch
  int sample_stride = kReclusterSampleStride;
  KMeansParams kmeans;          // k and seed are set per epoch
  std::uint64_t seed = 0;       // the run's seed; epoch e clusters with MixSeed(seed, e)
  void Validate() const;        // throws std::invalid_argument naming the field
};

// Epoch of the frame at `step` (index within its robot's stream): step / period.
int ReclusterEpochOf(int step, const ReclusterParams& params);

// Whether the frame at `step` is in the sample of epoch `epoch` (>= 1): taken before the epoch's
// boundary (step < epoch x period) and on the sample stride.
bool InReclusterSample(int step, int epoch, const ReclusterParams& params);

// Epochs after the first: e = 1..Epochs with e x period < the longest stream (an epoch no frame
// falls in is not run).
int ReclusterEpochs(int longest_stream, const ReclusterParams& params);

// The table of epoch `epoch` from the team's sample (rows in frame-id order): k-means++ / Lloyd
// with k = min(clusters_per_robot x num_robots, rows) and seed MixSeed(params.seed, epoch), then
// the clusters packed onto the robots of `live` (ascending; the leader's view of who is there) by
// LPT on the sample's nearest-centroid counts (plus one each, as LoadBalancedTable). Robots not in
// `live` own no centroid. Throws std::invalid_argument on an empty sample or `live`.
CentroidTable ReclusterTable(const DescriptorMatrix& sample, const std::vector<RobotId>& live, int num_robots,
                             const ReclusterParams& params, int epoch);

}  // namespace dvpr
