#include "experiments/protocols/paper/static_protocol.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "experiments/domain/data/npy.h"
#include "experiments/domain/strategies/run_placement.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/results/safe_output.h"

namespace dvpr {

namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void PaperProtocolParams::Validate() const {
  evaluation.Validate();
  if (clusters_per_robot < 1) {
    throw std::invalid_argument("PaperProtocolParams.clusters_per_robot must be >= 1");
  }
  KMeansParams probe = kmeans;
  probe.k = 1;  // set per run
  probe.Validate();
}

PaperEvaluator::PaperEvaluator(const Dataset& deployment, const GroundTruthParams& evaluation,
                               int candidate_list_size, int threads)
    : deployment_(deployment),
      evaluation_((evaluation.Validate(), evaluation)),
      window_(SuppressionWindow(deployment, evaluation.suppression_frames)),
      build_start_(std::chrono::steady_clock::now()),
      neighbours_(deployment.descriptors, window_, candidate_list_size,
                  threads) {
  if (deployment.trajectory.size() != deployment.size()) {
    throw std::invalid_argument("PaperEvaluator: " + std::to_string(deployment.trajectory.size()) +
                                " poses but " + std::to_string(deployment.size()) + " descriptors");
  }
  const double build_s = SecondsSince(build_start_);
  auto start = std::chrono::steady_clock::now();
  relevant_ = CountRelevant(deployment.trajectory.positions, evaluation_.radius_m, window_);
  timings_.ground_truth_s = SecondsSince(start);
  start = std::chrono::steady_clock::now();
  const std::vector<MatchOutcome> matches = neighbours_.BestMatches();
  timings_.distances_s = build_s + SecondsSince(start);
  start = std::chrono::steady_clock::now();
  centralized_ = EvaluatePr(matches, deployment.trajectory.positions, evaluation_.radius_m, relevant_);
  timings_.metrics_s = SecondsSince(start);
}

std::vector<std::int64_t> PaperEvaluator::Comparisons(const std::vector<RobotId>& routes,
                                                      int robots) const {
  std::vector<std::vector<std::int64_t>> members(static_cast<std::size_t>(robots));
  for (std::size_t i = 0; i < routes.size(); ++i) {
    members[static_cast<std::size_t>(routes[i].value)].push_back(static_cast<std::int64_t>(i));
  }
  std::vector<std::int64_t> comparisons(static_cast<std::size_t>(robots), 0);
  for (const auto& m : members) {
    for (std::int64_t i : m) {  // candidates of i: its robot's frames outside the window
      const FrameInterval w = window_.Around(i);
      const auto in_window = std::upper_bound(m.begin(), m.end(), w.hi) - std::lower_bound(m.begin(), m.end(), w.lo);
      comparisons[static_cast<std::size_t>(&m - members.data())] +=
          static_cast<std::int64_t>(m.size()) - in_window;
    }
  }
  return comparisons;
}

PaperRunResult PaperEvaluator::Evaluate(const CentroidTable& table, bool keep_curve) const {
  if (table.dim() != deployment_.dim()) {
    throw std::invalid_argument("PaperEvaluator: centroids have " + std::to_string(table.dim()) +
                                " dimensions, descriptors " + std::to_string(deployment_.dim()));
  }
  const int robots = table.num_robots();
  PaperRunResult result;
  auto start = std::chrono::steady_clock::now();
  const std::vector<RobotId> routes = table.RouteAll(deployment_.descriptors);
  const std::vector<MatchOutcome> matches = neighbours_.BestMatches(routes, &result.fallback_scans);
  result.timings.distances_s = SecondsSince(start);

  start = std::chrono::steady_clock::now();
  PrResult pr = EvaluatePr(matches, deployment_.trajectory.positions, evaluation_.radius_m, relevant_);
  const std::vector<std::int64_t> per_robot = CountPerRobot(routes, robots);
  const std::vector<std::int64_t> comparisons = Comparisons(routes, robots);
  FillResult("decentralized", std::move(pr), per_robot, comparisons, per_robot, keep_curve, result);
  result.timings.metrics_s = SecondsSince(start);
  return result;
}

void PaperEvaluator::FillResult(const std::string& strategy, PrResult pr, const std::vector<std::int64_t>& searches,
                                const std::vector<std::int64_t>& comparisons,
                                const std::vector<std::int64_t>& stored, bool keep_curve,
                                PaperRunResult& result) const {
  const int robots = static_cast<int>(searches.size());
  RunResult& row = result.row;
  row.key.protocol = kPaperProtocol;
  row.key.strategy = strategy;
  row.key.robots = robots;
  row.auc = pr.auc;
  row.auc_reference = centralized_.auc;
  row.relative_auc = RelativeAuc(pr.auc, centralized_.auc);
  const double fair_share = static_cast<double>(deployment_.size()) / robots;
  row.worst_balance_ratio = static_cast<double>(*std::max_element(searches.begin(), searches.end())) / fair_share;
  row.queries = deployment_.size();
  result.ranked_queries = pr.ranked;
  for (int r = 0; r < robots; ++r) {
    const auto ur = static_cast<std::size_t>(r);
    RobotLoadRow load;
    load.key = row.key;
    load.robot = r;
    load.queries_received = searches[ur];
    load.comparisons = comparisons[ur];
    load.stored = stored[ur];
    result.per_robot.push_back(std::move(load));
  }
  if (keep_curve) result.curve = PrCurve{strategy, robots, 0, std::move(pr.recall), std::move(pr.precision)};
}

PaperRunResult EvaluatePaperRun(const PaperEvaluator& evaluator, const CentroidTable& table,
                                const PaperProtocolParams& params, int run) {
  PaperRunResult result = evaluator.Evaluate(table, params.keep_curves);
  const int robots = table.num_robots();
  result.row.key.run = run;
  result.row.seed = params.centroids_pattern.empty() ? RunSeed(params.seed, robots, run) : 0;
  for (auto& r : result.per_robot) r.key.run = run;
  result.curve.run = run;
  if (!params.centroids_out_dir.empty()) {
    const auto start = std::chrono::steady_clock::now();
    WriteFileAtomic(params.centroids_out_dir / ("centroids_n" + std::to_string(robots) + "_r" + std::to_string(run) + ".npy"),
                    NpyBytes(table.centroids()));
    result.timings.io_s = SecondsSince(start);
  }
  return result;
}

PaperRunResult RunPaperRun(const PaperEvaluator& evaluator, const DescriptorMatrix& training,
                           const PaperProtocolParams& params, int robots, int run) {
  const auto start = std::chrono::steady_clock::now();
  StrategyInputs inputs;
  inputs.training = &training;
  inputs.deployment = &evaluator.deployment().descriptors;
  inputs.fps = evaluator.deployment().fps;
  inputs.centroids = static_cast<const RunCentroidParams&>(params);
  const RunPlacement paper = BuildRunPlacement(ParseStrategy("decentralized"), inputs, robots, run);
  const double kmeans_s = SecondsSince(start);
  PaperRunResult result = EvaluatePaperRun(evaluator, *paper.table(), params, run);
  result.timings.kmeans_s = kmeans_s;
  return result;
}

}  // namespace dvpr
