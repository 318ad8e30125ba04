#pragma once
// "gilbert_elliott": bursty loss. The pair's channel is a two-state Markov
// chain, good or bad, starting good. For every frame, the frame is lost with
// the current state's loss probability, then the state moves (good -> bad
// with p_good_to_bad, bad -> good with p_bad_to_good). Mean burst length is
// 1 / p_bad_to_good frames; the long-run fraction of frames sent in the bad
// state is p_good_to_bad / (p_good_to_bad + p_bad_to_good).
#include "net_models/propagation/frame_loss.h"

namespace dvpr {

struct GilbertElliottParams {
  double p_good_to_bad = 0.01;
  double p_bad_to_good = 0.1;
  double loss_good = 0.0;
  double loss_bad = 1.0;
  // Throws std::invalid_argument "<field>: ..." unless every probability
  // lies in [0, 1].
  void Validate() const;
  bool operator==(const GilbertElliottParams&) const = default;
};

class GilbertElliottLoss final : public FrameLoss {
 public:
  explicit GilbertElliottLoss(const GilbertElliottParams& params);
  bool IsBad() const { return bad_; }

 private:
  bool DoIsLost(RandomStream& rng) override;
  std::string_view DoName() const override { return "gilbert_elliott"; }

  GilbertElliottParams params_;
  bool bad_ = false;
};

}  // namespace dvpr
