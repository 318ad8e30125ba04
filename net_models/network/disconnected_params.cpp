#include "net_models/network/disconnected_params.h"

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

#include "net_models/core/param_checks.h"

namespace dvpr {
namespace {

constexpr std::array<std::pair<DisconnectedKind, std::string_view>, 2> kNames{{
    {DisconnectedKind::kDrop, "drop"},
    {DisconnectedKind::kStoreAndForward, "store_and_forward"},
}};

}  // namespace

DisconnectedKind ParseDisconnectedKind(std::string_view name) {
  std::string expected;
  for (const auto& [kind, spelling] : kNames) {
    if (spelling == name) return kind;
    expected += (expected.empty() ? "" : ", ") + std::string(spelling);
  }
  throw std::invalid_argument("unknown value '" + std::string(name) + "' (expected one of: " + expected + ")");
}

std::string_view ToString(DisconnectedKind kind) {
  for (const auto& [k, spelling] : kNames) {
    if (k == kind) return spelling;
  }
  return "unknown";
}

void DisconnectedParams::Validate() const {
  if (hold_bytes < Bytes(1) || hold_bytes > kMaxHoldBytes) {
    InvalidParam("hold_bytes", "must be in [1B, " + ToString(kMaxHoldBytes) + "], got " + ToString(hold_bytes));
  }
  if (hold_time <= SimTime::Zero() || hold_time > kMaxHoldTime) {
    InvalidParam("hold_time", "must be in (0s, " + FormatDuration(kMaxHoldTime) + "], got " + FormatDuration(hold_time));
  }
  if (retry <= SimTime::Zero() || retry > kMaxHoldTime) {
    InvalidParam("retry", "must be in (0s, " + FormatDuration(kMaxHoldTime) + "], got " + FormatDuration(retry));
  }
}

}  // namespace dvpr
