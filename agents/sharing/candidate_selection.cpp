#include "agents/sharing/candidate_selection.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "agents/sharing/top_indices.h"
#include "sim/random_bits.h"

namespace dvpr {
namespace {

void CheckEnd(const SelectionGraph& g, const KeyframeRef& k, const std::string& field) {
  const auto it = g.keyframes.find(k.robot);
  if (it == g.keyframes.end()) {
    throw std::invalid_argument("SelectionGraph." + field + ": robot " + std::to_string(k.robot.value) +
                                " has no entry in keyframes");
  }
  if (k.keyframe < 0 || k.keyframe >= it->second) {
    throw std::invalid_argument("SelectionGraph." + field + ": keyframe " + std::to_string(k.keyframe) +
                                " outside robot " + std::to_string(k.robot.value) + "'s 0.." +
                                std::to_string(it->second - 1));
  }
}

void CheckEdges(const SelectionGraph& g, const std::vector<KeyframeEdge>& edges, const std::string& name) {
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const std::string field = name + "[" + std::to_string(i) + "]";
    CheckEnd(g, edges[i].a, field + ".a");
    CheckEnd(g, edges[i].b, field + ".b");
    if (edges[i].a.robot == edges[i].b.robot) {
      throw std::invalid_argument("SelectionGraph." + field + ": joins robot " +
                                  std::to_string(edges[i].a.robot.value) + " to itself");
    }
    if (!std::isfinite(edges[i].weight)) {
      throw std::invalid_argument("SelectionGraph." + field + ".weight: not finite");
    }
  }
}

std::vector<double> WeightsOf(std::span<const KeyframeEdge> candidates) {
  std::vector<double> w;
  w.reserve(candidates.size());
  for (const KeyframeEdge& e : candidates) w.push_back(e.weight);
  return w;
}

std::size_t BudgetOf(int budget) { return budget > 0 ? static_cast<std::size_t>(budget) : 0; }

}  // namespace

void SelectionGraph::Validate() const {
  for (const auto& [robot, count] : keyframes) {
    if (count < 0) {
      throw std::invalid_argument("SelectionGraph.keyframes[" + std::to_string(robot.value) + "]: " +
                                  std::to_string(count) + " keyframes");
    }
  }
  CheckEdges(*this, fixed, "fixed");
  CheckEdges(*this, candidates, "candidates");
}

void MacParams::Validate() const {
  if (max_iterations < 1) throw std::invalid_argument("MacParams.max_iterations: at least 1");
  if (!(duality_gap_tolerance >= 0)) throw std::invalid_argument("MacParams.duality_gap_tolerance: >= 0");
  if (!(fixed_weight > 0) || !std::isfinite(fixed_weight)) {
    throw std::invalid_argument("MacParams.fixed_weight: a finite weight > 0");
  }
}

std::vector<std::size_t> SelectGreedy(std::span<const KeyframeEdge> candidates, int budget) {
  const std::vector<double> w = WeightsOf(candidates);
  return TopIndices(w, BudgetOf(budget));
}

std::vector<std::size_t> SelectRandom(std::span<const KeyframeEdge> candidates, int budget,
                                      std::uint64_t seed) {
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const std::size_t k = std::min(BudgetOf(budget), order.size());
  Xoshiro256 rng(seed);
  for (std::size_t i = 0; i < k; ++i) {
    const std::size_t j = i + static_cast<std::size_t>(rng.Below(order.size() - i));
    std::swap(order[i], order[j]);
  }
  order.resize(k);
  std::sort(order.begin(), order.end());
  return order;
}

std::vector<std::size_t> SelectConnectionBiasedGreedy(const SelectionGraph& graph, int budget,
                                                      bool may_exceed_budget) {
  graph.Validate();
  const std::size_t k = std::min(BudgetOf(budget), graph.candidates.size());
  std::set<RobotId> verified;
  for (const KeyframeEdge& e : graph.fixed) {
    verified.insert(e.a.robot);
    verified.insert(e.b.robot);
  }
  std::vector<double> w = WeightsOf(graph.candidates);
  std::set<std::size_t> chosen;
  std::size_t picks = 0;  // counts a repeated pick again, as Swarm-SLAM's counter does
  for (const auto& [robot, count] : graph.keyframes) {
    if (verified.contains(robot)) continue;
    if (!may_exceed_budget && picks >= k) break;
    double best_weight = -1.0;  // Swarm-SLAM's start: a candidate must weigh more than -1
    std::size_t best = w.size();
    for (std::size_t i = 0; i < w.size(); ++i) {
      const KeyframeEdge& e = graph.candidates[i];
      if ((e.a.robot == robot || e.b.robot == robot) && w[i] > best_weight) {
        best_weight = w[i];
        best = i;
      }
    }
    if (best == w.size()) continue;
    chosen.insert(best);
    w[best] = 0.0;
    ++picks;
  }
  if (k > picks) {
    for (const std::size_t i : TopIndices(w, k - picks)) chosen.insert(i);
  }
  return {chosen.begin(), chosen.end()};
}

}  // namespace dvpr
