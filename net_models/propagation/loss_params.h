#pragma once
// Choosing a loss process by configuration: none, bernoulli or gilbert_elliott.
#include <memory>
#include <string_view>

#include "net_models/propagation/bernoulli_loss.h"
#include "net_models/propagation/gilbert_elliott_loss.h"

namespace dvpr {

enum class LossModelKind { kNone, kBernoulli, kGilbertElliott };

// The one spelling of each kind: "none" | "bernoulli" | "gilbert_elliott". Parse throws
// std::invalid_argument "unknown value '<name>' (expected one of: ...)" for anything else.
LossModelKind ParseLossModelKind(std::string_view name);
std::string_view ToString(LossModelKind kind);

// The fields are flat in the config (`loss: {model: bernoulli, p: 0.01}`): each model's own
// struct holds the keys of that model.
struct LossParams {
  LossModelKind model = LossModelKind::kNone;
  BernoulliLossParams bernoulli;
  GilbertElliottParams gilbert_elliott;
  // Validates the chosen model's parameters; the error names the field ("p: ...").
  void Validate() const;
  bool operator==(const LossParams&) const = default;
};

// A fresh loss process for one pair; null for kNone.
std::unique_ptr<FrameLoss> MakeFrameLoss(const LossParams& params);

}  // namespace dvpr
