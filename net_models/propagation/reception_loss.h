#pragma once
// Loss on the channel (loss_params.h): every frame of a copy the medium access delivered goes
// through its directed pair's loss process, and a copy is lost if any of its frames is (IP and LCM
// reassembly need them all). The frames were on the medium all the same: the medium's use and the
// sender's bytes count them. Each pair draws from its own random stream, seeded from (run seed,
// pair), so one pair's traffic does not change another's losses. The network's PropagationChannel
// asks it first for a transmission its medium decided at send time, then the propagation (a
// contending medium access, which decides its copies later, takes no loss model).
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "net_models/core/node_id.h"
#include "net_models/core/transmission.h"
#include "net_models/propagation/frame_loss.h"
#include "net_models/propagation/loss_params.h"
#include "sim/random.h"

namespace dvpr {

// A directed pair whose loss differs from the network's (network.links[].loss).
struct PairLossOverride {
  NodeId src;
  NodeId dst;
  LossParams loss;
};

class ReceptionLoss {
 public:
  // Throws std::invalid_argument on a node count below 1, invalid parameters, or an override
  // naming a node outside [0, nodes).
  ReceptionLoss(int nodes, const LossParams& loss, std::span<const PairLossOverride> overrides, std::uint64_t run_seed);

  // outcomes[i] is receivers[i]'s: a copy not yet dropped draws once per frame (even after a loss,
  // so a stateful process advances once per frame on the air) and is dropped kLoss if any is lost.
  void Apply(NodeId src, std::span<const NodeId> receivers, std::size_t frames, std::span<LinkDelivery> outcomes);
  // The pair's loss process; null when the pair is lossless.
  const FrameLoss* LossOf(NodeId src, NodeId dst) const { return pairs_[Index(src, dst)].loss.get(); }
  std::uint64_t FramesLost() const;

 private:
  struct Pair {
    std::unique_ptr<FrameLoss> loss;
    RandomStream rng;
  };
  std::size_t Index(NodeId src, NodeId dst) const {
    return static_cast<std::size_t>(src.value) * static_cast<std::size_t>(nodes_) +
           static_cast<std::size_t>(dst.value);
  }

  int nodes_;
  std::vector<Pair> pairs_;
};

}  // namespace dvpr
