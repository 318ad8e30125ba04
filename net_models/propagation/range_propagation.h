#pragma once
// "range" (ns-3's RangePropagationLossModel): a robot hears a transmission iff its ground-plane
// distance to the sender, when the message is sent, is at most the range; the air adds that
// distance at the speed of light (ns-3's ConstantSpeedPropagationDelayModel), to the ns.
#include <string>

#include "net_models/mobility/mobility_model.h"
#include "net_models/propagation/propagation_model.h"

namespace dvpr {

inline constexpr double kSpeedOfLightMps = 299792458.0;

// distance / c, rounded to the nearest ns.
SimTime AirDelay(double metres);

class RangePropagation final : public PropagationModel {
 public:
  // Throws std::invalid_argument "range: must be in (0, 1e9], got <range_m>".
  RangePropagation(const MobilityModel& mobility, double range_m);

 private:
  void DoReach(NodeId src, std::span<const NodeId> receivers, SimTime now, std::span<Reception> out) override;
  std::string_view DoName() const override { return name_; }

  const MobilityModel& mobility_;
  double range_m_;
  std::string name_;  // "range(200m)"
};

}  // namespace dvpr
