#pragma once
// What the figures' tests share: a network variant's label, and the labels of hand-made rows as
// DrawFigures gets them from a run's config (VariantLabels): each variant's label as its rows carry it.
#include <cstddef>
#include <string>
#include <vector>

#include "experiments/results/results.h"

namespace dvpr::testing_support {

// A network variant of the figures' tests: `model` at `bps`, 2 ms, no loss.
inline NetworkLabel Net(int variant, const std::string& model, double bps) {
  return NetworkLabel{.variant = variant, .model = model, .bandwidth_bps = bps, .latency_ms = 2, .loss = "none"};
}

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
