#include "net_models/bernoulli_loss.h"

#include "net_models/loss_params.h"

namespace dvpr {

void BernoulliLossParams::Validate() const { CheckProbability("network.loss.p", p); }

BernoulliLoss::BernoulliLoss(const BernoulliLossParams& params) : p_(params.p) { params.Validate(); }

}  // namespace dvpr
