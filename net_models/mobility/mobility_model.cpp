#include "net_models/mobility/mobility_model.h"

#include <stdexcept>
#include <string>

namespace dvpr {

Position MobilityModel::PositionOf(NodeId node, SimTime at) const {
  if (node.value < 0 || node.value >= nodes()) {
    throw std::out_of_range("MobilityModel::PositionOf: node " + std::to_string(node.value) + " outside [0, " +
                            std::to_string(nodes()) + ")");
  }
  return DoPositionOf(node, at);
}

}  // namespace dvpr
