#pragma once
// Who hears whom on a network: the stack's propagation model (over the robots' mobility) and its
// reception loss, asked the questions every transmission asks (docs/design.md section 4.1,
// "propagation"), in one place. The network owns it and lends it to its medium at Bind
// (link_model.h); every medium asks it, whichever way it decides its copies.
//
// - Settle (a medium that decided its copies at send time): first the loss (reception_loss.h,
//   when the channel has one); then a copy the medium delivered but whose receiver does not hear
//   the transmission when it starts is lost (t.unheard: out of range, or a stale route); one whose
//   receiver has left range when its frame ends (LinkDelivery::frame_end) is lost out of range
//   (asked once per distinct frame end, and only when who hears whom changes over time); the
//   others arrive the propagation delay later. The full mesh without loss changes nothing.
// - Hear (a contending medium, for each frame it puts on the air): who hears it, with what delay.
// - KeepHearers: of a link-local send's members, those that hear the sender.
#include <cstddef>
#include <span>
#include <vector>

#include "net_models/core/node_id.h"
#include "net_models/core/transmission.h"
#include "net_models/propagation/propagation_model.h"
#include "net_models/propagation/reception_loss.h"
#include "sim/sim_time.h"

namespace dvpr {

class PropagationChannel {
 public:
  // loss: null on a lossless channel; both must outlive the channel.
  explicit PropagationChannel(PropagationModel& propagation, ReceptionLoss* loss = nullptr)
      : propagation_(propagation), loss_(loss) {}

  // out[i] is t.dsts[i]'s, as the medium decided it at t.now.
  void Settle(const LinkTransmission& t, std::span<LinkDelivery> out);
  // out[i]: whether receivers[i] hears what src transmits at `at`, and the delay the air adds.
  void Hear(NodeId src, std::span<const NodeId> receivers, SimTime at, std::span<Reception> out) {
    propagation_.Reach(src, receivers, at, out);
  }
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
