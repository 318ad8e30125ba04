#pragma once
// A routing strategy as a config names it, parsed into what it means (docs/strategies.md). The
// config parses every name when it is loaded, so a typo fails before any run; BuildRunPlacement
// (run_routing.h) turns a spec into a run's table and routing. Names carry their parameters, so
// a config lists what it compares and every name means one documented thing:
//
//   decentralized             the paper: the owner of the nearest centroid searches and stores
//   broadcast                 every robot searches every query, each keeps its own frames
//   multi_probe_M             search at the owners of the M nearest centroids (FAISS nprobe)
//   adaptive_probe_E          search at the owners of centroids within (1 + E) of the nearest,
//                             at most kAdaptiveProbes (SPANN query-aware pruning)
//   replicate_E[_rR]          store also at owners of centroids within (1 + E), at most R
//                             centroids (default kDefaultReplicas; SPANN closure assignment)
//   lpt_cC                    C clusters per robot packed onto robots by LPT on expected load
//   lpt_cC_train              the same with loads from the training set's cluster sizes
//   bounded_cC_B              C clusters per robot, bounded loads (1 + B) x average
//   sample_cC                 C clusters per robot from k-means on the shared deployment sample
//                             (not the training set), packed by LPT on the sample's counts
//   balanced_cC               C clusters per robot from balanced (size-constrained) k-means on the
//                             training set, round robin (agents/algorithms/balanced_kmeans.h)
//   balanced_sample_cC        balanced k-means on the shared deployment sample, packed by LPT on
//                             the sample's nearest-centroid counts
//   recluster_cC_pP           starts as lpt_cC_train; every P frames of each robot's stream the
//                             leader re-clusters (k = C n) a sample of the descriptors seen so far
//                             and the robots move what they no longer own (agents/recluster/recluster.h)
//   bow_centralized           bag-of-words reference: one index of every frame's tf-idf vector
//   bow_broadcast             the full BoW vector to every robot, each answers from its own frames
//   bow_decentralized         the distributed inverted index (Cieslewski and Scaramuzza, ICRA
//                             2017): word w owned by robot w mod n, partial queries, vote
//   bow_decentralized_df      the same with words packed onto robots by document frequency (LPT)
//   <table>+<routing>         a table above (lpt_, bounded_, sample_, balanced_) combined with a
//                             routing above (multi_probe_, adaptive_probe_, replicate_), e.g.
//                             lpt_c10+adaptive_probe_0.1
//
// C, M, R and P are whole numbers >= 1; E and B are numbers >= 0. Each number has one spelling,
// the shortest that reads back to it (0.1, not 0.10 or 1e-1; 4, not 04), so one strategy never
// appears under two names in the results. Epsilons are on L2 distance (not squared), as SPANN's.
// The paper's table (k-means on the training set, round robin, the config's clusters_per_robot)
// is used when no table is named.
#include <string>
#include <string_view>

#include "agents/algorithms/load_balanced_table.h"
#include "agents/placement/probe_placement.h"

namespace dvpr {

inline constexpr int kAdaptiveProbes = 8;
inline constexpr int kDefaultReplicas = 3;

struct StrategySpec {
  enum class Table { kPaper, kLpt, kBounded, kSampleKMeans, kBalanced, kBalancedSample };
  // Where a query goes (not the network's next hop: net_models/routing).
  enum class Placement { kBroadcast, kNearest, kProbe, kReplicate };
  std::string name;                   // as written in the config: the results' strategy column
  Table table = Table::kPaper;        // broadcast: none is used
  int clusters_per_robot = 0;         // 0: the config's training.clusters_per_robot
  bool loads_from_training = false;   // else from the deployment sample
  LoadBalanceParams balance;
  Placement placement = Placement::kNearest;
  MultiProbeParams probe;             // kProbe
  ReplicationParams replicate;        // kReplicate
  // > 0: adaptive re-clustering every this many frames of each robot's stream (recluster_cC_pP);
  // the table above (lpt_cC_train) is the one the team starts with.
  int recluster_period = 0;
  // Bag-of-words strategies (docs/bow.md): they use the dataset's BoW vectors, no table.
  enum class Bow { kNone, kCentralized, kBroadcast, kModulo, kDocumentFrequency };
  Bow bow = Bow::kNone;

  bool broadcast() const { return placement == Placement::kBroadcast; }
  bool reclusters() const { return recluster_period > 0; }
  bool bag_of_words() const { return bow != Bow::kNone; }
  // The paper's method itself (`decentralized`): its table, nearest owner, no re-clustering.
  bool paper_method() const {
    return table == Table::kPaper && placement == Placement::kNearest && !reclusters() && !bag_of_words();
  }
  bool operator==(const StrategySpec&) const = default;
};

// The spec a name stands for. Throws std::invalid_argument "'NAME' is not a strategy: REASON".
StrategySpec ParseStrategy(std::string_view name);

}  // namespace dvpr
