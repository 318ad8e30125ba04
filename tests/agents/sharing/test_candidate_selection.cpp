// Budgeted candidate selection: greedy, random, and algebraic connectivity maximisation on graphs
// whose Laplacian eigenvalues are worked out by hand (closed forms in each test's comment).
#include <cmath>
#include <cstdint>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agents/sharing/candidate_selection.h"

namespace dvpr {
namespace {

using Chosen = std::vector<std::size_t>;

KeyframeEdge Edge(int ra, int ka, int rb, int kb, double weight = 1.0) {
  return KeyframeEdge{KeyframeRef{RobotId(ra), ka}, KeyframeRef{RobotId(rb), kb}, weight};
}

std::vector<KeyframeEdge> Weighted(const std::vector<double>& weights) {
  std::vector<KeyframeEdge> out;
  for (std::size_t i = 0; i < weights.size(); ++i) out.push_back(Edge(0, static_cast<int>(i), 1, 0, weights[i]));
  return out;
}

TEST(SelectGreedy, TakesTheHighestWeightsEarlierFirstOnTies) {
  const std::vector<KeyframeEdge> c = Weighted({0.5, 0.9, 0.9, 0.7});
  EXPECT_EQ(SelectGreedy(c, 1), (Chosen{1}));
  EXPECT_EQ(SelectGreedy(c, 2), (Chosen{1, 2}));
  EXPECT_EQ(SelectGreedy(c, 3), (Chosen{1, 2, 3}));
  EXPECT_EQ(SelectGreedy(c, 4), (Chosen{0, 1, 2, 3}));
  EXPECT_EQ(SelectGreedy(c, 9), (Chosen{0, 1, 2, 3}));
  EXPECT_TRUE(SelectGreedy(c, 0).empty());
  EXPECT_TRUE(SelectGreedy({}, 3).empty());
}

TEST(SelectRandom, DrawsDistinctCandidatesTheSameForASeed) {
  const std::vector<KeyframeEdge> c = Weighted({0.1, 0.2, 0.3, 0.4, 0.5, 0.6});
  std::set<std::size_t> ever;
  std::set<Chosen> choices;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    const Chosen chosen = SelectRandom(c, 2, seed);
    ASSERT_EQ(chosen.size(), 2u);
    EXPECT_LT(chosen[0], chosen[1]);  // ascending, hence distinct
    EXPECT_LT(chosen[1], c.size());
    EXPECT_EQ(SelectRandom(c, 2, seed), chosen);
    ever.insert(chosen.begin(), chosen.end());
    choices.insert(chosen);
  }
  EXPECT_EQ(ever.size(), c.size());  // weights play no part: every candidate is drawn sometimes
  EXPECT_GT(choices.size(), 5u);
  EXPECT_TRUE(SelectRandom(c, 0, 1).empty());
  EXPECT_EQ(SelectRandom(c, 6, 1), (Chosen{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(SelectRandom(c, 7, 1), (Chosen{0, 1, 2, 3, 4, 5}));
}

// Two robots of two keyframes, the verified edge (0:1)-(1:0): the path P4, nodes 0 1 | 2 3.
// Candidates: c0 (0:1)-(1:0), similarity 1.0, a second link on the pair already linked; c1
// (0:0)-(1:1), similarity 0.9, closing the long loop 0-3.
// Reflection 0<->3, 1<->2 splits the Laplacian: symmetric vectors (a,b,b,a) see [[1,-1],[-1,1]]
// in every case here (eigenvalues 0, 2); antisymmetric ones (a,b,-b,-a):
//   nothing:   [[1,-1],[-1,3]]           lambda_2 = 2 - sqrt(2)  (= 2 - 2cos(pi/4), the path P4)
//   c0:        [[1,-1],[-1,5]]           lambda_2 = 3 - sqrt(5)                 ~ 0.7639
//   c1 (w):    [[1+2w,-1],[-1,3]]        lambda_2 = 2 + w - sqrt(w^2 - 2w + 2), w = 0.9:
//                                        2.9 - sqrt(1.01)                       ~ 1.8950
//   c0 and c1: [[2.8,-1],[-1,5]]         3.9 - sqrt(2.21) ~ 2.413 > 2: lambda_2 = 2
SelectionGraph LongLoopGraph() {
  SelectionGraph g;
  g.keyframes = {{RobotId(0), 2}, {RobotId(1), 2}};
  g.fixed = {Edge(0, 1, 1, 0)};
  g.candidates = {Edge(0, 1, 1, 0, 1.0), Edge(0, 0, 1, 1, 0.9)};
  return g;
}

TEST(AlgebraicConnectivity, MatchesTheHandWorkedEigenvalues) {
  const SelectionGraph g = LongLoopGraph();
  EXPECT_NEAR(AlgebraicConnectivity(g, Chosen{}), 2.0 - std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(AlgebraicConnectivity(g, Chosen{0}), 3.0 - std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(AlgebraicConnectivity(g, Chosen{1}), 2.9 - std::sqrt(1.01), 1e-12);
  EXPECT_NEAR(AlgebraicConnectivity(g, Chosen{0, 1}), 2.0, 1e-12);
}

// Path and cycle in closed form: P_n has lambda_2 = 2 - 2cos(pi/n), C_n 2 - 2cos(2pi/n). Two
// robots of 3 keyframes joined (0:2)-(1:0) make P6; the candidate (0:0)-(1:2) of similarity 1
// closes C6.
TEST(AlgebraicConnectivity, PathAndCycleInClosedForm) {
  SelectionGraph g;
  g.keyframes = {{RobotId(0), 3}, {RobotId(1), 3}};
  g.fixed = {Edge(0, 2, 1, 0)};
  g.candidates = {Edge(0, 0, 1, 2, 1.0)};
  EXPECT_NEAR(AlgebraicConnectivity(g, Chosen{}), 2.0 - 2.0 * std::cos(std::numbers::pi / 6), 1e-12);
  EXPECT_NEAR(AlgebraicConnectivity(g, Chosen{0}), 2.0 - 2.0 * std::cos(2.0 * std::numbers::pi / 6), 1e-12);
  // The fixed weight scales every fixed edge: 3 x P6's value.
  EXPECT_NEAR(AlgebraicConnectivity(g, Chosen{}, 3.0), 3.0 * (2.0 - std::sqrt(3.0)), 1e-12);
}

// Frank-Wolfe on LongLoopGraph, budget 1, by hand. Greedy start w = (1, 0): c0. Its Fiedler
// vector (a,b,-b,-a) has b = (1 - lambda) a = (sqrt(5) - 2) a ~ 0.236 a, so the gradient is
// c0: 1.0 (2b)^2 ~ 0.223 a^2, c1: 0.9 (2a)^2 = 3.6 a^2; s = c1, u = F + 3.377 a^2 > F, step
// 2/(0+2) = 1: w = (0, 1). There b = (2.8 - lambda) a ~ 0.905 a: c0 4b^2 ~ 3.276 a^2 < c1 3.6 a^2,
// so s = w, u = F and the gap closes at iteration 2: MAC takes c1 (lambda_2 ~ 1.895), where
// greedy takes c0 (~ 0.764).
TEST(SelectMac, ClosesTheLongLoopWhereGreedyTakesTheHigherSimilarity) {
  const SelectionGraph g = LongLoopGraph();
  EXPECT_EQ(SelectGreedy(g.candidates, 1), (Chosen{0}));
  const MacSelection mac = SelectMac(g, 1);
  EXPECT_EQ(mac.chosen, (Chosen{1}));
  EXPECT_EQ(mac.path, MacPath::kFrankWolfe);
  EXPECT_EQ(mac.iterations, 2);
  EXPECT_TRUE(mac.converged);
  EXPECT_GT(AlgebraicConnectivity(g, mac.chosen), AlgebraicConnectivity(g, Chosen{0}));
}

TEST(SelectMac, BudgetZeroChoosesNothingAndABudgetBeyondTheCandidatesAll) {
  const SelectionGraph g = LongLoopGraph();
  const MacSelection none = SelectMac(g, 0);
  EXPECT_TRUE(none.chosen.empty());
  EXPECT_EQ(none.path, MacPath::kNothingToChoose);
  EXPECT_EQ(SelectMac(g, 2).chosen, (Chosen{0, 1}));
  const MacSelection all = SelectMac(g, 5);
  EXPECT_EQ(all.chosen, (Chosen{0, 1}));
  EXPECT_EQ(all.path, MacPath::kAll);
  SelectionGraph empty = g;
  empty.candidates.clear();
  EXPECT_TRUE(SelectMac(empty, 3).chosen.empty());
}

// Three robots of two keyframes; only robots 0 and 1 have a verified edge. Candidates:
// c0 (0:0)-(1:1) 0.95, c1 (0:1)-(1:1) 0.9, c2 (1:1)-(2:0) 0.6, c3 (0:0)-(2:1) 0.5.
// Robot 2 has no verified edge, so Swarm-SLAM picks robot 2's best first (c2: 0.6 > 0.5), then
// the greedy rest: budget 2 gives {c0, c2}, where greedy alone gives {c0, c1}.
TEST(SelectMac, ARobotWithoutAVerifiedEdgeGetsItsBestCandidateFirst) {
  SelectionGraph g;
  g.keyframes = {{RobotId(0), 2}, {RobotId(1), 2}, {RobotId(2), 2}};
  g.fixed = {Edge(0, 1, 1, 0)};
  g.candidates = {Edge(0, 0, 1, 1, 0.95), Edge(0, 1, 1, 1, 0.9), Edge(1, 1, 2, 0, 0.6), Edge(0, 0, 2, 1, 0.5)};
  EXPECT_EQ(SelectGreedy(g.candidates, 2), (Chosen{0, 1}));
  const MacSelection mac = SelectMac(g, 2);
  EXPECT_EQ(mac.path, MacPath::kConnectionBiasedGreedy);
  EXPECT_EQ(mac.chosen, (Chosen{0, 2}));
  EXPECT_EQ(SelectMac(g, 1).chosen, (Chosen{2}));
  // No verified edge at all: robot 0 picks c0, robot 1 its best left (c1; c0 now weighs 0),
  // robot 2 c2: three picks; budget 2 stops after two unless Swarm-SLAM's overrun is asked for.
  g.fixed.clear();
  EXPECT_EQ(SelectMac(g, 2).chosen, (Chosen{0, 1}));
  MacParams overrun;
  overrun.connection_picks_may_exceed_budget = true;
  EXPECT_EQ(SelectMac(g, 2, overrun).chosen, (Chosen{0, 1, 2}));
}

// Four robots of one keyframe, verified edges 0-1 and 2-3 only: every robot has one, yet the
// fixed graph has two components (lambda_2 = 0). Candidates c0 (0:0)-(1:0) 0.95 (inside a
// component), c1 (1:0)-(2:0) 0.9 and c2 (3:0)-(0:0) 0.8 (bridges). Budget 1: the greedy start c0
// leaves L(w) disconnected, where networkx's solver fails and Swarm-SLAM ends with the greedy
// start; so do we, before any iteration. c1 instead makes the path 0-1-2-3 weighted (1, 0.9, 1):
// antisymmetric (a,b,-b,-a) sees [[1,-1],[-1,2.8]], lambda = 1.9 - sqrt(1.81) ~ 0.555 (the
// symmetric part gives 0 and 2).
TEST(SelectMac, ADisconnectedStartKeepsTheGreedyChoice) {
  SelectionGraph g;
  g.keyframes = {{RobotId(0), 1}, {RobotId(1), 1}, {RobotId(2), 1}, {RobotId(3), 1}};
  g.fixed = {Edge(0, 0, 1, 0), Edge(2, 0, 3, 0)};
  g.candidates = {Edge(0, 0, 1, 0, 0.95), Edge(1, 0, 2, 0, 0.9), Edge(3, 0, 0, 0, 0.8)};
  EXPECT_EQ(AlgebraicConnectivity(g, Chosen{}), 0.0);
  EXPECT_EQ(AlgebraicConnectivity(g, Chosen{0}), 0.0);
  EXPECT_NEAR(AlgebraicConnectivity(g, Chosen{1}), 1.9 - std::sqrt(1.81), 1e-12);
  const MacSelection mac = SelectMac(g, 1);
  EXPECT_EQ(mac.path, MacPath::kDisconnectedStart);
  EXPECT_EQ(mac.chosen, (Chosen{0}));
  EXPECT_EQ(mac.iterations, 0);
  EXPECT_FALSE(mac.converged);
}

TEST(SelectionGraph, ValidateNamesTheField) {
  SelectionGraph g = LongLoopGraph();
  g.candidates.push_back(Edge(0, 0, 2, 0, 0.5));
  try {
    g.Validate();
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("candidates[2].b"), std::string::npos) << e.what();
  }
  g = LongLoopGraph();
  g.fixed.push_back(Edge(0, 2, 1, 0));
  EXPECT_THROW(g.Validate(), std::invalid_argument);  // keyframe 2 of a robot of 2
  g = LongLoopGraph();
  g.candidates.push_back(Edge(1, 0, 1, 1, 0.5));
  EXPECT_THROW(g.Validate(), std::invalid_argument);  // a robot to itself
  MacParams p;
  p.max_iterations = 0;
  EXPECT_THROW(SelectMac(LongLoopGraph(), 1, p), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
