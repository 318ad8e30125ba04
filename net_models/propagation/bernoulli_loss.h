#pragma once
// "bernoulli": each frame is lost independently with probability p.
#include "net_models/propagation/frame_loss.h"

namespace dvpr {

struct BernoulliLossParams {
  double p = 0.0;
  // Throws std::invalid_argument "p: ..." unless 0 <= p <= 1.
  void Validate() const;
  bool operator==(const BernoulliLossParams&) const = default;
};

class BernoulliLoss final : public FrameLoss {
 public:
  explicit BernoulliLoss(const BernoulliLossParams& params);

 private:
  bool DoIsLost(RandomStream& rng) override { return rng.Bernoulli(p_); }
  std::string_view DoName() const override { return "bernoulli"; }

  double p_;
};

}  // namespace dvpr
