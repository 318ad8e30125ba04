#pragma once
// Who can reach whom at a virtual time (issue 33's connectivity.csv, and tests): the graph of
// pairs that hear each other both ways, as the PropagationModel answers it, summarised. A
// pure question: it asks PropagationModel::Reach once per node (every other node a receiver)
// and changes nothing, so asking at any times in any order gives the same answers.
#include <vector>

#include "net_models/propagation/propagation_model.h"
#include "sim/sim_time.h"

namespace dvpr {

struct ConnectivitySnapshot {
  SimTime at;
  int pairs_in_range = 0;     // unordered pairs {a, b} with a hearing b and b hearing a
  int components = 0;         // connected components of that graph (an isolated node is one)
  int largest_component = 0;  // nodes in the largest
  double mean_hops = 0.0;     // mean shortest-path hops over connected ordered pairs; 0 when none
  int max_hops = 0;           // the longest of those shortest paths; 0 when none
  std::vector<int> in_range;  // per node: the nodes it and they hear both ways (its degree)

  bool connected() const { return components == 1; }
  bool operator==(const ConnectivitySnapshot&) const = default;
};

// The graph at `at` among nodes 0 .. nodes - 1 (nodes >= 1, else std::invalid_argument): one
// Reach per node, then a breadth-first search from each node, O(n (n + e)).
ConnectivitySnapshot ConnectivityAt(PropagationModel& propagation, int nodes, SimTime at);

// ConnectivityAt at 0, step, 2 step, ... up to and including `end` (step > 0 and end >= 0, else
// std::invalid_argument).
std::vector<ConnectivitySnapshot> ConnectivityOver(PropagationModel& propagation, int nodes, SimTime step,
                                                   SimTime end);

}  // namespace dvpr
