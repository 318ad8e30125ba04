#pragma once
// Choosing a loss process by configuration: none, bernoulli or gilbert_elliott.
#include <memory>
#include <string_view>

#include "net_models/bernoulli_loss.h"
#include "net_models/gilbert_elliott_loss.h"

namespace dvpr {

enum class LossModelKind { kNone, kBernoulli, kGilbertElliott };

// "none" | "bernoulli" | "gilbert_elliott"; anything else throws
// std::invalid_argument naming network.loss.model and the value.
LossModelKind ParseLossModelKind(std::string_view name);
std::string_view ToString(LossModelKind kind);

struct LossParams {
  LossModelKind model = LossModelKind::kNone;
  BernoulliLossParams bernoulli;
  GilbertElliottParams gilbert_elliott;
  void Validate() const;  // validates the chosen model's parameters
};

// A fresh loss process for one pair; null for kNone.
std::unique_ptr<FrameLoss> MakeFrameLoss(const LossParams& params);

// Throws std::invalid_argument "<key> = <p>: a probability must lie in [0, 1]"
// unless 0 <= p <= 1 (NaN fails).
void CheckProbability(std::string_view key, double p);

}  // namespace dvpr
