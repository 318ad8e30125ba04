// Algebraic connectivity maximisation (candidate_selection.h): Laplacians on the keyframes laid
// out robot after robot, the Fiedler pair, and Frank-Wolfe as Swarm-SLAM's MAC solver runs it.
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <span>
#include <utility>
#include <vector>

#include "agents/sharing/candidate_selection.h"
#include "agents/sharing/top_indices.h"

namespace dvpr {
namespace {

// Below this a relaxed weight leaves its edge out of L(w) (mac.py combined_laplacian's tol).
constexpr double kEdgeOff = 1e-10;

// Node numbers: robot after robot in increasing id, keyframe order within a robot.
class KeyframeLayout {
 public:
  explicit KeyframeLayout(const SelectionGraph& g) {
    for (const auto& [robot, count] : g.keyframes) {
      offset_[robot] = size_;
      size_ += count;
    }
  }
  int Node(const KeyframeRef& k) const { return offset_.at(k.robot) + k.keyframe; }
  int size() const { return size_; }

 private:
  std::map<RobotId, int> offset_;
  int size_ = 0;
};

void AddEdge(Eigen::MatrixXd& laplacian, int i, int j, double w) {
  laplacian(i, i) += w;
  laplacian(j, j) += w;
  laplacian(i, j) -= w;
  laplacian(j, i) -= w;
}

// Odometry chains and verified edges, each fixed_weight.
Eigen::MatrixXd FixedLaplacian(const SelectionGraph& g, const KeyframeLayout& layout, double fixed_weight) {
  Eigen::MatrixXd laplacian = Eigen::MatrixXd::Zero(layout.size(), layout.size());
  for (const auto& [robot, count] : g.keyframes) {
    for (int k = 0; k + 1 < count; ++k) {
      const int node = layout.Node(KeyframeRef{robot, k});
      AddEdge(laplacian, node, node + 1, fixed_weight);
    }
  }
  for (const KeyframeEdge& e : g.fixed) AddEdge(laplacian, layout.Node(e.a), layout.Node(e.b), fixed_weight);
  return laplacian;
}

std::size_t Root(std::vector<std::size_t>& parent, std::size_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];  // path halving
    x = parent[x];
  }
  return x;
}

// Whether the graph of the Laplacian's off-diagonal entries is connected (union-find on the
// nonzero entries: exact, where a tolerance on lambda_2 would not be).
bool Connected(const Eigen::MatrixXd& laplacian) {
  const auto n = static_cast<std::size_t>(laplacian.rows());
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  std::size_t parts = n;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (laplacian(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) == 0.0) continue;
      const std::size_t a = Root(parent, i);
      const std::size_t b = Root(parent, j);
      if (a != b) {
        parent[a] = b;
        --parts;
      }
    }
  }
  return parts <= 1;
}

struct FiedlerPair {
  double value = 0.0;
  Eigen::VectorXd vector;  // unit norm
};

FiedlerPair Fiedler(const Eigen::MatrixXd& laplacian) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(laplacian);
  return FiedlerPair{solver.eigenvalues()(1), solver.eigenvectors().col(1)};
}

// The fixed Laplacian plus candidate i weighted by w[i] * similarity where w[i] > kEdgeOff.
class RelaxedLaplacian {
 public:
  RelaxedLaplacian(const SelectionGraph& g, double fixed_weight)
      : layout_(g), fixed_(FixedLaplacian(g, layout_, fixed_weight)) {
    for (const KeyframeEdge& e : g.candidates) {
      ends_.emplace_back(layout_.Node(e.a), layout_.Node(e.b));
      similarity_.push_back(e.weight);
    }
  }
  Eigen::MatrixXd At(const std::vector<double>& w) const {
    Eigen::MatrixXd laplacian = fixed_;
    for (std::size_t i = 0; i < w.size(); ++i) {
      if (w[i] > kEdgeOff) AddEdge(laplacian, ends_[i].first, ends_[i].second, w[i] * similarity_[i]);
    }
    return laplacian;
  }
  // dF/dw_i = similarity_i (v_a - v_b)^2 (Doherty et al., eq. 8).
  std::vector<double> Gradient(const Eigen::VectorXd& v) const {
    std::vector<double> grad(ends_.size());
    for (std::size_t i = 0; i < ends_.size(); ++i) {
      const double d = v(ends_[i].first) - v(ends_[i].second);
      grad[i] = similarity_[i] * d * d;
    }
    return grad;
  }
  const std::vector<double>& similarity() const { return similarity_; }
  bool Empty() const { return layout_.size() < 2; }

 private:
  KeyframeLayout layout_;
  Eigen::MatrixXd fixed_;
  std::vector<std::pair<int, int>> ends_;
  std::vector<double> similarity_;
};

std::vector<double> Indicator(std::size_t size, const std::vector<std::size_t>& chosen) {
  std::vector<double> w(size, 0.0);
  for (const std::size_t i : chosen) w[i] = 1.0;
  return w;
}

// mac.py round_solution_tiebreaker: the k largest of w at 10 decimals (numpy's round, half to
// even), ties by higher similarity, then earlier.
std::vector<std::size_t> RoundRelaxed(const std::vector<double>& w, const std::vector<double>& similarity,
                                      std::size_t k) {
  std::vector<double> rounded(w.size());
  for (std::size_t i = 0; i < w.size(); ++i) rounded[i] = std::nearbyint(w[i] * 1e10) / 1e10;
  return TopIndices(rounded, k, similarity);
}

MacSelection FrankWolfe(const RelaxedLaplacian& relaxed, std::vector<std::size_t> start, std::size_t k,
                        const MacParams& params) {
  MacSelection out;
  out.path = MacPath::kFrankWolfe;
  std::vector<double> w = Indicator(relaxed.similarity().size(), start);
  double bound = std::numeric_limits<double>::infinity();
  for (int it = 0; it < params.max_iterations; ++it) {
    const Eigen::MatrixXd laplacian = relaxed.At(w);
    if (!Connected(laplacian)) return MacSelection{std::move(start), MacPath::kDisconnectedStart, it, false};
    const FiedlerPair pair = Fiedler(laplacian);
    const std::vector<double> grad = relaxed.Gradient(pair.vector);
    const std::vector<double> s = Indicator(w.size(), TopIndices(grad, k));
    double slope = 0.0;
    for (std::size_t i = 0; i < w.size(); ++i) slope += grad[i] * (s[i] - w[i]);
    bound = std::min(bound, pair.value + slope);
    out.iterations = it + 1;
    if (bound - pair.value < params.duality_gap_tolerance) {
      out.converged = true;
      break;
    }
    const double alpha = 2.0 / (it + 2.0);
    for (std::size_t i = 0; i < w.size(); ++i) w[i] += alpha * (s[i] - w[i]);
  }
  out.chosen = RoundRelaxed(w, relaxed.similarity(), k);
  return out;
}

bool EveryRobotVerified(const SelectionGraph& graph) {
  std::set<RobotId> verified;
  for (const KeyframeEdge& e : graph.fixed) {
    verified.insert(e.a.robot);
    verified.insert(e.b.robot);
  }
  return std::all_of(graph.keyframes.begin(), graph.keyframes.end(),
                     [&](const auto& entry) { return verified.contains(entry.first); });
}

}  // namespace

MacSelection SelectMac(const SelectionGraph& graph, int budget, const MacParams& params) {
  graph.Validate();
  params.Validate();
  const std::size_t m = graph.candidates.size();
  const std::size_t k = std::min(budget > 0 ? static_cast<std::size_t>(budget) : std::size_t{0}, m);
  MacSelection out;
  if (k == 0) return out;
  if (!EveryRobotVerified(graph)) {
    out.chosen = SelectConnectionBiasedGreedy(graph, budget, params.connection_picks_may_exceed_budget);
    out.path = MacPath::kConnectionBiasedGreedy;
    return out;
  }
  if (k == m) {  // Frank-Wolfe over the one point of the feasible set would round to it too
    out.chosen.resize(m);
    std::iota(out.chosen.begin(), out.chosen.end(), std::size_t{0});
    out.path = MacPath::kAll;
    return out;
  }
  const RelaxedLaplacian relaxed(graph, params.fixed_weight);
  return FrankWolfe(relaxed, SelectGreedy(graph.candidates, static_cast<int>(k)), k, params);
}

double AlgebraicConnectivity(const SelectionGraph& graph, std::span<const std::size_t> chosen,
                             double fixed_weight) {
  graph.Validate();
  const RelaxedLaplacian relaxed(graph, fixed_weight);
  if (relaxed.Empty()) return 0.0;
  std::vector<double> w(graph.candidates.size(), 0.0);
  for (const std::size_t i : chosen) w.at(i) = 1.0;
  const Eigen::MatrixXd laplacian = relaxed.At(w);
  if (!Connected(laplacian)) return 0.0;
  return Fiedler(laplacian).value;
}

}  // namespace dvpr
