#include "net_models/propagation/loss_params.h"

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace dvpr {
namespace {

constexpr std::array<std::pair<LossModelKind, std::string_view>, 3> kNames{{
    {LossModelKind::kNone, "none"},
    {LossModelKind::kBernoulli, "bernoulli"},
    {LossModelKind::kGilbertElliott, "gilbert_elliott"},
}};

}  // namespace

LossModelKind ParseLossModelKind(std::string_view name) {
  std::string expected;
  for (const auto& [kind, spelling] : kNames) {
    if (spelling == name) return kind;
    expected += (expected.empty() ? "" : ", ") + std::string(spelling);
  }
  throw std::invalid_argument("unknown value '" + std::string(name) + "' (expected one of: " + expected + ")");
}

std::string_view ToString(LossModelKind kind) {
  for (const auto& [k, spelling] : kNames) {
    if (k == kind) return spelling;
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

}  // namespace dvpr
