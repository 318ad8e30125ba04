#pragma once
// The lower-bound screen of a robot's store (IncrementalIndex) at one byte a value: every row
// kept again as 8-bit multiples of one power-of-two step, so a search that must read most of the
// store streams half the bytes of HalfScreen.
//
// Why: in the 10^6-frame x 1000-robot run every search reads a store that 999 other robots'
// searches have pushed out of the caches, and the screen's reads from memory were most of the
// search's time (docs/performance.md). The bound is HalfScreen's (agents/half_screen.h): the
// squared difference over a row's leading values, tested after 32 values, then every 16 and at
// dim, widened by the largest ||row - copy|| over the rows, measured exactly when a row is added
// (the triangle inequality), and by the float sum's rounding. The copy is coarser than a half
// (the step is 2^-7 for values within +-1), so the bound is a little looser: more rows reach the
// later checks, fewer bytes are read for each. Routing's centroid table (hot in cache) keeps
// HalfScreen.
//
// The step is fixed by the first row added: the smallest power of two that holds twice that
// row's largest magnitude in 127 steps. A later value beyond 127 steps is clipped; its error
// counts like any other (a looser bound, never a wrong one). A value that is not finite leaves
// the screen without a bound.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "agents/growable_array.h"

namespace dvpr {

class ByteScreen {
 public:
  static constexpr std::size_t kTileRows = 8;

  explicit ByteScreen(int dim);  // dim >= 0

  std::size_t size() const { return rows_; }
  // Where the bound is tested: numbers of leading values, ascending, the last one dim.
  const std::vector<int>& checks() const { return checks_; }
  // The copy's step (0 before the first row).
  float step() const { return step_; }

  void Append(const float* row);  // dim values
  void Clear();                   // also forgets the step

  // As HalfScreen::Limit: the largest float partial sum over the first checks()[k] values of a
  // row's copy that the row can have when its exact squared distance to the query is at most
  // `exact`. +inf when the screen has no bound.
  float Limit(double exact, std::size_t k) const;
  // As HalfScreen::Survivors: bit r set for each row first + r of the tile (first a multiple of 8)
  // that no check rules out. Rows past size() in the last tile are padding: ignore their bits.
  unsigned Survivors(std::size_t first, const float* query, const float* limits) const;

 private:
  std::vector<int> checks_;
  std::size_t rows_ = 0;
  float step_ = 0.0f;
  // Band k: tiles of 8 rows x (checks[k] - checks[k-1]) values, value-major, as multiples of step_.
  std::vector<GrowableArray<std::int8_t>> bands_;
  float error_ = 0.0f;  // the largest ||row - copy||, rounded up; +inf without a bound
};

}  // namespace dvpr
