#pragma once
// The k largest entries of a score vector, the one tie rule of the selections: higher `score`,
// then higher `second` (when given), then the earlier index. Returns ascending indices.
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <span>
#include <vector>

namespace dvpr {

inline std::vector<std::size_t> TopIndices(std::span<const double> score, std::size_t k,
                                           std::span<const double> second = {}) {
  std::vector<std::size_t> order(score.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  k = std::min(k, order.size());
  const auto before = [&](std::size_t i, std::size_t j) {
    if (score[i] != score[j]) return score[i] > score[j];
    if (!second.empty() && second[i] != second[j]) return second[i] > second[j];
    return i < j;
  };
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(), before);
  order.resize(k);
  std::sort(order.begin(), order.end());
  return order;
}

}  // namespace dvpr
