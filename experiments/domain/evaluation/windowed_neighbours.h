#pragma once
// Exact best matches of the static protocol (docs/design.md section 2), for every query at once and
// for any restriction of the candidate pool, fast enough to evaluate hundreds of routings of the
// same sequence.
//
// The squared distances D (N x N, float GEMM) are computed once, in blocks of rows. Instead of
// keeping D, each query keeps its `list_size` nearest candidates outside the suppression window,
// re-measured in double and sorted by (distance, frame), plus a bound below which that list is
// known to be complete. A restricted best match is then the first list entry in the pool (a few
// steps), and only when the list cannot prove it does the query fall back to scanning its pool.
// Results equal argmin_j D[i, j] in exact arithmetic with ties to the lowest frame (numpy.argmin);
// list_size changes only the speed.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "agents/algorithms/descriptors.h"
#include "agents/algorithms/frame_window.h"
#include "agents/algorithms/ids.h"
#include "experiments/domain/evaluation/metrics.h"

namespace dvpr {

class WindowedNeighbours {
 public:
  // Keeps a reference to `descriptors` (N x d), which must outlive this object.
  WindowedNeighbours(const DescriptorMatrix& descriptors, const FrameWindow& window, int list_size,
                     int threads);

  std::int64_t size() const { return n_; }

  // Best match of every query (in frame order) among all frames outside its window.
  std::vector<MatchOutcome> BestMatches() const;

  // Best match of every query among the frames outside its window with the same pool label
  // (pool[j] == pool[i], e.g. the robot owning the nearest centroid). Queries without any such
  // frame get no match. `fallbacks`, if given, receives the number of queries the list could not
  // answer (diagnostics).
  std::vector<MatchOutcome> BestMatches(std::span<const RobotId> pool,
                                        std::int64_t* fallbacks = nullptr) const;

  // Best match of every query i among the frames j outside its window with candidate(i, j):
  // pools generalised to routings where a frame is stored at several robots or a query searched
  // at several (j is a candidate of i when j is stored where i is searched). Same results as a
  // full scan; a query the list cannot answer scans every frame.
  using CandidateTest = std::function<bool(std::int64_t query, std::int64_t frame)>;
  std::vector<MatchOutcome> BestMatchesWhere(const CandidateTest& candidate,
                                             std::int64_t* fallbacks = nullptr) const;

 private:
  void BuildRows(const Eigen::VectorXf& norms, std::int64_t first, std::int64_t count);
  MatchOutcome Scan(std::int64_t i, const std::vector<std::int32_t>& members) const;

  const DescriptorMatrix& x_;
  std::int64_t n_;
  FrameWindow window_;
  int list_size_;
  std::vector<std::int32_t> frame_;   // n x list_size, row i = query i's nearest, sorted
  std::vector<double> distance_;      // exact squared distances of frame_
  std::vector<std::int32_t> length_;  // entries of row i actually used
  std::vector<double> complete_below_;  // no frame outside the list is nearer than this
};

}  // namespace dvpr
