#include "net_models/propagation/propagation_channel.h"

namespace dvpr {

void PropagationChannel::Settle(const LinkTransmission& t, std::span<LinkDelivery> outcomes) {
  const NodeId src = t.src;
  const std::span<const NodeId> receivers = t.dsts;
  // Loss before propagation, each pair's draws as many as its frames: the order of the draws is
  // the run's (seeded per pair) and must not depend on who hears whom.
  if (loss_ != nullptr) loss_->Apply(src, receivers, t.frames.size(), outcomes);
  receptions_.resize(receivers.size());
  propagation_.Reach(src, receivers, t.now, receptions_);
  for (std::size_t i = 0; i < receivers.size(); ++i) {
    LinkDelivery& d = outcomes[i];
    if (d.drop == DropReason::kNone && !receptions_[i].reaches) d.drop = t.unheard;
  }
  if (propagation_.ChangesOverTime()) {
    // Asked again at each frame's end, one question per distinct end time (usually one for all).
    for (std::size_t i = 0; i < receivers.size();) {
      if (outcomes[i].drop != DropReason::kNone) {
        ++i;
        continue;
      }
      const SimTime end = outcomes[i].frame_end;
      frame_end_receivers_.clear();
      frame_end_index_.clear();
      std::size_t j = i;
      for (; j < receivers.size(); ++j) {
        if (outcomes[j].drop != DropReason::kNone) continue;
        if (outcomes[j].frame_end != end) break;
        frame_end_receivers_.push_back(receivers[j]);
        frame_end_index_.push_back(j);
      }
      frame_end_receptions_.resize(frame_end_receivers_.size());
      propagation_.Reach(src, frame_end_receivers_, end, frame_end_receptions_);
      for (std::size_t k = 0; k < frame_end_index_.size(); ++k) {
        if (!frame_end_receptions_[k].reaches) outcomes[frame_end_index_[k]].drop = DropReason::kOutOfRange;
      }
      i = j;
    }
  }
  for (std::size_t i = 0; i < receivers.size(); ++i) {
    LinkDelivery& d = outcomes[i];
    if (d.drop == DropReason::kNone) d.arrival += receptions_[i].delay;
  }
}

void PropagationChannel::KeepHearers(NodeId src, std::vector<NodeId>& nodes, SimTime at) {
  receptions_.resize(nodes.size());
  propagation_.Reach(src, nodes, at, receptions_);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (receptions_[i].reaches) nodes[kept++] = nodes[i];
  }
  nodes.resize(kept);
}

}  // namespace dvpr
