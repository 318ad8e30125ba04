#pragma once
// Brokerage of verification data, as Swarm-SLAM's Broker (cslam/broker.py): once the broker has
// selected the inter-robot edges to verify, which keyframes' local features are sent so that
// every selected edge has one of its two keyframes at the other robot. The result is the set of
// keyframes to send, sorted; who receives each follows from the edges.
#include <cstdint>
#include <span>
#include <vector>

#include "agents/algorithms/ids.h"
#include "agents/sharing/keyframe_graph.h"

namespace dvpr {

// A minimum vertex cover of the graph of `edges` whose two robots are both in `robots_involved`
// (other edges are left out, as Swarm-SLAM's Broker leaves them out of its graph), per connected
// component:
// - exactly two robots involved: the exact minimum, from a maximum bipartite matching by König's
//   theorem (the vertices not reached by alternating paths from the unmatched keyframes of
//   robots_involved[0], plus the reached ones of the other robot). Swarm-SLAM takes the left side
//   from networkx's 2-colouring of each component, so where a component has several minimum
//   covers it may return another one of the same size;
// - more robots: the local-ratio 2-approximation (Bar-Yehuda and Even) with unit weights, which
//   is networkx's min_weighted_vertex_cover that Swarm-SLAM calls. Its result depends on the
//   order of the edges: we take networkx's order for a graph built from `edges` in their order
//   (keyframes numbered by first appearance, each keyframe's edges in insertion order, an edge
//   reported at its earlier keyframe, which wins a tie). networkx may reorder the keyframes of a
//   component smaller than half the graph (it copies a subgraph through a set).
// Throws std::invalid_argument when fewer than two distinct robots are involved (as the Broker).
std::vector<KeyframeRef> VertexCoverBrokerage(std::span<const KeyframeEdge> edges,
                                              std::span<const RobotId> robots_involved);

// Swarm-SLAM's "simple dialog": for each edge in order, unless one of its keyframes is already
// sent, one of the two is sent, side a or b with probability 1/2 each (Swarm-SLAM draws numpy's
// randint(2); here one draw of Xoshiro256(seed).Below(2) per such edge, 0 meaning side a), so a
// seed always gives the same keyframes. All edges count, whatever their robots.
std::vector<KeyframeRef> DialogBrokerage(std::span<const KeyframeEdge> edges, std::uint64_t seed);

}  // namespace dvpr
