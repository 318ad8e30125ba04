#include "net_models/propagation/log_distance_propagation.h"

#include <algorithm>
#include <cmath>

#include "net_models/core/param_checks.h"
#include "net_models/mobility/ground_distance.h"
#include "net_models/propagation/range_propagation.h"
#include "sim/random.h"

namespace dvpr {

LogDistancePropagation::LogDistancePropagation(const MobilityModel& mobility, const LogDistanceParams& params,
                                               std::uint64_t seed)
    : mobility_(mobility), params_(params), seed_(seed) {
  params_.Validate();
  name_ = "log_distance(n=" + FormatNumber(params_.exponent) + ", " + FormatNumber(params_.sensitivity_dbm) + "dBm)";
}

double LogDistancePropagation::ReceivedDbm(double metres) const {
  double loss = params_.reference_loss_db;
  if (metres > params_.reference_distance_m) {
    loss += 10.0 * params_.exponent * std::log10(metres / params_.reference_distance_m);
  }
  return params_.tx_power_dbm - loss;
}

double LogDistancePropagation::ShadowingDb(NodeId a, NodeId b, SimTime now) const {
  if (params_.shadowing_db == 0.0) return 0.0;
  const auto lo = static_cast<std::uint64_t>(std::min(a.value, b.value));
  const auto hi = static_cast<std::uint64_t>(std::max(a.value, b.value));
  const auto window = static_cast<std::uint64_t>(std::floor(now.ToSeconds() / params_.shadowing_window_s));
  RandomStream draw(seed_, MixSeed(MixSeed(MixSeed(ComponentId("log_distance/shadowing"), lo), hi), window));
  return params_.shadowing_db * draw.Normal();
}

void LogDistancePropagation::DoReach(NodeId src, std::span<const NodeId> receivers, SimTime now,
                                     std::span<Reception> out) {
  const Position from = mobility_.PositionOf(src, now);
  for (std::size_t i = 0; i < receivers.size(); ++i) {
    const double d = GroundDistance(from, mobility_.PositionOf(receivers[i], now));
    const double received = ReceivedDbm(d) - ShadowingDb(src, receivers[i], now);
    out[i] = received >= params_.sensitivity_dbm ? Reception{true, AirDelay(d)} : Reception{false, SimTime::Zero()};
  }
}

}  // namespace dvpr
