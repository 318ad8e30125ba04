#include "net_models/bernoulli_loss.h"

#include "net_models/param_checks.h"

namespace dvpr {

void BernoulliLossParams::Validate() const { CheckProbability("p", p); }

BernoulliLoss::BernoulliLoss(const BernoulliLossParams& params) : p_(params.p) { params.Validate(); }

}  // namespace dvpr
