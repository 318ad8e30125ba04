#pragma once
// Ground truth of place recognition (docs/design.md section 2), from positions only. Frames are
// indexed in the full sequence; frame j is a candidate for query i only outside the suppression
// window, |i - j| > suppression_frames (within i's own robot's frames for a team plan:
// agents/algorithms/frame_window.h).
#include <cstdint>
#include <vector>

#include "agents/algorithms/frame_window.h"
#include "experiments/domain/data/dataset.h"

namespace dvpr {

struct GroundTruthParams {
  double radius_m = 5.0;        // r: a match is correct within r metres
  int suppression_frames = 250; // frames with |i - j| <= this are never candidates
  void Validate() const;        // throws std::invalid_argument "<field>: <problem>"
  bool operator==(const GroundTruthParams&) const = default;
};

// g(i) = min over j outside i's window of ||P_i - P_j||^2; +inf when no frame is outside it.
// Squared distance between frames i and j of `p`.
inline double SquaredDistance(const Positions& p, Eigen::Index i, Eigen::Index j) {
  return (p.row(i) - p.row(j)).squaredNorm();
}

std::vector<double> NearestOutsideWindowSquared(const Positions& positions, const FrameWindow& window);

// relevant[i] = g(i) < r^2 (1 or 0): over the window of params (one stream, the paper's split), or
// over `window` (a team plan's: SuppressionWindow in experiments/domain/data/dataset.h).
std::vector<std::uint8_t> RelevantFlags(const Positions& positions, const GroundTruthParams& params);
std::vector<std::uint8_t> RelevantFlags(const Positions& positions, double radius_m, const FrameWindow& window);

// R: the number of relevant queries.
std::int64_t CountRelevant(const Positions& positions, const GroundTruthParams& params);
std::int64_t CountRelevant(const Positions& positions, double radius_m, const FrameWindow& window);

// Whether a reported match is correct: ||P_query - P_match||^2 < r^2.
bool IsCorrectMatch(const Positions& positions, std::int64_t query, std::int64_t match,
                    double radius_m);

}  // namespace dvpr
