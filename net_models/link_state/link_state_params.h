#pragma once
// The parameters of `link_state` routing (config: network.routing {kind: link_state, hello,
// topology}; link_state_routing.h): how often each robot beacons. The defaults and the hold
// times are OLSR's (RFC 3626, section 18.3): HELLO_INTERVAL 2 s, TC_INTERVAL 5 s, and what a
// robot heard is kept three periods (NEIGHB_HOLD_TIME = 3 x HELLO_INTERVAL, TOP_HOLD_TIME =
// 3 x TC_INTERVAL), so one lost beacon does not break a route.
#include "sim/sim_time.h"

namespace dvpr {

struct LinkStateParams {
  // A period of up to an hour (a beacon an hour tells a moving team nothing).
  static constexpr SimTime kMaxPeriod = SimTime::Millis(3600LL * 1000);
  static constexpr int kHoldPeriods = 3;

  SimTime hello = SimTime::Millis(2000);     // each robot's HELLO to the robots that hear it
  SimTime topology = SimTime::Millis(5000);  // each robot's topology flood to the team

  SimTime NeighborHold() const { return SimTime::Nanos(kHoldPeriods * hello.ns()); }
  SimTime TopologyHold() const { return SimTime::Nanos(kHoldPeriods * topology.ns()); }
  // Throws std::invalid_argument "<field>: ..." ("hello: must be in [1ns, 1h], got 0s").
  void Validate() const;
  bool operator==(const LinkStateParams&) const = default;
};

}  // namespace dvpr
