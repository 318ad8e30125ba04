#pragma once
// "log_distance" (ns-3's LogDistancePropagationLossModel): the path loss at ground-plane
// distance d is L0 + 10 n log10(d / d0) (L0 below d0), and a robot hears a transmission iff
// tx_power - loss - shadowing is at least the sensitivity (propagation_params.h). Shadowing, when its
// standard deviation is positive, is a normal draw in dB fixed per unordered pair of robots and
// window of virtual time, taken from (seed, pair, window) alone: both directions and every
// question in a window get the same value, whatever the order of the questions. The air adds
// the distance at the speed of light, as the range model.
#include <cstdint>
#include <string>

#include "net_models/mobility/mobility_model.h"
#include "net_models/propagation/propagation_model.h"
#include "net_models/propagation/propagation_params.h"

namespace dvpr {

class LogDistancePropagation final : public PropagationModel {
 public:
  // Throws std::invalid_argument naming the field of a parameter out of range.
  LogDistancePropagation(const MobilityModel& mobility, const LogDistanceParams& params, std::uint64_t seed);

  // The received power (dBm) at ground-plane distance d, without shadowing.
  double ReceivedDbm(double metres) const;
  // The shadowing (dB) of the pair {a, b} at `now`: 0 when shadowing_db is 0.
  double ShadowingDb(NodeId a, NodeId b, SimTime now) const;

 private:
  void DoReach(NodeId src, std::span<const NodeId> receivers, SimTime now, std::span<Reception> out) override;
  std::string_view DoName() const override { return name_; }

  const MobilityModel& mobility_;
  LogDistanceParams params_;
  std::uint64_t seed_;
  std::string name_;
};

}  // namespace dvpr
