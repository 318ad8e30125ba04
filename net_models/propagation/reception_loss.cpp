#include "net_models/propagation/reception_loss.h"

#include <stdexcept>
#include <string>

namespace dvpr {
namespace {

std::uint64_t PairComponent(NodeId src, NodeId dst) {
  return ComponentId("network.loss") ^ (static_cast<std::uint64_t>(static_cast<std::uint32_t>(src.value)) << 32 |
                                        static_cast<std::uint32_t>(dst.value));
}

}  // namespace

ReceptionLoss::ReceptionLoss(int nodes, const LossParams& loss, std::span<const PairLossOverride> overrides,
                             std::uint64_t run_seed)
    : nodes_(nodes) {
  if (nodes <= 0) throw std::invalid_argument("robots = " + std::to_string(nodes) + ": need at least one node");
  loss.Validate();
  pairs_.reserve(static_cast<std::size_t>(nodes) * static_cast<std::size_t>(nodes));
  for (int s = 0; s < nodes; ++s) {
    for (int d = 0; d < nodes; ++d) {
      pairs_.push_back(Pair{MakeFrameLoss(loss), RandomStream(run_seed, PairComponent(NodeId(s), NodeId(d)))});
    }
  }
  for (const PairLossOverride& o : overrides) {
    if (o.src.value < 0 || o.src.value >= nodes || o.dst.value < 0 || o.dst.value >= nodes) {
      throw std::invalid_argument("network.links: loss override for " + std::to_string(o.src.value) + "->" +
                                  std::to_string(o.dst.value) + " names a node outside [0, " +
                                  std::to_string(nodes) + ")");
    }
    o.loss.Validate();
    pairs_[Index(o.src, o.dst)].loss = MakeFrameLoss(o.loss);
  }
}

std::uint64_t ReceptionLoss::FramesLost() const {
  std::uint64_t lost = 0;
  for (const Pair& p : pairs_) lost += p.loss ? p.loss->Lost() : 0;
  return lost;
}

void ReceptionLoss::Apply(NodeId src, std::span<const NodeId> receivers, std::size_t frames,
                          std::span<LinkDelivery> outcomes) {
  for (std::size_t i = 0; i < receivers.size(); ++i) {
    Pair& pair = pairs_[Index(src, receivers[i])];
    if (outcomes[i].drop != DropReason::kNone || !pair.loss) continue;
    bool lost = false;
    for (std::size_t f = 0; f < frames; ++f) lost = pair.loss->IsLost(pair.rng) || lost;
    if (lost) outcomes[i].drop = DropReason::kLoss;
  }
}

}  // namespace dvpr
