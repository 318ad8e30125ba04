#include "net_models/lossy_link.h"

#include <stdexcept>

namespace dvpr {
namespace {

std::uint64_t PairComponent(NodeId src, NodeId dst) {
  return ComponentId("network.loss") ^ (static_cast<std::uint64_t>(static_cast<std::uint32_t>(src.value)) << 32 |
                                        static_cast<std::uint32_t>(dst.value));
}

}  // namespace

LossyLink::LossyLink(std::unique_ptr<LinkModel> inner, int nodes, const LossParams& loss,
                     std::span<const PairLossOverride> overrides, std::uint64_t run_seed)
    : inner_(std::move(inner)), nodes_(nodes) {
  if (!inner_) throw std::invalid_argument("LossyLink: no inner link model");
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
  name_ = std::string(ToString(loss.model)) + "(" + std::string(inner_->Name()) + ")";
}

std::uint64_t LossyLink::FramesLost() const {
  std::uint64_t lost = 0;
  for (const Pair& p : pairs_) lost += p.loss ? p.loss->Lost() : 0;
  return lost;
}

LinkModel::MediumUse LossyLink::DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) {
  const MediumUse use = inner_->Transmit(t, out);
  for (std::size_t i = 0; i < out.size(); ++i) {
    Pair& pair = pairs_[Index(t.src, t.dsts[i])];
    if (out[i].drop != DropReason::kNone || !pair.loss) continue;
    // Every frame is examined, even after a loss, so a stateful process
    // advances once per frame on the air.
    bool lost = false;
    for (std::size_t f = 0; f < t.frames.size(); ++f) lost = pair.loss->IsLost(pair.rng) || lost;
    if (lost) out[i].drop = DropReason::kLoss;
  }
  return use;  // a lost frame was on the air all the same
}

}  // namespace dvpr
