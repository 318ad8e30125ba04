#pragma once
// connectivity.csv (outputs.connectivity, docs/network_model.md "Connectivity"): who reaches
// whom at every frame period of a simulated run on a radio variant, one row per step, and the
// two numbers summary.json gives per group from them. Plain rows as results.h; the simulation
// fills them from net_models' ConnectivityOver.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "experiments/results/results.h"

namespace dvpr {

// One row of connectivity.csv: the graph of pairs that hear each other both ways at one time.
struct ConnectivityRow {
  RunKey key;
  std::int64_t time_ns = 0;         // written as time_s
  int pairs_in_range = 0;           // unordered pairs
  int components = 0;               // an isolated robot is one
  int largest_component = 0;        // robots in the largest
  double mean_hops = 0.0;           // shortest-path hops over connected ordered pairs; 0 when none
  int max_hops = 0;                 // 0 when none
  std::vector<int> robots_in_range;  // per robot, robot 0 first: the teammates in range both ways
};

extern const char* const kConnectivityHeader;
std::string CsvRow(const ConnectivityRow& r);

// What summary.json says of one run's connectivity (its rows, all with the same key).
struct RunConnectivity {
  RunKey key;
  // Share of the steps at which the team is one network (components == 1).
  double connected_time_share = kNotApplicable;
  // Mean of mean_hops over the steps at which at least one pair is in range: how many hops a
  // message between robots that can reach each other takes, while any can. NaN when no step has
  // a pair in range (summary.json: null).
  double connected_pair_mean_hops = kNotApplicable;
};
// The rows of one run (a key with no row gives NaNs); the key is the first row's.
RunConnectivity SummarizeConnectivity(std::span<const ConnectivityRow> rows);
// A run output's rows (runs one after another, each run's rows together) summarised run by run,
// appended to `out` in their order.
void SummarizeConnectivityRuns(std::span<const ConnectivityRow> rows, std::vector<RunConnectivity>& out);

}  // namespace dvpr
