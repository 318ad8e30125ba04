#pragma once
// Place-recognition metrics as pure functions of an immutable log of query outcomes
// (docs/design.md section 2, restating the authors' evaluation code; implemented exactly):
//   rank the queries that have a match by score ascending (stable: equal scores keep the order
//   of the input); tp_k = 1 if ||P_query - P_match||^2 < r^2; TP, FP = cumulative sums of tp and
//   1 - tp; FN = R - TP; precision_k = TP/(TP+FP+1e-12); recall_k = TP/(TP+FN+1e-12);
//   AUC = sum over k >= 2 (1-based) of (recall_k - recall_{k-1}) * precision_k.
// A query without a match (no candidate) is not ranked, so it is neither TP nor FP, but it still
// counts in R when it is relevant. Note that the sum starts at k = 2: the step from recall 0 to
// recall_1 is not counted, so a perfect ranking of R relevant queries scores (R - 1)/R, not 1.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "agents/algorithms/ids.h"
#include "experiments/domain/data/dataset.h"
#include "experiments/domain/evaluation/ground_truth.h"

namespace dvpr {

// What one query got back: its best match and that match's score (squared L2 distance).
struct MatchOutcome {
  FrameId query;
  std::optional<FrameId> match;  // empty: no candidate (left out of the ranking)
  double score = 0;              // ignored when match is empty; must not be NaN otherwise
};

struct PrResult {
  std::vector<double> precision;  // one point per ranked query, in ranking order
  std::vector<double> recall;
  double auc = 0;
  std::int64_t relevant = 0;        // R
  std::int64_t ranked = 0;          // queries with a match
  std::int64_t true_positives = 0;  // TP at the end of the ranking
};

// The PR curve and AUC of `outcomes` (pass them in query order: ties in score keep it) with
// R = `relevant` given by the caller (e.g. CountRelevant, or the causal count of a simulation).
// Throws std::invalid_argument on a NaN score or a frame outside the positions.
PrResult EvaluatePr(std::span<const MatchOutcome> outcomes, const Positions& positions,
                    double radius_m, std::int64_t relevant);

// The same with R = CountRelevant(positions, params).
PrResult EvaluatePr(std::span<const MatchOutcome> outcomes, const Positions& positions,
                    const GroundTruthParams& params);

// sum over k >= 2 of (recall_k - recall_{k-1}) * precision_k; 0 for fewer than two points.
double PrAuc(std::span<const double> precision, std::span<const double> recall);

// auc / reference; NaN when the reference is 0.
double RelativeAuc(double auc, double reference);

// Frames routed to each robot 0..robots-1. Throws std::invalid_argument on a robot out of range.
std::vector<std::int64_t> CountPerRobot(std::span<const RobotId> routes, int robots);

// max over robots of count_r / (N / n), N = sum of the counts, n = number of robots (including
// robots that got nothing). 1 is perfect balance, n is everything on one robot. NaN if N = 0.
double WorstBalanceRatio(std::span<const std::int64_t> per_robot);

}  // namespace dvpr
