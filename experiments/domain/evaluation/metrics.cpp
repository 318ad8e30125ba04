#include "experiments/domain/evaluation/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace dvpr {

namespace {

constexpr double kEpsilon = 1e-12;  // the authors' guard against 0/0

void CheckFrame(FrameId f, const Positions& positions) {
  if (f.value < 0 || f.value >= positions.rows()) {
    throw std::invalid_argument("EvaluatePr: frame " + std::to_string(f.value) + " outside [0, " +
                                std::to_string(positions.rows()) + ")");
  }
}

}  // namespace

PrResult EvaluatePr(std::span<const MatchOutcome> outcomes, const Positions& positions,
                    double radius_m, std::int64_t relevant) {
  if (relevant < 0) throw std::invalid_argument("EvaluatePr: relevant count < 0");
  std::vector<const MatchOutcome*> ranking;
  ranking.reserve(outcomes.size());
  for (const MatchOutcome& o : outcomes) {
    if (!o.match) continue;
    if (std::isnan(o.score)) {
      throw std::invalid_argument("EvaluatePr: NaN score for query " + std::to_string(o.query.value));
    }
    CheckFrame(o.query, positions);
    CheckFrame(*o.match, positions);
    ranking.push_back(&o);
  }
  std::stable_sort(ranking.begin(), ranking.end(),
                   [](const MatchOutcome* a, const MatchOutcome* b) { return a->score < b->score; });
  PrResult result;
  result.relevant = relevant;
  result.ranked = static_cast<std::int64_t>(ranking.size());
  result.precision.reserve(ranking.size());
  result.recall.reserve(ranking.size());
  const double r2 = radius_m * radius_m;
  double tp = 0;
  double fp = 0;
  for (const MatchOutcome* o : ranking) {
    const bool correct = (positions.row(o->query.value) - positions.row(o->match->value))
                             .squaredNorm() < r2;
    (correct ? tp : fp) += 1;
    const double fn = static_cast<double>(relevant) - tp;
    result.precision.push_back(tp / (tp + fp + kEpsilon));
    result.recall.push_back(tp / (tp + fn + kEpsilon));
  }
  result.true_positives = static_cast<std::int64_t>(tp);
  result.auc = PrAuc(result.precision, result.recall);
  return result;
}

PrResult EvaluatePr(std::span<const MatchOutcome> outcomes, const Positions& positions,
                    const GroundTruthParams& params) {
  return EvaluatePr(outcomes, positions, params.radius_m, CountRelevant(positions, params));
}

double PrAuc(std::span<const double> precision, std::span<const double> recall) {
  if (precision.size() != recall.size()) {
    throw std::invalid_argument("PrAuc: precision and recall differ in length");
  }
  double auc = 0;
  for (std::size_t k = 1; k < recall.size(); ++k) {
    auc += (recall[k] - recall[k - 1]) * precision[k];
  }
  return auc;
}

double RelativeAuc(double auc, double reference) {
  return reference == 0 ? std::numeric_limits<double>::quiet_NaN() : auc / reference;
}

std::vector<std::int64_t> CountPerRobot(std::span<const RobotId> routes, int robots) {
  if (robots < 1) throw std::invalid_argument("CountPerRobot: robots must be >= 1");
  std::vector<std::int64_t> counts(static_cast<std::size_t>(robots), 0);
  for (RobotId r : routes) {
    if (r.value < 0 || r.value >= robots) {
      throw std::invalid_argument("CountPerRobot: robot " + std::to_string(r.value) +
                                  " outside [0, " + std::to_string(robots) + ")");
    }
    ++counts[static_cast<std::size_t>(r.value)];
  }
  return counts;
}

double WorstBalanceRatio(std::span<const std::int64_t> per_robot) {
  const std::int64_t total = std::accumulate(per_robot.begin(), per_robot.end(), std::int64_t{0});
  if (per_robot.empty() || total == 0) return std::numeric_limits<double>::quiet_NaN();
  const std::int64_t worst = *std::max_element(per_robot.begin(), per_robot.end());
  return static_cast<double>(worst) /
         (static_cast<double>(total) / static_cast<double>(per_robot.size()));
}

}  // namespace dvpr
