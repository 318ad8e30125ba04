#pragma once
// Budgeted selection of candidate inter-robot edges, as Swarm-SLAM's broker does before it asks
// for verifications (cslam/algebraic_connectivity_maximization.py, its MAC solver
// cslam/third_party/mac/mac.py; Tian et al. RSS 2018, Doherty et al. ICRA 2022). Pure functions:
// the caller gathers the graph of the robots in reach and acts on the chosen indices.
//
// Ties: where Swarm-SLAM lets numpy's argpartition pick among equal values (any of them), we take
// the candidate earlier in `candidates` (the caller keeps them in the order they were found, as
// Swarm-SLAM's dict of candidates does).
#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <vector>

#include "agents/algorithms/ids.h"
#include "agents/sharing/keyframe_graph.h"

namespace dvpr {

// The pose graph a selection sees. Robot r's keyframes are 0..keyframes[r]-1, linked in order by
// odometry edges; the nodes are laid out robot after robot in increasing id (Swarm-SLAM's
// offsets). Swarm-SLAM counts a robot's keyframes as the largest keyframe id in any known edge
// plus one; the caller passes that count to reproduce it (later keyframes only hang a tail on the
// chain, which lowers the algebraic connectivity). Every edge joins two robots of `keyframes`.
struct SelectionGraph {
  std::map<RobotId, std::int32_t> keyframes;
  std::vector<KeyframeEdge> fixed;       // verified inter-robot edges
  std::vector<KeyframeEdge> candidates;  // weight: similarity, > -1

  // Throws std::invalid_argument naming the field (e.g. "candidates[2].b") of an edge whose
  // robot is not in `keyframes`, whose keyframe is out of its range, that joins a robot to
  // itself, or whose weight is not finite; or a negative keyframe count.
  void Validate() const;
};

struct MacParams {
  int max_iterations = 20;               // Swarm-SLAM's max_iters
  double duality_gap_tolerance = 1e-8;   // mac.py fw_subset's duality_gap_tol
  double fixed_weight = 1.0;             // weight of odometry and verified edges
  // Swarm-SLAM's connection-biased greedy picks one candidate for every robot without a verified
  // edge even when they are more than the budget; false stops at the budget.
  bool connection_picks_may_exceed_budget = false;
  void Validate() const;  // throws std::invalid_argument naming the field
};

// Which path SelectMac took.
enum class MacPath {
  kNothingToChoose,         // budget 0 or no candidate
  kAll,                     // budget >= candidates: all of them
  kConnectionBiasedGreedy,  // a robot has no verified edge yet
  kFrankWolfe,              // Frank-Wolfe ran and its iterate was rounded
  kDisconnectedStart,       // a disconnected Laplacian on the way: the greedy start returned
};

struct MacSelection {
  std::vector<std::size_t> chosen;  // indices into candidates, ascending
  MacPath path = MacPath::kNothingToChoose;
  int iterations = 0;               // Frank-Wolfe iterations run
  bool converged = false;           // stopped on the duality gap, not the iteration cap
};

// The min(budget, size) candidates of highest weight (ties: earlier first), ascending indices.
// Budget 0 chooses none: Swarm-SLAM's greedy start, asked for 0, takes all (numpy's [-0:]); we
// read the budget as "at most".
std::vector<std::size_t> SelectGreedy(std::span<const KeyframeEdge> candidates, int budget);

// min(budget, size) distinct candidates drawn uniformly (a partial Fisher-Yates shuffle on
// Xoshiro256(seed)), ascending indices: the same seed, the same choice.
std::vector<std::size_t> SelectRandom(std::span<const KeyframeEdge> candidates, int budget,
                                      std::uint64_t seed);

// Swarm-SLAM's connection_biased_greedy_selection: for each robot of graph.keyframes in
// increasing id that has no verified edge, its candidate of highest weight not yet picked (a
// picked one weighs 0 from then on and can be picked again, counting again, as there); then the
// greedy choice of the rest of the budget over those weights.
std::vector<std::size_t> SelectConnectionBiasedGreedy(const SelectionGraph& graph, int budget,
                                                      bool may_exceed_budget);

// Algebraic connectivity maximisation as Swarm-SLAM runs it, k = min(budget, candidates):
// - some robot of graph.keyframes without a verified edge: the connection-biased greedy choice;
// - otherwise Frank-Wolfe over w in [0,1]^m, sum w = k, maximising F(w) = lambda_2(L(w)), L(w)
//   the Laplacian of odometry and verified edges (fixed_weight each) plus candidate i with weight
//   w_i * similarity_i (w_i <= 1e-10 left out): from the greedy start, at iteration t the
//   gradient dF/dw_i = similarity_i (v_a - v_b)^2 of the unit Fiedler vector v, the direction s
//   the k largest gradients, the dual bound u = min(u, F + grad.(s - w)); stop when u - F < tol,
//   else w += 2/(t + 2) (s - w); at most max_iterations. The last w is rounded to its k largest
//   entries, compared at 10 decimals, ties by higher similarity, then earlier.
// - If L(w) is disconnected (lambda_2 = 0), we return the greedy start at once. Swarm-SLAM's
//   solver (networkx's TraceMIN with an LU of L whose largest-degree diagonal entry is set to
//   infinity, which makes only a connected Laplacian regular) then raises "singular" as its
//   comment on run_mac_solver says, and Swarm-SLAM retries from k - 1 starts with 1..k-1 random
//   picks (np.random) before it keeps the greedy start; the random retries are not mirrored, nor
//   the case where the LU of a disconnected L happens to succeed in floating point and its
//   Frank-Wolfe goes on with lambda_2 ~ 0. Since the first step is 1 (w becomes s), only the
//   start and the first direction can be disconnected; later iterates keep their support.
// The Fiedler pair comes from a dense eigensolver: O(N^3) time and O(N^2) memory per iteration
// for N keyframes in the graph (Swarm-SLAM's TraceMIN is sparse, iterative, to a residual of
// 1e-8, so its gradients differ from ours in the last digits); fine up to about a thousand
// keyframes, beyond that a sparse Lanczos solver would be the next step.
// Where lambda_2 is a multiple eigenvalue the gradient depends on which vector of its space the
// solver returns, as it does in Swarm-SLAM.
MacSelection SelectMac(const SelectionGraph& graph, int budget, const MacParams& params = {});

// lambda_2 of the Laplacian of odometry and verified edges (fixed_weight each) plus the chosen
// candidates (their similarity each): what SelectMac maximises; 0 for a disconnected graph.
double AlgebraicConnectivity(const SelectionGraph& graph, std::span<const std::size_t> chosen,
                             double fixed_weight = 1.0);

}  // namespace dvpr
