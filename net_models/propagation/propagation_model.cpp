#include "net_models/propagation/propagation_model.h"

#include <algorithm>
#include <stdexcept>

namespace dvpr {

void PropagationModel::Reach(NodeId src, std::span<const NodeId> receivers, SimTime now, std::span<Reception> out) {
  if (out.size() != receivers.size()) {
    throw std::logic_error("PropagationModel::Reach: one outcome slot per receiver expected");
  }
  for (Reception& r : out) r = Reception{true, SimTime::Zero()};
  DoReach(src, receivers, now, out);
}

std::vector<std::vector<NodeId>> HeardBy(PropagationModel& propagation, int nodes, SimTime at) {
  std::vector<std::vector<NodeId>> heard_by(static_cast<std::size_t>(std::max(nodes, 0)));
  std::vector<NodeId> receivers;
  std::vector<Reception> out;
  for (int u = 0; u < nodes; ++u) {
    receivers.clear();
    for (int v = 0; v < nodes; ++v) {
      if (v != u) receivers.push_back(NodeId(v));
    }
    out.assign(receivers.size(), Reception{});
    propagation.Reach(NodeId(u), receivers, at, out);
    for (std::size_t i = 0; i < receivers.size(); ++i) {
      if (out[i].reaches) heard_by[static_cast<std::size_t>(u)].push_back(receivers[i]);
    }
  }
  return heard_by;
}

}  // namespace dvpr
