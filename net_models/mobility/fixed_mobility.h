#pragma once
// "fixed": every node stays where it is put (ns-3's ConstantPositionMobilityModel). The
// network's default: with the full-mesh propagation nothing asks where a node is, and a team
// whose robots stand still (a static deployment, a test) needs nothing more.
#include <vector>

#include "net_models/mobility/mobility_model.h"

namespace dvpr {

class FixedMobility final : public MobilityModel {
 public:
  // Node i at positions[i]. Throws std::invalid_argument for no node or a coordinate that is
  // not finite ("positions[i]: ...").
  explicit FixedMobility(std::vector<Position> positions);
  // `nodes` nodes, all at the origin.
  static FixedMobility AtOrigin(int nodes);

 private:
  int DoNodes() const override { return static_cast<int>(positions_.size()); }
  Position DoPositionOf(NodeId node, SimTime at) const override;
  std::string_view DoName() const override { return "fixed"; }

  std::vector<Position> positions_;
};

}  // namespace dvpr
