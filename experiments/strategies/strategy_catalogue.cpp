#include "experiments/strategies/strategy_catalogue.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "agents/balanced_kmeans.h"
#include "agents/decentralized_routing.h"
#include "agents/kmeans.h"

namespace dvpr {

namespace {

using Spec = StrategySpec;

// Routing parts: (name, how). Epsilons are on L2 distance (not squared), as SPANN's.
std::vector<Spec> RoutingParts() {
  std::vector<Spec> parts;
  const auto probe = [&](std::string name, int m, double eps) {
    Spec s;
    s.name = std::move(name);
    s.routing = Spec::Routing::kProbe;
    s.probe = {.probes = m, .epsilon = eps};
    parts.push_back(s);
  };
  const auto replicate = [&](std::string name, double eps, int replicas = 3) {
    Spec s;
    s.name = std::move(name);
    s.routing = Spec::Routing::kReplicate;
    s.replicate = {.epsilon = eps, .max_replicas = replicas};
    parts.push_back(s);
  };
  probe("multi_probe_2", 2, -1);
  probe("multi_probe_3", 3, -1);
  probe("adaptive_probe_0.05", 8, 0.05);
  probe("adaptive_probe_0.1", 8, 0.1);
  probe("adaptive_probe_0.2", 8, 0.2);
  replicate("replicate_0.05", 0.05);
  replicate("replicate_0.1", 0.1);
  replicate("replicate_0.2", 0.2);
  replicate("replicate_0.3", 0.3);
  replicate("replicate_0.5", 0.5);
  replicate("replicate_0.5_r5", 0.5, 5);
  replicate("replicate_1_r8", 1.0, 8);
  return parts;
}

// Table parts: (name, clusters per robot, how the owners are chosen).
std::vector<Spec> TableParts() {
  std::vector<Spec> parts;
  const auto table = [&](std::string name, Spec::Table kind, int c, double eps, bool training) {
    Spec s;
    s.name = std::move(name);
    s.table = kind;
    s.clusters_per_robot = c;
    s.balance.epsilon = eps;
    s.loads_from_training = training;
    parts.push_back(s);
  };
  table("lpt_c4", Spec::Table::kLpt, 4, -1, false);
  table("lpt_c10", Spec::Table::kLpt, 10, -1, false);
  table("lpt_c20", Spec::Table::kLpt, 20, -1, false);
  table("lpt_c10_train", Spec::Table::kLpt, 10, -1, true);
  table("bounded_c10_0.1", Spec::Table::kBounded, 10, 0.1, false);
  table("bounded_c10_0.25", Spec::Table::kBounded, 10, 0.25, false);
  table("sample_c2", Spec::Table::kSampleKMeans, 2, -1, false);
  table("sample_c4", Spec::Table::kSampleKMeans, 4, -1, false);
  table("balanced_c1", Spec::Table::kBalanced, 1, -1, false);
  table("balanced_c4", Spec::Table::kBalanced, 4, -1, false);
  table("balanced_sample_c1", Spec::Table::kBalancedSample, 1, -1, false);
  table("balanced_sample_c2", Spec::Table::kBalancedSample, 2, -1, false);
  table("balanced_sample_c4", Spec::Table::kBalancedSample, 4, -1, false);
  return parts;
}

// Adaptive re-clustering: (C, P). The team starts from lpt_cC_train's table (no deployment
// knowledge); no routing combinations (the agents route by their current table).
std::vector<Spec> ReclusterParts() {
  std::vector<Spec> parts;
  for (const auto& [c, p] : {std::pair{4, 50}, std::pair{4, 100}, std::pair{2, 50}}) {
    Spec s;
    s.name = "recluster_c" + std::to_string(c) + "_p" + std::to_string(p);
    s.table = Spec::Table::kLpt;
    s.clusters_per_robot = c;
    s.loads_from_training = true;
    s.recluster_period = p;
    parts.push_back(s);
  }
  return parts;
}

std::vector<Spec> BuildCatalogue() {
  std::vector<Spec> all = RoutingParts();
  const std::vector<Spec> tables = TableParts();
  all.insert(all.end(), tables.begin(), tables.end());
  for (const Spec& t : tables) {
    if (t.loads_from_training) continue;
    for (const Spec& r : RoutingParts()) {
      Spec s = t;
      s.name = t.name + "+" + r.name;
      s.routing = r.routing;
      s.probe = r.probe;
      s.replicate = r.replicate;
      all.push_back(s);
    }
  }
  const std::vector<Spec> recluster = ReclusterParts();
  all.insert(all.end(), recluster.begin(), recluster.end());
  return all;
}

}  // namespace

const std::vector<StrategySpec>& BeyondPaperStrategies() {
  static const std::vector<StrategySpec> all = BuildCatalogue();
  return all;
}

std::vector<std::string> BeyondPaperStrategyNames() {
  std::vector<std::string> names;
  for (const StrategySpec& s : BeyondPaperStrategies()) names.push_back(s.name);
  return names;
}

const StrategySpec* FindStrategySpec(std::string_view name) {
  for (const StrategySpec& s : BeyondPaperStrategies()) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

DescriptorMatrix DeploymentSample(const DescriptorMatrix& deployment) {
  const Eigen::Index rows = (deployment.rows() + kSampleStride - 1) / kSampleStride;
  DescriptorMatrix sample(rows, deployment.cols());
  for (Eigen::Index i = 0; i < rows; ++i) sample.row(i) = deployment.row(i * kSampleStride);
  return sample;
}

std::shared_ptr<const CentroidTable> BuildStrategyTable(const StrategySpec& spec, const DescriptorMatrix& training,
                                                        const DescriptorMatrix& deployment,
                                                        RunCentroidParams params, int robots, int run) {
  if (spec.clusters_per_robot > 0) params.clusters_per_robot = spec.clusters_per_robot;
  using Table = StrategySpec::Table;
  if (spec.table == Table::kSampleKMeans || spec.table == Table::kBalancedSample) {
    // The clusters follow where the deployment actually is, so no cluster holds half the team's
    // frames; the sample (shared at start) also gives the loads.
    const DescriptorMatrix sample = DeploymentSample(deployment);
    KMeansParams kmeans = params.kmeans;
    kmeans.k = std::min<int>(robots * params.clusters_per_robot, static_cast<int>(sample.rows()));
    kmeans.seed = RunSeed(params.seed, robots, run);
    CentroidMatrix centroids =
        spec.table == Table::kBalancedSample ? BalancedKMeans(sample, kmeans) : KMeans(sample, kmeans);
    return std::make_shared<const CentroidTable>(LoadBalancedTable(std::move(centroids), sample, robots, spec.balance));
  }
  if (spec.table == Table::kBalanced) {
    // Equal-size clusters of the training set, round robin: equal loads as far as the deployment
    // looks like the training set. Seeded as the paper's k-means of the run.
    KMeansParams kmeans = params.kmeans;
    kmeans.k = robots * params.clusters_per_robot;
    kmeans.seed = RunSeed(params.seed, robots, run);
    return std::make_shared<const CentroidTable>(CentroidTable::RoundRobin(BalancedKMeans(training, kmeans), robots));
  }
  CentroidMatrix centroids = RunCentroids(training, params, robots, run);
  if (spec.table == Table::kPaper) {
    return std::make_shared<const CentroidTable>(CentroidTable::RoundRobin(std::move(centroids), robots));
  }
  const DescriptorMatrix sample = spec.loads_from_training ? training : DeploymentSample(deployment);
  return std::make_shared<const CentroidTable>(
      LoadBalancedTable(std::move(centroids), sample, robots, spec.balance));
}

std::unique_ptr<RoutingStrategy> MakeSpecRouting(const StrategySpec& spec, std::shared_ptr<const CentroidTable> table) {
  switch (spec.routing) {
    case StrategySpec::Routing::kNearest: return std::make_unique<DecentralizedRouting>(std::move(table));
    case StrategySpec::Routing::kProbe: return std::make_unique<MultiProbeRouting>(std::move(table), spec.probe);
    case StrategySpec::Routing::kReplicate:
      return std::make_unique<BoundaryReplicationRouting>(std::move(table), spec.replicate);
  }
  throw std::logic_error("MakeSpecRouting: unknown routing kind");
}

}  // namespace dvpr
