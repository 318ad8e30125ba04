#pragma once
// The routing strategies beyond the paper (issue 8) by config name. Parameters are fixed in the
// name, so a config lists what it compares and every name means one documented thing:
//
//   multi_probe_M             search at the owners of the M nearest centroids (FAISS nprobe)
//   adaptive_probe_E          search at the owners of centroids within (1 + E) of the nearest,
//                             at most 8 (SPANN query-aware pruning)
//   replicate_E[_rR]          store also at owners of centroids within (1 + E), at most R
//                             centroids (default 3; SPANN closure assignment)
//   lpt_cC                    C clusters per robot packed onto robots by LPT on expected load
//   lpt_cC_train              the same with loads from the training set's cluster sizes
//   bounded_cC_B              C clusters per robot, bounded loads (1 + B) x average
//   sample_cC                 C clusters per robot from k-means on the shared deployment sample
//                             (not the training set), packed by LPT on the sample's counts
//   balanced_cC               C clusters per robot from balanced (size-constrained) k-means on the
//                             training set, round robin (agents/balanced_kmeans.h)
//   balanced_sample_cC        balanced k-means on the shared deployment sample, packed by LPT on
//                             the sample's nearest-centroid counts
//   recluster_cC_pP           starts as lpt_cC_train; every P frames of each robot's stream the
//                             leader re-clusters (k = C n) a sample of the descriptors seen so far
//                             and the robots move what they no longer own (agents/recluster.h)
//   <table>+<routing>         a load-balanced table combined with probing or replication,
//                             e.g. lpt_c10+adaptive_probe_0.1
//
// Expected loads come from a sample shared at start: every kSampleStride-th deployment frame
// (about 5% of the sequence), nearest-centroid counts. The paper's table (round robin with the
// config's clusters_per_robot) is used when no table is named.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "agents/centroid_table.h"
#include "agents/load_balanced_table.h"
#include "agents/probe_routing.h"
#include "agents/routing.h"
#include "experiments/strategies/run_centroids.h"

namespace dvpr {

inline constexpr int kSampleStride = 20;

struct StrategySpec {
  enum class Table { kPaper, kLpt, kBounded, kSampleKMeans, kBalanced, kBalancedSample };
  enum class Routing { kNearest, kProbe, kReplicate };
  std::string name;
  Table table = Table::kPaper;
  int clusters_per_robot = 0;         // 0: the config's training.clusters_per_robot
  bool loads_from_training = false;   // else from the deployment sample
  LoadBalanceParams balance;
  Routing routing = Routing::kNearest;
  MultiProbeParams probe;
  ReplicationParams replicate;
  // > 0: adaptive re-clustering every this many frames of each robot's stream (recluster_cC_pP;
  // experiments/protocols/paper/static_recluster.h, agents/recluster_agent.h); the table above (lpt_cC_train)
  // is the one the team starts with.
  int recluster_period = 0;
};

// Every name the catalogue defines, in a fixed order (config registers them).
const std::vector<StrategySpec>& BeyondPaperStrategies();
std::vector<std::string> BeyondPaperStrategyNames();
// nullptr when `name` is not in the catalogue.
const StrategySpec* FindStrategySpec(std::string_view name);

// Every kSampleStride-th row of the deployment descriptors.
DescriptorMatrix DeploymentSample(const DescriptorMatrix& deployment);

// The table of run (robots, run): k-means as the paper protocol's (RunCentroids with the
// spec's clusters per robot), owners by the spec's table kind.
std::shared_ptr<const CentroidTable> BuildStrategyTable(const StrategySpec& spec, const DescriptorMatrix& training,
                                                        const DescriptorMatrix& deployment,
                                                        RunCentroidParams params, int robots, int run);

std::unique_ptr<RoutingStrategy> MakeSpecRouting(const StrategySpec& spec, std::shared_ptr<const CentroidTable> table);

}  // namespace dvpr
