#include "net_models/mobility/fixed_mobility.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "net_models/core/param_checks.h"

namespace dvpr {

FixedMobility::FixedMobility(std::vector<Position> positions) : positions_(std::move(positions)) {
  if (positions_.empty()) InvalidParam("positions", "a network needs at least one node, got none");
  for (std::size_t i = 0; i < positions_.size(); ++i) CheckFinitePosition("positions[" + std::to_string(i) + "]", positions_[i]);
}

FixedMobility FixedMobility::AtOrigin(int nodes) {
  if (nodes <= 0) InvalidParam("nodes", "a network needs at least one node, got " + std::to_string(nodes));
  return FixedMobility(std::vector<Position>(static_cast<std::size_t>(nodes)));
}

Position FixedMobility::DoPositionOf(NodeId node, SimTime) const {
  return positions_[static_cast<std::size_t>(node.value)];
}

}  // namespace dvpr
