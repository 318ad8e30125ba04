#pragma once
// The paper's static evaluation (docs/design.md section 2): the centralized AUC once, then for
// every robot count n and run: centroids (k-means with k = n x clusters_per_robot on the training
// set, or loaded from files), every frame routed to the owner of its nearest centroid, the
// decentralized AUC with each query's candidates restricted to frames routed to the same robot,
// relative AUC and the worst balance ratio. Ground truth (R) stays global.
//
// Seeding: run (n, run) clusters with seed RunSeed(config seed, n, run) =
// MixSeed(MixSeed(seed, n), run) (sim/random_bits.h), so a run's centroids depend only on
// its own key: adding robot counts or runs, or changing the thread count, changes nothing else.
//
// Speed: descriptor distances are computed once for all runs (WindowedNeighbours), so a run
// costs its k-means, one routing (N x k) and a few list look-ups per query. The sweep over n and
// runs is driven by experiments/sweep/run_sweep.h (RunSweep, as for every protocol), which runs
// RunPaperRun for each (n, run) in parallel; results do not depend on the number of threads.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "agents/algorithms/centroid_table.h"
#include "agents/algorithms/kmeans.h"
#include "experiments/domain/data/dataset.h"
#include "experiments/domain/evaluation/ground_truth.h"
#include "experiments/domain/evaluation/metrics.h"
#include "experiments/domain/evaluation/windowed_neighbours.h"
#include "experiments/domain/strategies/run_centroids.h"
#include "experiments/results/results.h"

namespace dvpr {

// One run's parameters. The run centroids' (seed, clusters per robot, k-means, centroid files)
// come from RunCentroidParams; centroid c is owned by robot c mod n.
struct PaperProtocolParams : RunCentroidParams {
  GroundTruthParams evaluation;         // r = 5 m, window 250
  // Non-empty: each run's centroids are written here as centroids_n{robots}_r{run}.npy.
  std::filesystem::path centroids_out_dir;
  bool keep_curves = false;             // keep the run's PR curve (figures)
  void Validate() const;                // throws std::invalid_argument naming the field
};

// Wall-clock seconds per stage (diagnostics, not deterministic). For a run: its own stages; for
// the evaluator: its precompute.
struct PaperTimings {
  double ground_truth_s = 0;   // g(i), R
  double distances_s = 0;      // D once + centralized matches, or routing + restricted matches
  double kmeans_s = 0;         // k-means (or loading the centroids)
  double metrics_s = 0;        // PR curve, AUC, balance
  double io_s = 0;             // writing centroids
};

struct PaperRunResult {
  // runs.csv row: key {protocol "paper", strategy "decentralized", robots, run}, seed (the
  // k-means seed; 0 when centroids were given), auc, auc_reference (centralized AUC),
  // relative_auc, worst_balance_ratio, queries = N (every frame is one query; the ranked ones
  // are in ranked_queries). Network fields stay not-applicable.
  RunResult row;
  std::vector<RobotLoadRow> per_robot;  // queries_received = stored = frames routed there;
                                        // comparisons = candidates those queries were compared to
  std::int64_t ranked_queries = 0;      // queries with a candidate in their pool
  std::int64_t fallback_scans = 0;      // queries the neighbour lists could not answer
  PrCurve curve;                        // filled when keep_curves
  PaperTimings timings;
};

// What does not change between runs: ground truth, R, the neighbour lists, the centralized
// result. Construct once per deployment; Evaluate is const and may run on several threads.
class PaperEvaluator {
 public:
  PaperEvaluator(const Dataset& deployment, const GroundTruthParams& evaluation,
                 int candidate_list_size = 64, int threads = 0);

  const PrResult& centralized() const { return centralized_; }
  std::int64_t relevant() const { return relevant_; }
  const PaperTimings& timings() const { return timings_; }
  // For evaluations of other routings (experiments/protocols/paper/static_strategies.h) over the same data.
  const Dataset& deployment() const { return deployment_; }
  const GroundTruthParams& evaluation() const { return evaluation_; }
  // evaluation().suppression_frames over the deployment (within each robot's frames for a plan).
  const FrameWindow& window() const { return window_; }
  const WindowedNeighbours& neighbours() const { return neighbours_; }

  // One routing: every frame goes to table.RouteOf(descriptor). Fills everything but the row's
  // run/seed and the centroids.
  PaperRunResult Evaluate(const CentroidTable& table, bool keep_curve) const;

  // The row and per-robot load of one evaluated routing, into `result`: key {"paper", strategy,
  // robots = searches.size()}, AUC against the centralized one, worst balance ratio = busiest
  // robot's searches / (N / n) (a routing that searches at m robots pays m times), queries = N,
  // per robot queries_received = searches, comparisons, stored; the curve when keep_curve.
  void FillResult(const std::string& strategy, PrResult pr, const std::vector<std::int64_t>& searches,
                  const std::vector<std::int64_t>& comparisons, const std::vector<std::int64_t>& stored,
                  bool keep_curve, PaperRunResult& result) const;

 private:
  std::vector<std::int64_t> Comparisons(const std::vector<RobotId>& routes, int robots) const;

  const Dataset& deployment_;
  GroundTruthParams evaluation_;
  FrameWindow window_;
  std::chrono::steady_clock::time_point build_start_;  // before neighbours_: times its build
  WindowedNeighbours neighbours_;
  std::int64_t relevant_ = 0;
  PrResult centralized_;
  PaperTimings timings_;
};

// The paper's method in run `run` on `table`, the run's paper table (BuildRunPlacement of
// `decentralized`, experiments/domain/strategies/run_placement.h): metrics, the row's run and seed (the
// k-means seed RunSeed(params.seed, n, run); 0 when centroids were given), centroids written
// if asked.
PaperRunResult EvaluatePaperRun(const PaperEvaluator& evaluator, const CentroidTable& table,
                                const PaperProtocolParams& params, int run);

// One (robots, run) of the sweep: the paper table (k-means on `training` or loaded), then
// EvaluatePaperRun.
PaperRunResult RunPaperRun(const PaperEvaluator& evaluator, const DescriptorMatrix& training,
                           const PaperProtocolParams& params, int robots, int run);

}  // namespace dvpr
