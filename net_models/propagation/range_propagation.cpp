#include "net_models/propagation/range_propagation.h"

#include <cmath>

#include "net_models/core/units.h"
#include "net_models/mobility/ground_distance.h"
#include "net_models/propagation/propagation_params.h"

namespace dvpr {

SimTime AirDelay(double metres) { return SimTime::Nanos(std::llround(metres / kSpeedOfLightMps * 1e9)); }

RangePropagation::RangePropagation(const MobilityModel& mobility, double range_m)
    : mobility_(mobility), range_m_(range_m) {
  PropagationParams params;
  params.range_m = range_m;
  params.Validate();
  name_ = "range(" + FormatMeters(range_m) + ")";
}

void RangePropagation::DoReach(NodeId src, std::span<const NodeId> receivers, SimTime now, std::span<Reception> out) {
  const Position from = mobility_.PositionOf(src, now);
  for (std::size_t i = 0; i < receivers.size(); ++i) {
    const double d = GroundDistance(from, mobility_.PositionOf(receivers[i], now));
    out[i] = d <= range_m_ ? Reception{true, AirDelay(d)} : Reception{false, SimTime::Zero()};
  }
}

}  // namespace dvpr
