#pragma once
// The one place a strategy becomes objects: BuildRunPlacement turns a StrategySpec
// (strategy_spec.h) into the centroid table and the routing of one run (robots, run). The paper
// protocol, the simulation and `dvpr agent` all call it, so a name means the same in each.
//
// Tables (docs/strategies.md): the paper's is k-means on the training set (RunCentroids, k = n x
// the config's clusters per robot) with centroid c owned by robot c mod n; lpt_ and bounded_
// cluster the same way with their own C and pack the clusters on expected loads (from the
// deployment sample, or the training set for _train); sample_ and balanced_sample_ cluster the
// deployment sample (seeded RunSeed as the run's k-means); balanced_ runs balanced k-means on the
// training set, round robin.
#include <memory>
#include <utility>
#include <variant>

#include "agents/algorithms/bow_words.h"
#include "agents/algorithms/centroid_table.h"
#include "agents/bow_robot_agent.h"
#include "agents/placement/agent_placement.h"
#include "agents/placement/failover_placement.h"
#include "agents/placement/placement.h"
#include "agents/recluster/recluster.h"
#include "experiments/domain/data/bow_data.h"
#include "experiments/domain/data/split.h"
#include "experiments/domain/strategies/run_centroids.h"
#include "experiments/domain/strategies/strategy_spec.h"

namespace dvpr {

// What the tables of every run are built from: the inputs the runs of a config share.
struct StrategyInputs {
  const DescriptorMatrix* training = nullptr;    // k-means' input (no rows when centroid files are given)
  const DescriptorMatrix* deployment = nullptr;  // sample tables' input; re-clustering splits its frames
  double fps = 10.0;                             // frames per second: the re-clustering leader's timeout
  const SequenceSplit* plan = nullptr;           // a planned team (Dataset::plan): its capture times
  RunCentroidParams centroids;                   // config seed, clusters per robot, centroid files
  RunCentroidCache* cache = nullptr;             // optional: k-means shared by the runs of a (robots, run)
  // enabled: every stateless strategy's team routes around lost robots (FailoverTeam); the
  // re-clustering strategies have no failover (BuildRunPlacement throws).
  FailoverParams failover;
  const BowData* bow = nullptr;                  // the deployment's BoW vectors: bow_ strategies' word owners
};

// One run's routing, by strategy family (docs/strategies.md). A strategy belongs to exactly one
// family, and what a protocol runs depends on the family alone, so callers visit it
// (RunPlacement::Visit): a family that a caller does not handle is a compile error, not a null
// pointer met at run time.

// The descriptor strategies that keep no per-robot state: broadcast, decentralized, multi_probe_,
// replicate_, on any table (sample_, lpt_, balanced_, ...).
struct StatelessFamily {
  std::shared_ptr<const CentroidTable> table;  // null for broadcast
  // What each robot's routing component is made from (TeamPlacement::MakeAgentPlacement): the
  // strategy itself, or the FailoverTeam around it.
  std::unique_ptr<TeamPlacement> team;
  // The strategy, owned by `team`: Route(self, descriptor) answers for every robot.
  const PlacementStrategy* strategy = nullptr;
  // `team` itself when it fails over (StrategyInputs::failover), null otherwise; real agents
  // tell it that their process announces the heartbeats (UseProcessHeartbeats).
  FailoverTeam* failover = nullptr;
};

// recluster_cC_pP: the team re-clusters its own frames during the run.
struct ReclusterFamily {
  std::shared_ptr<const CentroidTable> table;  // the start table
  // C, P, the sample stride, seed RunSeed(config seed, robots, run). The static protocol plans
  // the epochs from these and the start table.
  ReclusterParams params;
  std::unique_ptr<TeamPlacement> team;  // ReclusterPlacement: per-robot state, no failover
};

// bow_ strategies: a team of BoW agents (docs/bow.md); no centroid table.
struct BowFamily {
  // How the team (simulated or real) sends its queries: the distributed index as `words`;
  // bow_broadcast the whole vector to every robot (no owners); bow_centralized one server,
  // robot 0, that owns every word.
  BowTeamPlan team;
  // bow_decentralized*: which robot owns each word (modulo n, or LPT on the document frequencies
  // of the deployment's vectors, known before deployment like their idf); null for
  // bow_broadcast and bow_centralized, whose static evaluation is their reference's.
  std::shared_ptr<const WordOwners> words;
};

namespace detail {
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;
}  // namespace detail

class RunPlacement {
 public:
  using Family = std::variant<StatelessFamily, ReclusterFamily, BowFamily>;

  explicit RunPlacement(Family family) : family_(std::move(family)) {}

  // Calls the one of `handlers` that takes this run's family (a generic lambda may take several).
  template <class... F>
  decltype(auto) Visit(F&&... handlers) const {
    return std::visit(detail::Overloaded{std::forward<F>(handlers)...}, family_);
  }
  // The family, or null when the run's strategy is of another.
  template <class T>
  const T* As() const { return std::get_if<T>(&family_); }
  template <class T>
  T* As() { return std::get_if<T>(&family_); }

  // The centroid table of a descriptor strategy (the start table when re-clustering); null for
  // broadcast and the bow_ strategies.
  const CentroidTable* table() const;

 private:
  Family family_;
};

// What a strategy's table takes from the training side, so a sweep can check it before any run
// (experiments/sweep/sweep_checks.h): the run's centroids (k-means on the training set, or the
// run's centroid file) and/or the training descriptors themselves.
struct TrainingUse {
  int clusters_per_robot = 0;  // k = robots x this; 0 when neither is used
  bool run_centroids = false;  // RunCentroids (paper, lpt_, bounded_ tables)
  bool descriptors = false;    // k-means of its own on them (balanced_), or loads from them (_train)
};
TrainingUse TrainingUseOf(const StrategySpec& spec, const StrategyInputs& inputs);

// Throws std::invalid_argument when an input it needs is missing or the centroid files do not fit.
RunPlacement BuildRunPlacement(const StrategySpec& spec, const StrategyInputs& inputs, int robots, int run);

}  // namespace dvpr
