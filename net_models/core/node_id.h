#pragma once
// A node of the simulated network: robot r is node r (0..n-1). The network
// layer knows nodes, not robots; agents convert RobotId <-> NodeId at the edge.
#include <compare>
#include <cstdint>
#include <ostream>

namespace dvpr {

struct NodeId {
  std::int32_t value = 0;
  constexpr NodeId() = default;
  constexpr explicit NodeId(std::int32_t v) : value(v) {}
  constexpr auto operator<=>(const NodeId&) const = default;
};

inline std::ostream& operator<<(std::ostream& os, NodeId n) { return os << n.value; }

}  // namespace dvpr
