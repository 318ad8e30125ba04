#pragma once
// The network variants' labels of hand-made rows, as DrawFigures gets them from a run's config
// (VariantLabels): each variant's label as its rows carry it.
#include <cstddef>
#include <vector>

#include "experiments/results/results.h"

namespace dvpr::testing_support {

inline std::vector<NetworkLabel> NetworkLabelsOf(const std::vector<RunResult>& rows) {
  std::vector<NetworkLabel> labels;
  for (const RunResult& r : rows) {
    if (r.key.network.model.empty()) continue;
    const auto v = static_cast<std::size_t>(r.key.network.variant);
    if (labels.size() <= v) labels.resize(v + 1);
    labels[v] = r.key.network;
  }
  return labels;
}

}  // namespace dvpr::testing_support
