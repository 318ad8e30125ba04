#include "net_models/loss_params.h"

#include <sstream>
#include <stdexcept>
#include <string>

namespace dvpr {

LossModelKind ParseLossModelKind(std::string_view name) {
  if (name == "none") return LossModelKind::kNone;
  if (name == "bernoulli") return LossModelKind::kBernoulli;
  if (name == "gilbert_elliott") return LossModelKind::kGilbertElliott;
  throw std::invalid_argument("network.loss.model = \"" + std::string(name) +
                              "\": unknown loss model; expected none, bernoulli or gilbert_elliott");
}

std::string_view ToString(LossModelKind kind) {
  switch (kind) {
    case LossModelKind::kNone: return "none";
    case LossModelKind::kBernoulli: return "bernoulli";
    case LossModelKind::kGilbertElliott: return "gilbert_elliott";
  }
  return "unknown";
}

void LossParams::Validate() const {
  if (model == LossModelKind::kBernoulli) bernoulli.Validate();
  if (model == LossModelKind::kGilbertElliott) gilbert_elliott.Validate();
}

std::unique_ptr<FrameLoss> MakeFrameLoss(const LossParams& params) {
  switch (params.model) {
    case LossModelKind::kNone: return nullptr;
    case LossModelKind::kBernoulli: return std::make_unique<BernoulliLoss>(params.bernoulli);
    case LossModelKind::kGilbertElliott: return std::make_unique<GilbertElliottLoss>(params.gilbert_elliott);
  }
  return nullptr;
}

void CheckProbability(std::string_view key, double p) {
  if (!(p >= 0.0 && p <= 1.0)) {
    std::ostringstream msg;
    msg << key << " = " << p << ": a probability must lie in [0, 1]";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace dvpr
