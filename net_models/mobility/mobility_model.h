#pragma once
// Where each node is at a virtual time (docs/design.md section 4.1, "position"): the lowest of
// the network's four concerns. A propagation model that depends on distance asks it; nothing
// else in the network does, and the agents never see it (as IP does not tell an application
// where its peer is). ns-3's MobilityModel, queried instead of aggregated to a node.
//
// PositionOf is the public, non-virtual entry point: it checks the node, then asks the model.
// Models are pure functions of (node, time): asking never changes what a later question gets,
// so any number of models or recorders may ask in any order.
#include <string_view>

#include "net_models/core/node_id.h"
#include "net_models/core/position.h"
#include "sim/sim_time.h"

namespace dvpr {

class MobilityModel {
 public:
  virtual ~MobilityModel() = default;

  // The number of nodes the model places (nodes 0 .. nodes() - 1).
  int nodes() const { return DoNodes(); }
  // Throws std::out_of_range for a node the model does not place.
  Position PositionOf(NodeId node, SimTime at) const;
  // "fixed", "track", ...
  std::string_view Name() const { return DoName(); }

 private:
  virtual int DoNodes() const = 0;
  // node lies in [0, nodes()).
  virtual Position DoPositionOf(NodeId node, SimTime at) const = 0;
  virtual std::string_view DoName() const = 0;
};

}  // namespace dvpr
