#pragma once
// Ground truth of place recognition (docs/design.md section 2), from positions only. Frames are
// indexed in the full sequence; frame j is a candidate for query i only outside the suppression
// window, |i - j| > suppression_frames.
#include <cstdint>
#include <vector>

#include "experiments/data/dataset.h"

namespace dvpr {

struct GroundTruthParams {
  double radius_m = 5.0;        // r: a match is correct within r metres
  int suppression_frames = 250; // frames with |i - j| <= this are never candidates
  void Validate() const;        // throws std::invalid_argument "<field>: <problem>"
  bool operator==(const GroundTruthParams&) const = default;
};

// g(i) = min over |i - j| > window of ||P_i - P_j||^2; +inf when no frame is outside the window.
std::vector<double> NearestOutsideWindowSquared(const Positions& positions, int suppression_frames);

// relevant[i] = g(i) < r^2 (1 or 0).
std::vector<std::uint8_t> RelevantFlags(const Positions& positions, const GroundTruthParams& params);

// R: the number of relevant queries.
std::int64_t CountRelevant(const Positions& positions, const GroundTruthParams& params);

// Whether a reported match is correct: ||P_query - P_match||^2 < r^2.
bool IsCorrectMatch(const Positions& positions, std::int64_t query, std::int64_t match,
                    double radius_m);

}  // namespace dvpr
