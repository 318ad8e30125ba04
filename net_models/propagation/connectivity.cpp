#include "net_models/propagation/connectivity.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "net_models/core/param_checks.h"

namespace dvpr {
namespace {

using Adjacency = std::vector<std::vector<int>>;

// Edges where both directions are heard: a link a relay can use whichever way a message goes.
Adjacency SymmetricGraph(PropagationModel& propagation, int nodes, SimTime at, int& pairs) {
  const auto n = static_cast<std::size_t>(nodes);
  std::vector<char> hears(n * n, 0);  // hears[a * n + b]: b hears what a sends
  const std::vector<std::vector<NodeId>> heard_by = HeardBy(propagation, nodes, at);
  for (std::size_t a = 0; a < n; ++a) {
    for (const NodeId b : heard_by[a]) hears[a * n + static_cast<std::size_t>(b.value)] = 1;
  }
  Adjacency adj(n);
  pairs = 0;
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      if (hears[a * n + b] && hears[b * n + a]) {
        adj[a].push_back(static_cast<int>(b));
        adj[b].push_back(static_cast<int>(a));
        ++pairs;
      }
    }
  }
  return adj;
}

}  // namespace

ConnectivitySnapshot ConnectivityAt(PropagationModel& propagation, int nodes, SimTime at) {
  if (nodes < 1) InvalidParam("nodes", "a network needs at least one node, got " + std::to_string(nodes));
  ConnectivitySnapshot s;
  s.at = at;
  const Adjacency adj = SymmetricGraph(propagation, nodes, at, s.pairs_in_range);
  const auto n = static_cast<std::size_t>(nodes);
  s.in_range.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.in_range[i] = static_cast<int>(adj[i].size());
  std::vector<int> component(n, -1);
  std::vector<int> dist(n);
  std::vector<int> queue;
  queue.reserve(n);
  long long hop_sum = 0;
  long long connected_pairs = 0;
  for (std::size_t src = 0; src < n; ++src) {
    std::fill(dist.begin(), dist.end(), -1);
    dist[src] = 0;
    queue.assign(1, static_cast<int>(src));
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const auto u = static_cast<std::size_t>(queue[head]);
      for (const int v : adj[u]) {
        if (dist[static_cast<std::size_t>(v)] >= 0) continue;
        dist[static_cast<std::size_t>(v)] = dist[u] + 1;
        queue.push_back(v);
      }
    }
    if (component[src] < 0) {  // the first node of a new component: its search found all of it
      for (const int v : queue) component[static_cast<std::size_t>(v)] = s.components;
      ++s.components;
      s.largest_component = std::max(s.largest_component, static_cast<int>(queue.size()));
    }
    for (std::size_t k = 1; k < queue.size(); ++k) {
      const int d = dist[static_cast<std::size_t>(queue[k])];
      hop_sum += d;
      s.max_hops = std::max(s.max_hops, d);
    }
    connected_pairs += static_cast<long long>(queue.size()) - 1;
  }
  s.mean_hops = connected_pairs > 0 ? static_cast<double>(hop_sum) / static_cast<double>(connected_pairs) : 0.0;
  return s;
}

std::vector<ConnectivitySnapshot> ConnectivityOver(PropagationModel& propagation, int nodes, SimTime step,
                                                   SimTime end) {
  if (step <= SimTime::Zero()) InvalidParam("step", "must be positive, got " + FormatDuration(step));
  CheckNonNegativeDuration("end", end);
  std::vector<ConnectivitySnapshot> out;
  for (SimTime t = SimTime::Zero(); t <= end; t += step) {
    out.push_back(ConnectivityAt(propagation, nodes, t));
    if (end - t < step) break;  // the next step would pass end (and t + step might overflow)
  }
  return out;
}

}  // namespace dvpr
