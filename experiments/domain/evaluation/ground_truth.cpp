#include "experiments/domain/evaluation/ground_truth.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dvpr {

void GroundTruthParams::Validate() const {
  if (!(radius_m > 0.0) || !std::isfinite(radius_m)) {
    throw std::invalid_argument("radius_m: must be finite and positive, got " + std::to_string(radius_m));
  }
  if (suppression_frames < 0) {
    throw std::invalid_argument("suppression_frames: must not be negative, got " +
                                std::to_string(suppression_frames));
  }
}

namespace {

// Calls fn(j) for every j outside the window of i: [0, lo) and (hi, N).
template <typename Fn>
void ForEachOutsideWindow(Eigen::Index n, const FrameInterval& window, Fn&& fn) {
  const Eigen::Index below = std::clamp<Eigen::Index>(window.lo, 0, n);  // j < below
  for (Eigen::Index j = 0; j < below; ++j) fn(j);
  for (Eigen::Index j = std::max<Eigen::Index>(window.hi + 1, 0); j < n; ++j) fn(j);
}

}  // namespace

std::vector<double> NearestOutsideWindowSquared(const Positions& positions, const FrameWindow& window) {
  GroundTruthParams{.radius_m = 1.0, .suppression_frames = window.frames()}.Validate();
  const Eigen::Index n = positions.rows();
  std::vector<double> g(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  for (Eigen::Index i = 0; i < n; ++i) {
    double best = std::numeric_limits<double>::infinity();
    ForEachOutsideWindow(n, window.Around(i),
                         [&](Eigen::Index j) { best = std::min(best, SquaredDistance(positions, i, j)); });
    g[static_cast<std::size_t>(i)] = best;
  }
  return g;
}

std::vector<std::uint8_t> RelevantFlags(const Positions& positions, const GroundTruthParams& params) {
  return RelevantFlags(positions, params.radius_m, FrameWindow(params.suppression_frames));
}

std::vector<std::uint8_t> RelevantFlags(const Positions& positions, double radius_m, const FrameWindow& window) {
  GroundTruthParams{.radius_m = radius_m, .suppression_frames = window.frames()}.Validate();
  const double r2 = radius_m * radius_m;
  const std::vector<double> g = NearestOutsideWindowSquared(positions, window);
  std::vector<std::uint8_t> relevant(g.size());
  std::transform(g.begin(), g.end(), relevant.begin(), [r2](double v) { return v < r2 ? 1 : 0; });
  return relevant;
}

std::int64_t CountRelevant(const Positions& positions, const GroundTruthParams& params) {
  return CountRelevant(positions, params.radius_m, FrameWindow(params.suppression_frames));
}

std::int64_t CountRelevant(const Positions& positions, double radius_m, const FrameWindow& window) {
  const auto flags = RelevantFlags(positions, radius_m, window);
  return std::count(flags.begin(), flags.end(), std::uint8_t{1});
}

bool IsCorrectMatch(const Positions& positions, std::int64_t query, std::int64_t match,
                    double radius_m) {
  const Eigen::Index n = positions.rows();
  if (query < 0 || query >= n || match < 0 || match >= n) {
    throw std::out_of_range("IsCorrectMatch: frame outside [0, " + std::to_string(n) + ")");
  }
  return SquaredDistance(positions, query, match) < radius_m * radius_m;
}

}  // namespace dvpr
