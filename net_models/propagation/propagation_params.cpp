#include "net_models/propagation/propagation_params.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "net_models/core/param_checks.h"
#include "net_models/propagation/propagation_registry.h"

namespace dvpr {
namespace {

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
  for (const PropagationModelInfo& m : PropagationRegistry::Global().models()) {
    if (!m.needs_positions && !with_full_mesh) continue;
    if (m.kind.name() == name) return m.kind;
    expected += (expected.empty() ? "" : ", ") + std::string(m.kind.name());
  }
  throw std::invalid_argument("unknown value '" + std::string(name) + "' (expected one of: " + expected + ")");
}

bool PropagationParams::NeedsPositions() const {
  const PropagationModelInfo* m = PropagationRegistry::Global().Find(kind);
  return m == nullptr || m->needs_positions;  // an unknown kind: MakePropagation refuses it
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
