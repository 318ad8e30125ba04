#include "net_models/gilbert_elliott_loss.h"

#include "net_models/loss_params.h"

namespace dvpr {

void GilbertElliottParams::Validate() const {
  CheckProbability("network.loss.p_good_to_bad", p_good_to_bad);
  CheckProbability("network.loss.p_bad_to_good", p_bad_to_good);
  CheckProbability("network.loss.loss_good", loss_good);
  CheckProbability("network.loss.loss_bad", loss_bad);
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
