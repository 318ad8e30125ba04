#pragma once
// Loss as a decorator around any LinkModel: the inner model decides timing
// and queue drops; then every frame that reached a receiver goes through that
// directed pair's loss process (loss_params.h). A message is lost if any of
// its frames is (IP and LCM reassembly need them all); lost frames still
// occupied the medium. Each pair draws from its own random stream, seeded from
// (run seed, pair), so one pair's traffic does not change another's losses.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "net_models/link_model.h"
#include "net_models/loss_params.h"
#include "sim/random.h"

namespace dvpr {

struct PairLossOverride {
  NodeId src;
  NodeId dst;
  LossParams loss;
};

class LossyLink final : public LinkModel {
 public:
  LossyLink(std::unique_ptr<LinkModel> inner, int nodes, const LossParams& loss,
            std::span<const PairLossOverride> overrides, std::uint64_t run_seed);

  const LinkModel& inner() const { return *inner_; }
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
  MediumUse DoTransmit(const LinkTransmission& t, std::span<LinkDelivery> out) override;
  std::string_view DoName() const override { return name_; }
  SimTime DoDelayAfterFrame() const override { return inner_->DelayAfterFrame(); }

  std::unique_ptr<LinkModel> inner_;
  int nodes_;
  std::vector<Pair> pairs_;
  std::string name_;
};

}  // namespace dvpr
