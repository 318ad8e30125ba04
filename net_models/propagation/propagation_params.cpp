#include "net_models/propagation/propagation_params.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "net_models/core/param_checks.h"

namespace dvpr {
namespace {

constexpr std::array<std::pair<PropagationKind, std::string_view>, 3> kNames{{
    {PropagationKind::kFullMesh, "full_mesh"},
    {PropagationKind::kRange, "range"},
    {PropagationKind::kLogDistance, "log_distance"},
}};

// lo <= v <= hi (NaN fails), or lo < v when low_open.
void CheckNumber(std::string_view field, double v, double lo, double hi, bool low_open = false) {
  const bool ok = std::isfinite(v) && (low_open ? v > lo : v >= lo) && v <= hi;
  if (ok) return;
  InvalidParam(field, "must be in " + std::string(low_open ? "(" : "[") + FormatNumber(lo) + ", " + FormatNumber(hi) +
                          "], got " + FormatNumber(v));
}

}  // namespace

PropagationKind ParsePropagationKind(std::string_view name, bool with_full_mesh) {
  std::string expected;
  for (const auto& [kind, spelling] : kNames) {
    if (kind == PropagationKind::kFullMesh && !with_full_mesh) continue;
    if (spelling == name) return kind;
    expected += (expected.empty() ? "" : ", ") + std::string(spelling);
  }
  throw std::invalid_argument("unknown value '" + std::string(name) + "' (expected one of: " + expected + ")");
}

std::string_view ToString(PropagationKind kind) {
  for (const auto& [k, spelling] : kNames) {
    if (k == kind) return spelling;
  }
  return "unknown";
}

// Received power tx - L(d) equals the sensitivity where L(d) = tx - sensitivity, so
// 10 n log10(d / d0) = tx - sensitivity - L0.
double LogDistanceParams::MeanRangeM() const {
  return reference_distance_m * std::pow(10.0, (tx_power_dbm - reference_loss_db - sensitivity_dbm) / (10.0 * exponent));
}

void LogDistanceParams::Validate() const {
  CheckNumber("exponent", exponent, 1.0, 10.0);
  CheckNumber("reference_distance", reference_distance_m, 0.0, PropagationParams::kMaxRangeM, /*low_open=*/true);
  CheckNumber("reference_loss_db", reference_loss_db, 0.0, 300.0);
  CheckNumber("tx_power_dbm", tx_power_dbm, -200.0, 100.0);
  CheckNumber("sensitivity_dbm", sensitivity_dbm, -200.0, 100.0);
  CheckNumber("shadowing_db", shadowing_db, 0.0, 30.0);
  CheckNumber("shadowing_window", shadowing_window_s, 0.0, 86400.0, /*low_open=*/true);
}

void PropagationParams::Validate() const {
  CheckNumber("range", range_m, 0.0, kMaxRangeM, /*low_open=*/true);
  ValidateNested("log_distance.", [&] { log_distance.Validate(); });
}

}  // namespace dvpr
