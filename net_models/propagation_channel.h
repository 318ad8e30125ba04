#pragma once
// Who hears whom on a network: the stack's propagation model (over the robots' mobility) asked
// the questions every transmission asks (docs/design.md section 4.1, "propagation"), in one place.
// The network hands it each transmission a medium access decided at send time; a contending
// medium access asks the propagation itself while it contends (its copies are decided later).
//
// - Settle: first the loss (reception_loss.h, when the channel has one), then: a copy the medium
//   delivered but whose receiver does not hear the transmission when it
//   starts is lost (`unheard`: out of range, or a stale route); one whose receiver has left range
//   when its frame ends is lost out of range (asked once per distinct frame end, and only when
//   who hears whom changes over time); the others arrive the propagation delay later. The full
//   mesh changes nothing.
// - KeepHearers: of a link-local send's members, those that hear the sender.
#include <cstddef>
#include <span>
#include <vector>

#include "net_models/link_model.h"
#include "net_models/node_id.h"
#include "net_models/propagation_model.h"
#include "net_models/reception_loss.h"
#include "sim/sim_time.h"

namespace dvpr {

class PropagationChannel {
 public:
  // loss: null on a lossless channel; both must outlive the channel.
  explicit PropagationChannel(PropagationModel& propagation, ReceptionLoss* loss = nullptr)
      : propagation_(propagation), loss_(loss) {}

  // outcomes[i] is receivers[i]'s, as the medium decided it at `now`, for a message of `frames`
  // frames; after_frame: the medium's time from a frame's end at the sender to its arrival
  // (LinkModel::DelayAfterFrame).
  void Settle(NodeId src, std::span<const NodeId> receivers, SimTime now, std::size_t frames,
              std::span<LinkDelivery> outcomes, DropReason unheard, SimTime after_frame);
  // Keeps, of `nodes`, those that hear src at `at`, in their order.
  void KeepHearers(NodeId src, std::vector<NodeId>& nodes, SimTime at);

 private:
  PropagationModel& propagation_;
  ReceptionLoss* loss_;
  // Scratch reused by every transmission (no allocation once warm).
  std::vector<Reception> receptions_;
  std::vector<NodeId> frame_end_receivers_;  // those asked again at a frame's end
  std::vector<std::size_t> frame_end_index_;
  std::vector<Reception> frame_end_receptions_;
};

}  // namespace dvpr
