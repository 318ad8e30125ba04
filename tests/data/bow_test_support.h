#pragma once
// What the bag-of-words data tests share.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <set>
#include <vector>

namespace dvpr::testing_support {

// How many distinct words two frames' word lists have in common.
inline std::size_t SharedWords(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b) {
  const std::set<std::int32_t> x(a.begin(), a.end()), y(b.begin(), b.end());
  return static_cast<std::size_t>(std::count_if(x.begin(), x.end(), [&](std::int32_t w) { return y.contains(w); }));
}

}  // namespace dvpr::testing_support
