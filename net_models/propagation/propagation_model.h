#pragma once
// What a transmission reaches (docs/design.md section 4.1, "propagation"): whether a node hears
// what another sends at a virtual time, and the propagation delay the air adds to the link's
// arrival time (ns-3's PropagationLossModel and PropagationDelayModel in one question). A model
// that depends on distance is built over a MobilityModel; one that loses transmissions at random
// draws from its own seeded stream, as the channel's loss does (reception_loss.h).
//
// The network's PropagationChannel asks (propagation_channel.h), for all of a transmission's
// receivers together, when the medium access has put it on the medium (or, a contending one, a
// frame on the air): a copy the medium delivered but the receiver does not hear is dropped
// (DropReason::kOutOfRange); its frames were on the air all the same.
//
// Reach is the public, non-virtual entry point (NVI): it checks the request and presets every
// outcome to "reaches, no added delay", which is the full mesh; a model changes what differs.
#include <span>
#include <string_view>
#include <vector>

#include "net_models/core/node_id.h"
#include "sim/sim_time.h"

namespace dvpr {

struct Reception {
  bool reaches = true;
  SimTime delay;  // added to the arrival the medium access model worked out
};

class PropagationModel {
 public:
  virtual ~PropagationModel() = default;

  // Fills out[i] for receivers[i] (out.size() == receivers.size(); receivers distinct, none
  // equal to src) of what src transmits at `now`.
  void Reach(NodeId src, std::span<const NodeId> receivers, SimTime now, std::span<Reception> out);
  // "full_mesh", "range(50m)", ...
  std::string_view Name() const { return DoName(); }
  // Whether who hears whom can change over time (nodes that move): then the channel asks again
  // at the end of each frame, and a receiver that left range while it was sent does not get it.
  bool ChangesOverTime() const { return DoChangesOverTime(); }

 private:
  // out[i] arrives preset to {reaches, zero delay}.
  virtual void DoReach(NodeId src, std::span<const NodeId> receivers, SimTime now, std::span<Reception> out) = 0;
  virtual std::string_view DoName() const = 0;
  virtual bool DoChangesOverTime() const { return true; }
};

// Who hears whom at `at`: heard_by[u] lists, ascending, the nodes of 0 .. nodes - 1 that hear
// what u sends (one Reach per node, every other node a receiver). The graph that routing over
// the radio and the connectivity outputs are built on.
std::vector<std::vector<NodeId>> HeardBy(PropagationModel& propagation, int nodes, SimTime at);

}  // namespace dvpr
