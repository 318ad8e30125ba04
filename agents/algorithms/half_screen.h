#pragma once
// A lower-bound screen for exact nearest-neighbour search: every row kept a second time in half
// precision, so a search can rule most rows out from a few of their leading values, streaming
// 2 bytes a value, and compute exact distances only for the rest.
//
// The squared difference over a row's leading values is a lower bound of its distance (the
// descriptors' variance sits in the leading dimensions, as after PCA). The half-precision copy
// differs from the row by at most the row's rounding error, measured exactly when the row is
// added, which widens the bound by the triangle inequality; the float sum's own rounding widens it
// again. The bound is tested after the first 32 values, then every 16, and at dim. Rows sit in
// tiles of 8, value-major, one band of tiles a check (values [checks[k - 1], checks[k])), so 8
// rows' partial sums are one vector and a search that stops early does not stream what it skips.
// Used by IncrementalIndex (a robot's store) and CentroidTable (routing). docs/performance.md.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dvpr {

class HalfScreen {
 public:
  static constexpr std::size_t kTileRows = 8;

  explicit HalfScreen(int dim);  // dim >= 0

  std::size_t size() const { return rows_; }
  // Where the bound is tested: numbers of leading values, ascending, the last one dim.
  const std::vector<int>& checks() const { return checks_; }

  void Append(const float* row);  // dim values
  void Clear();

  // The largest float partial sum over the first checks()[k] values of a row's copy that the
  // row can have when its exact squared distance to the query is at most `exact`: prune a row
  // whose partial sum is above it. +inf when a stored value has no finite half.
  float Limit(double exact, std::size_t k) const;

  // The tile of rows [first, first + 8) (first a multiple of 8): bit r set for each row first + r
  // that no check rules out, given the limit of each check. A NaN partial sum rules nothing out.
  // The rows past size() in the last tile are padding (zeros): the caller ignores their bits.
  unsigned Survivors(std::size_t first, const float* query, const float* limits) const;
  // The same, with the tile's partial sums over the first band already known (`first_sums`, from
  // FirstBandSums): the first band is not read again.
  unsigned Survivors(std::size_t first, const float* query, const float* limits, const float* first_sums) const;
  // The tile's 8 partial sums over the first checks()[0] values.
  void FirstBandSums(std::size_t first, const float* query, float* sums) const;

 private:
  unsigned SurvivorsFrom(std::size_t first, const float* query, const float* limits, std::size_t band,
                         const float* sums) const;

  std::vector<int> checks_;
  std::size_t rows_ = 0;
  // Band k: tiles of 8 rows x (checks[k] - checks[k-1]) values, as IEEE binary16 bits (not
  // _Float16, which clang 14 does not have on x86).
  std::vector<std::vector<std::uint16_t>> bands_;
  // The largest ||row - half(row)|| over the rows, rounded up; +inf if a value has no finite half.
  float error_ = 0.0f;
};

}  // namespace dvpr
