#include "net_models/propagation_model.h"

#include <stdexcept>

namespace dvpr {

void PropagationModel::Reach(NodeId src, std::span<const NodeId> receivers, SimTime now, std::span<Reception> out) {
  if (out.size() != receivers.size()) {
    throw std::logic_error("PropagationModel::Reach: one outcome slot per receiver expected");
  }
  for (Reception& r : out) r = Reception{true, SimTime::Zero()};
  DoReach(src, receivers, now, out);
}

}  // namespace dvpr
