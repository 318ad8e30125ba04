#include "net_models/propagation/gilbert_elliott_loss.h"

#include "net_models/core/param_checks.h"

namespace dvpr {

void GilbertElliottParams::Validate() const {
  CheckProbability("p_good_to_bad", p_good_to_bad);
  CheckProbability("p_bad_to_good", p_bad_to_good);
  CheckProbability("loss_good", loss_good);
  CheckProbability("loss_bad", loss_bad);
}

GilbertElliottLoss::GilbertElliottLoss(const GilbertElliottParams& params) : params_(params) {
  params_.Validate();
}

bool GilbertElliottLoss::DoIsLost(RandomStream& rng) {
  const bool lost = rng.Bernoulli(bad_ ? params_.loss_bad : params_.loss_good);
  bad_ = bad_ ? !rng.Bernoulli(params_.p_bad_to_good) : rng.Bernoulli(params_.p_good_to_bad);
  return lost;
}

}  // namespace dvpr
