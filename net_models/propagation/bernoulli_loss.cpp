#include "net_models/propagation/bernoulli_loss.h"

#include "net_models/core/param_checks.h"

namespace dvpr {

void BernoulliLossParams::Validate() const { CheckProbability("p", p); }

BernoulliLoss::BernoulliLoss(const BernoulliLossParams& params) : p_(params.p) { params.Validate(); }

}  // namespace dvpr
