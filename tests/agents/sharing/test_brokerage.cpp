// Brokerage of verification data: which keyframes' features are sent for the selected edges.
// Expected covers worked by hand below each example.
#include <cstdint>
#include <set>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "agents/sharing/brokerage.h"
#include "sim/random_bits.h"

namespace dvpr {
namespace {

KeyframeRef K(int robot, int keyframe) { return KeyframeRef{RobotId(robot), keyframe}; }
KeyframeEdge E(KeyframeRef a, KeyframeRef b) { return KeyframeEdge{a, b, 1.0}; }

bool Covers(const std::vector<KeyframeRef>& sent, const std::vector<KeyframeEdge>& edges) {
  const std::set<KeyframeRef> s(sent.begin(), sent.end());
  for (const KeyframeEdge& e : edges) {
    if (!s.contains(e.a) && !s.contains(e.b)) return false;
  }
  return true;
}

// Robots A = 0 and B = 1, two components:
//   star:  A0-B0, A0-B1, A0-B2, A1-B0, A2-B0. A1 and A2 reach only B0, so a matching holds at
//          most one of them, plus A0: maximum matching 2 (A0-B1, A1-B0). A cover of 2 must take
//          B0 (or both A1, A2) and A0 (or both B1, B2): {A0, B0}, the only one.
//   path:  A3-B3-A4-B4-A5 (4 edges, 5 keyframes): maximum matching 2 (A3-B3, A4-B4); the only
//          cover of 2 is {B3, B4} (A3-B3 needs A3 or B3, B4-A5 needs B4 or A5, and the middle
//          edges rule out the other three pairs).
// König: minimum cover = maximum matching = 2 + 2 = 4. An edge to robot C = 2, not involved, is
// left out (else A0 or C0 would be needed for it, which here A0 already is; C0 must not appear).
TEST(VertexCoverBrokerage, TwoRobotsGiveTheMinimumCoverOfKonigsTheorem) {
  const std::vector<KeyframeEdge> edges = {
      E(K(0, 0), K(1, 0)), E(K(0, 0), K(1, 1)), E(K(0, 0), K(1, 2)), E(K(0, 1), K(1, 0)),
      E(K(0, 2), K(1, 0)), E(K(0, 3), K(1, 3)), E(K(1, 3), K(0, 4)), E(K(0, 4), K(1, 4)),
      E(K(1, 4), K(0, 5)), E(K(2, 0), K(0, 0))};
  const std::vector<RobotId> involved = {RobotId(0), RobotId(1)};
  const std::vector<KeyframeRef> sent = VertexCoverBrokerage(edges, involved);
  EXPECT_EQ(sent, (std::vector<KeyframeRef>{K(0, 0), K(1, 0), K(1, 3), K(1, 4)}));
  EXPECT_TRUE(Covers(sent, std::vector<KeyframeEdge>(edges.begin(), edges.end() - 1)));
  // The side named first does not change a cover that is the only minimum.
  const std::vector<RobotId> swapped = {RobotId(1), RobotId(0)};
  EXPECT_EQ(VertexCoverBrokerage(edges, swapped), sent);
}

// A minimum cover is the least any brokerage can send: the dialog, whatever its draws, sends at
// least as many keyframes for the same edges.
TEST(VertexCoverBrokerage, TwoRobotsNeverSendMoreThanTheDialog) {
  const std::vector<KeyframeEdge> edges = {
      E(K(0, 0), K(1, 0)), E(K(0, 0), K(1, 1)), E(K(0, 0), K(1, 2)), E(K(0, 1), K(1, 0)),
      E(K(0, 2), K(1, 0)), E(K(0, 3), K(1, 3)), E(K(1, 3), K(0, 4)), E(K(0, 4), K(1, 4)),
      E(K(1, 4), K(0, 5))};
  const std::vector<RobotId> involved = {RobotId(0), RobotId(1)};
  const std::size_t cover = VertexCoverBrokerage(edges, involved).size();
  for (std::uint64_t seed = 0; seed < 32; ++seed) {
    EXPECT_LE(cover, DialogBrokerage(edges, seed).size()) << "seed " << seed;
  }
}

// Three robots, a triangle with a pendant: edges in order (0:0)-(1:0), (1:0)-(2:0),
// (2:0)-(0:0), (2:1)-(1:0). Keyframes by first appearance n0=(0:0), n1=(1:0), n2=(2:0),
// n3=(2:1); networkx's edge order (n0,n1), (n0,n2), (n1,n2), (n1,n3). Unit costs:
// (n0,n1) takes n0 (a tie goes to the first), cost(n1) = 0; (n0,n2) covered; (n1,n2): cost 0 <= 1
// takes n1; (n1,n3) covered. Cover {(0:0), (1:0)}: 2, the triangle's minimum.
TEST(VertexCoverBrokerage, ThreeRobotsTakeTheLocalRatioCover) {
  const std::vector<KeyframeEdge> edges = {E(K(0, 0), K(1, 0)), E(K(1, 0), K(2, 0)),
                                           E(K(2, 0), K(0, 0)), E(K(2, 1), K(1, 0))};
  const std::vector<RobotId> involved = {RobotId(0), RobotId(1), RobotId(2)};
  EXPECT_EQ(VertexCoverBrokerage(edges, involved), (std::vector<KeyframeRef>{K(0, 0), K(1, 0)}));
}

// A star around (2:0) whose first edge comes from a leaf: (0:0)-(2:0), (1:0)-(2:0), (1:1)-(2:0).
// Order n0=(0:0), n1=(2:0), n2=(1:0), n3=(1:1); edges (n0,n1), (n1,n2), (n1,n3). (n0,n1) takes
// the leaf n0, cost(n1) = 0; (n1,n2) takes n1; (n1,n3) covered. Cover {(0:0), (2:0)}: 2, twice
// the minimum {(2:0)}, the 2-approximation's worst case, as Swarm-SLAM would send.
TEST(VertexCoverBrokerage, ThreeRobotsCanSendTwiceTheMinimum) {
  const std::vector<KeyframeEdge> edges = {E(K(0, 0), K(2, 0)), E(K(1, 0), K(2, 0)), E(K(1, 1), K(2, 0))};
  const std::vector<RobotId> involved = {RobotId(0), RobotId(1), RobotId(2)};
  EXPECT_EQ(VertexCoverBrokerage(edges, involved), (std::vector<KeyframeRef>{K(0, 0), K(2, 0)}));
}

TEST(VertexCoverBrokerage, RefusesFewerThanTwoRobotsAndEdgesWithinARobot) {
  const std::vector<KeyframeEdge> edges = {E(K(0, 0), K(1, 0))};
  const std::vector<RobotId> one = {RobotId(0), RobotId(0)};
  EXPECT_THROW(VertexCoverBrokerage(edges, one), std::invalid_argument);
  const std::vector<KeyframeEdge> inner = {E(K(0, 0), K(0, 1))};
  const std::vector<RobotId> two = {RobotId(0), RobotId(1)};
  EXPECT_THROW(VertexCoverBrokerage(inner, two), std::invalid_argument);
  EXPECT_TRUE(VertexCoverBrokerage(std::vector<KeyframeEdge>{}, two).empty());
}

// The dialog by its rule, one Below(2) draw per edge with neither side sent: edges A0-B0,
// A0-B1, A1-B1. The first draw d1 sends A0 (0) or B0 (1). If A0 went, A0-B1 is covered and the
// second draw d2 decides A1-B1; if B0 went, d2 decides A0-B1 (A0 or B1), and A1-B1 needs a third
// draw unless B1 was sent.
TEST(DialogBrokerage, FollowsItsDrawsAndIsTheSameForASeed) {
  const std::vector<KeyframeEdge> edges = {E(K(0, 0), K(1, 0)), E(K(0, 0), K(1, 1)), E(K(0, 1), K(1, 1))};
  std::set<std::vector<KeyframeRef>> seen;
  for (std::uint64_t seed = 0; seed < 64; ++seed) {
    Xoshiro256 rng(seed);
    std::set<KeyframeRef> expected;
    if (rng.Below(2) == 0) {
      expected = {K(0, 0), rng.Below(2) == 0 ? K(0, 1) : K(1, 1)};
    } else if (rng.Below(2) == 0) {
      expected = {K(1, 0), K(0, 0), rng.Below(2) == 0 ? K(0, 1) : K(1, 1)};
    } else {
      expected = {K(1, 0), K(1, 1)};
    }
    const std::vector<KeyframeRef> sent = DialogBrokerage(edges, seed);
    EXPECT_EQ(sent, std::vector<KeyframeRef>(expected.begin(), expected.end())) << "seed " << seed;
    EXPECT_EQ(DialogBrokerage(edges, seed), sent);
    EXPECT_TRUE(Covers(sent, edges));
    seen.insert(sent);
  }
  EXPECT_EQ(seen.size(), 5u);  // {A0,A1} {A0,B1} {B0,A0,A1} {B0,A0,B1} {B0,B1}: every outcome occurs
}

}  // namespace
}  // namespace dvpr
