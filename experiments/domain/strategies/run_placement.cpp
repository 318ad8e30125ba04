#include "experiments/domain/strategies/run_placement.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "agents/algorithms/balanced_kmeans.h"
#include "agents/algorithms/frame_stream.h"
#include "agents/algorithms/kmeans.h"
#include "agents/algorithms/load_balanced_table.h"
#include "agents/placement/decentralized_placement.h"
#include "agents/placement/probe_placement.h"
#include "agents/recluster/recluster_placement.h"
#include "experiments/domain/data/split.h"
#include "experiments/domain/strategies/deployment_sample.h"

namespace dvpr {

namespace {

using Table = StrategySpec::Table;

int ClustersPerRobot(const StrategySpec& spec, const StrategyInputs& in) {
  return spec.clusters_per_robot > 0 ? spec.clusters_per_robot : in.centroids.clusters_per_robot;
}

// The run's k-means on the training set (or its centroid file), through the run's cache if any.
CentroidMatrix TrainingCentroids(const StrategySpec& spec, const StrategyInputs& in, int robots, int run) {
  RunCentroidParams params = in.centroids;
  params.clusters_per_robot = ClustersPerRobot(spec, in);
  if (in.cache != nullptr) return in.cache->Get(*in.training, params, robots, run);
  return RunCentroids(*in.training, params, robots, run);
}

// k-means settings of a table's own clustering, seeded as the run's k-means.
KMeansParams OwnKMeans(const StrategyInputs& in, int k, int robots, int run) {
  KMeansParams kmeans = in.centroids.kmeans;
  kmeans.k = k;
  kmeans.seed = RunSeed(in.centroids.seed, robots, run);
  return kmeans;
}

// sample_ and balanced_sample_: the clusters follow where the deployment actually is, so no
// cluster holds half the team's frames; the sample (shared at start) also gives the loads.
CentroidTable SampleTable(const StrategySpec& spec, const StrategyInputs& in, int robots, int run) {
  const DescriptorMatrix sample = DeploymentSample(*in.deployment);
  const KMeansParams kmeans =
      OwnKMeans(in, std::min<int>(robots * ClustersPerRobot(spec, in), static_cast<int>(sample.rows())), robots, run);
  CentroidMatrix centroids =
      spec.table == Table::kBalancedSample ? BalancedKMeans(sample, kmeans) : KMeans(sample, kmeans);
  return LoadBalancedTable(std::move(centroids), sample, robots, spec.balance);
}

CentroidTable BuildTable(const StrategySpec& spec, const StrategyInputs& in, int robots, int run) {
  switch (spec.table) {
    case Table::kPaper: return CentroidTable::RoundRobin(TrainingCentroids(spec, in, robots, run), robots);
    case Table::kSampleKMeans:
    case Table::kBalancedSample: return SampleTable(spec, in, robots, run);
    case Table::kBalanced:
      // Equal-size clusters of the training set: equal loads as far as the deployment looks like it.
      return CentroidTable::RoundRobin(
          BalancedKMeans(*in.training, OwnKMeans(in, robots * ClustersPerRobot(spec, in), robots, run)), robots);
    case Table::kLpt:
    case Table::kBounded: {
      const DescriptorMatrix loads = spec.loads_from_training ? *in.training : DeploymentSample(*in.deployment);
      return LoadBalancedTable(TrainingCentroids(spec, in, robots, run), loads, robots, spec.balance);
    }
  }
  throw std::logic_error("BuildRunPlacement: unknown table kind");
}

// recluster_cC_pP in run (robots, run); both protocols plan with these.
ReclusterParams ReclusterParamsOf(const StrategySpec& spec, const StrategyInputs& in, int robots, int run) {
  ReclusterParams p;
  p.clusters_per_robot = ClustersPerRobot(spec, in);
  p.period = spec.recluster_period;
  p.seed = RunSeed(in.centroids.seed, robots, run);
  p.Validate();
  return p;
}

// What the re-clustering team agrees on before the run (agents/recluster/recluster_placement.h). The leader
// waits half a period for the samples.
ReclusterPlan ReclusterPlanOf(const ReclusterParams& params, std::shared_ptr<const CentroidTable> initial,
                              const StrategyInputs& in, int robots) {
  if (in.plan != nullptr) throw std::invalid_argument("a re-clustering strategy needs the paper's split, not a team plan");
  ReclusterPlan plan;
  plan.params = params;
  plan.initial = std::move(initial);
  const SequenceSplit split = SplitSequence(static_cast<int>(in.deployment->rows()), robots);
  int longest = 0;
  for (const FrameRange& r : split.ranges) {
    plan.stream_first.push_back(r.begin);
    longest = std::max(longest, r.size());
  }
  plan.epochs = ReclusterEpochs(longest, plan.params);
  plan.sample_timeout = SimTime::Seconds(0.5 * plan.params.period / in.fps);
  return plan;
}

// The agent time of the team's last frame (the longest sub-sequence's, or a team plan's latest).
SimTime LastFrameTime(const StrategyInputs& in, int robots) {
  if (in.plan != nullptr) return in.plan->LastCapture(in.fps);
  return SplitSequence(static_cast<int>(in.deployment->rows()), robots).LastCapture(in.fps);
}

}  // namespace

TrainingUse TrainingUseOf(const StrategySpec& spec, const StrategyInputs& in) {
  TrainingUse use;
  if (spec.broadcast() || spec.bag_of_words()) return use;
  switch (spec.table) {
    case Table::kPaper: use.run_centroids = true; break;
    case Table::kSampleKMeans:
    case Table::kBalancedSample: return use;
    case Table::kBalanced: use.descriptors = true; break;
    case Table::kLpt:
    case Table::kBounded:
      use.run_centroids = true;
      use.descriptors = spec.loads_from_training;
      break;
  }
  use.clusters_per_robot = ClustersPerRobot(spec, in);
  return use;
}

namespace {

RunPlacement BowPlacement(const StrategySpec& spec, const StrategyInputs& in, int robots) {
  if (in.bow == nullptr || in.bow->empty()) {
    throw std::invalid_argument("strategy " + spec.name + ": the dataset has no bag-of-words vectors");
  }
  BowFamily f;
  if (spec.bow == StrategySpec::Bow::kModulo) {
    f.words = std::make_shared<const WordOwners>(WordOwners::Modulo(in.bow->vocabulary, robots));
  } else if (spec.bow == StrategySpec::Bow::kDocumentFrequency) {
    f.words = std::make_shared<const WordOwners>(
        WordOwners::ByDocumentFrequency(DocumentFrequency(in.bow->frames, in.bow->vocabulary), robots));
  }
  f.team = BowTeamPlan{robots, f.words};
  if (spec.bow == StrategySpec::Bow::kCentralized) {
    f.team.words = std::make_shared<const WordOwners>(WordOwners::Server(in.bow->vocabulary, robots, RobotId(0)));
  }
  return RunPlacement(std::move(f));
}

}  // namespace

const CentroidTable* RunPlacement::table() const {
  return Visit([](const BowFamily&) -> const CentroidTable* { return nullptr; },
               [](const auto& descriptor) -> const CentroidTable* { return descriptor.table.get(); });
}

RunPlacement BuildRunPlacement(const StrategySpec& spec, const StrategyInputs& in, int robots, int run) {
  if (spec.bag_of_words()) return BowPlacement(spec, in, robots);
  if (in.training == nullptr || in.deployment == nullptr) {
    throw std::invalid_argument("BuildRunPlacement: StrategyInputs needs the training and deployment descriptors");
  }
  std::shared_ptr<const CentroidTable> table;
  std::unique_ptr<PlacementStrategy> stateless;
  if (spec.broadcast()) {  // no table: every robot searches, each keeps its own frames
    stateless = std::make_unique<BroadcastPlacement>(robots);
  } else {
    table = std::make_shared<const CentroidTable>(BuildTable(spec, in, robots, run));
    if (spec.reclusters()) {
      if (in.failover.enabled) {
        throw std::invalid_argument("failover.enabled: '" + spec.name + "' re-clusters, which has no failover");
      }
      ReclusterFamily f;
      f.table = table;
      f.params = ReclusterParamsOf(spec, in, robots, run);
      f.team = std::make_unique<ReclusterPlacement>(ReclusterPlanOf(f.params, table, in, robots));
      return RunPlacement(std::move(f));
    }
    switch (spec.placement) {
      case StrategySpec::Placement::kNearest: stateless = std::make_unique<DecentralizedPlacement>(table); break;
      case StrategySpec::Placement::kProbe: stateless = std::make_unique<MultiProbePlacement>(table, spec.probe); break;
      case StrategySpec::Placement::kReplicate:
        stateless = std::make_unique<BoundaryReplicationPlacement>(table, spec.replicate);
        break;
      case StrategySpec::Placement::kBroadcast: throw std::logic_error("BuildRunPlacement: broadcast with a table");
    }
  }
  StatelessFamily f;
  f.table = std::move(table);
  f.strategy = stateless.get();
  if (in.failover.enabled) {
    auto team = std::make_unique<FailoverTeam>(std::move(stateless), f.table, in.failover, LastFrameTime(in, robots));
    f.failover = team.get();
    f.team = std::move(team);
  } else {
    f.team = std::move(stateless);
  }
  return RunPlacement(std::move(f));
}

}  // namespace dvpr
