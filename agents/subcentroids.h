#pragma once
// Sub-centroids of what one robot stores (issue 15): its rows split into groups, each with a
// centroid c and a radius r >= max ||x - c|| over its members, so the triangle inequality
// ||x - q|| >= ||q - c|| - r bounds every member's distance from below and whole groups can be
// skipped by an exact search. The bounds only select candidates; the search decides among them
// with its own arithmetic (agents/descriptor_index.h), so the grouping never changes a result,
// only how many rows are looked at.
//
// Groups come from a few Lloyd iterations over all rows, rebuilt when the store has doubled;
// rows added in between join their nearest centroid (which stays put) and widen its radius.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dvpr {

class SubCentroids {
 public:
  SubCentroids() = default;

  bool empty() const { return members_.empty(); }
  std::size_t groups() const { return members_.size(); }
  // Entry indices of group g, increasing.
  const std::vector<std::uint32_t>& members(std::size_t g) const { return members_[g]; }

  // Regroups rows [0, n) of the row-major n x dim buffer `data` into about sqrt(n) groups.
  void Rebuild(const float* data, std::size_t n, int dim);
  // Row `index` (dim floats at `row`) joins the nearest group; the bounds stay valid.
  void Add(const float* row, std::uint32_t index);
  void Clear();

  // Lower bounds on the exact squared distance from `query` to every member of each group
  // (one per group, into `out`). Conservative by the float error of ||q - c||^2.
  void LowerBounds(const float* query, float query_sq_norm, std::vector<double>& out) const;

 private:
  void AssignAll(const float* data, std::size_t n, std::vector<std::uint32_t>& group) const;
  void MoveCentroids(const float* data, const std::vector<std::uint32_t>& group);
  void UpdateNorms();
  std::size_t Nearest(const float* row) const;
  void Widen(std::size_t g, const float* row);

  int dim_ = 0;
  std::vector<float> centroids_;  // groups() x dim, row-major
  std::vector<float> centroid_norms_;
  float max_centroid_norm_ = 0.0f;
  std::vector<double> radius_;    // >= the exact largest member distance, rounded up
  std::vector<std::vector<std::uint32_t>> members_;
  mutable std::vector<float> scratch_;
};

}  // namespace dvpr
