#pragma once
// What every figure shares so a reader learns it once: one colour per strategy (its place in
// runs.csv's order of appearance), one line style per network variant, the same terminal.
#include <cstddef>
#include <string>

namespace dvpr::figure_style {

inline constexpr const char* kStrategyColours[10] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                                     "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

// The colour of the i-th strategy of runs.csv.
inline std::string StrategyColour(std::size_t i) { return kStrategyColours[i % 10]; }

// gnuplot dash type and point type of the i-th network variant (variant index order).
inline int NetworkDash(std::size_t i) { return static_cast<int>(i % 5) + 1; }
inline int NetworkPoint(std::size_t i) {
  constexpr int kPoints[6] = {7, 5, 9, 11, 13, 15};
  return kPoints[i % 6];
}

// One colour per message role (results.h MessageRole order).
inline constexpr const char* kRoleColours[6] = {"#4c72b0", "#55a868", "#c44e52", "#8172b2", "#ccb974", "#999999"};

}  // namespace dvpr::figure_style
