#include "agents/sharing/brokerage.h"

#include <algorithm>
#include <cstddef>
#include <deque>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "sim/random_bits.h"

namespace dvpr {
namespace {

// The undirected graph networkx's Broker builds: keyframes numbered by first appearance, each
// keyframe's neighbours in the order their edges came, a repeated edge kept once.
struct CoverGraph {
  std::vector<KeyframeRef> keyframes;
  std::vector<std::vector<int>> neighbours;
  std::map<KeyframeRef, int> number;

  int Add(KeyframeRef k) {
    const auto [it, added] = number.try_emplace(k, static_cast<int>(keyframes.size()));
    if (added) {
      keyframes.push_back(k);
      neighbours.emplace_back();
    }
    return it->second;
  }
  void Link(KeyframeRef a, KeyframeRef b) {
    const int u = Add(a);
    const int v = Add(b);
    auto& nu = neighbours[static_cast<std::size_t>(u)];
    if (u == v || std::find(nu.begin(), nu.end(), v) != nu.end()) return;
    nu.push_back(v);
    neighbours[static_cast<std::size_t>(v)].push_back(u);
  }
};

std::vector<KeyframeRef> Sorted(const CoverGraph& g, const std::vector<bool>& in_cover) {
  std::vector<KeyframeRef> out;
  for (std::size_t i = 0; i < in_cover.size(); ++i) {
    if (in_cover[i]) out.push_back(g.keyframes[i]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Local ratio with unit weights, over the edges in networkx's Graph.edges() order: keyframe u in
// order, then its neighbours v not yet visited as a u.
std::vector<KeyframeRef> LocalRatioCover(const CoverGraph& g) {
  const std::size_t n = g.keyframes.size();
  std::vector<int> cost(n, 1);
  std::vector<bool> cover(n, false);
  for (std::size_t u = 0; u < n; ++u) {
    for (const int vi : g.neighbours[u]) {
      const auto v = static_cast<std::size_t>(vi);
      if (v < u || cover[u] || cover[v]) continue;
      if (cost[u] <= cost[v]) {
        cover[u] = true;
        cost[v] -= cost[u];
      } else {
        cover[v] = true;
        cost[u] -= cost[v];
      }
    }
  }
  return Sorted(g, cover);
}

// Kuhn's augmenting path from left keyframe u; match[x] is x's partner or -1.
bool Augment(const CoverGraph& g, int u, std::vector<int>& match, std::vector<bool>& visited) {
  for (const int v : g.neighbours[static_cast<std::size_t>(u)]) {
    if (visited[static_cast<std::size_t>(v)]) continue;
    visited[static_cast<std::size_t>(v)] = true;
    const int partner = match[static_cast<std::size_t>(v)];
    if (partner < 0 || Augment(g, partner, match, visited)) {
      match[static_cast<std::size_t>(v)] = u;
      match[static_cast<std::size_t>(u)] = v;
      return true;
    }
  }
  return false;
}

// König: a maximum matching, then Z = the keyframes reached from unmatched left keyframes by
// alternating paths (left to right off the matching, right to left on it); the cover is the
// left keyframes outside Z and the right ones inside.
std::vector<KeyframeRef> KonigCover(const CoverGraph& g, RobotId left) {
  const std::size_t n = g.keyframes.size();
  std::vector<int> match(n, -1);
  for (std::size_t u = 0; u < n; ++u) {
    if (g.keyframes[u].robot != left || match[u] >= 0) continue;
    std::vector<bool> visited(n, false);
    Augment(g, static_cast<int>(u), match, visited);
  }
  std::vector<bool> reached(n, false);
  std::deque<std::size_t> todo;
  for (std::size_t u = 0; u < n; ++u) {
    if (g.keyframes[u].robot == left && match[u] < 0) {
      reached[u] = true;
      todo.push_back(u);
    }
  }
  while (!todo.empty()) {
    const std::size_t u = todo.front();
    todo.pop_front();
    for (const int vi : g.neighbours[u]) {
      const auto v = static_cast<std::size_t>(vi);
      if (reached[v] || match[u] == vi) continue;  // left to right off the matching
      reached[v] = true;
      const int back = match[v];  // right to left on it
      if (back >= 0 && !reached[static_cast<std::size_t>(back)]) {
        reached[static_cast<std::size_t>(back)] = true;
        todo.push_back(static_cast<std::size_t>(back));
      }
    }
  }
  std::vector<bool> cover(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    cover[i] = (g.keyframes[i].robot == left) != reached[i];
  }
  return Sorted(g, cover);
}

}  // namespace

std::vector<KeyframeRef> VertexCoverBrokerage(std::span<const KeyframeEdge> edges,
                                              std::span<const RobotId> robots_involved) {
  const std::set<RobotId> involved(robots_involved.begin(), robots_involved.end());
  if (involved.size() < 2) {
    throw std::invalid_argument("VertexCoverBrokerage: robots_involved names " +
                                std::to_string(involved.size()) + " robot(s); brokerage needs at least 2");
  }
  CoverGraph g;
  for (const KeyframeEdge& e : edges) {
    if (e.a.robot == e.b.robot) {
      throw std::invalid_argument("VertexCoverBrokerage: an edge joins two keyframes of robot " +
                                  std::to_string(e.a.robot.value) + "; brokerage is between robots");
    }
    if (involved.contains(e.a.robot) && involved.contains(e.b.robot)) g.Link(e.a, e.b);
  }
  if (involved.size() == 2) return KonigCover(g, robots_involved.front());
  return LocalRatioCover(g);
}

std::vector<KeyframeRef> DialogBrokerage(std::span<const KeyframeEdge> edges, std::uint64_t seed) {
  Xoshiro256 rng(seed);
  std::set<KeyframeRef> sent;
  for (const KeyframeEdge& e : edges) {
    if (sent.contains(e.a) || sent.contains(e.b)) continue;
    sent.insert(rng.Below(2) == 0 ? e.a : e.b);
  }
  return {sent.begin(), sent.end()};
}

}  // namespace dvpr
