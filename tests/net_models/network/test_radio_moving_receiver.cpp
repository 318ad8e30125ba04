// A receiver that leaves range while a frame is sent does not get it (docs/network_model.md,
// "The radio"): robot 1 drives away from robot 0 at 10 m/s, from 190 m at 0 s, and is 200 m
// away - the edge of the range - at 1 s. A 505-byte message on "ALL" is a 547-byte frame, on the
// air 4.376 ms at 1 Mbit/s, then 2 ms of processing.
//
// Sent at 0.995 s: robot 1 is 199.95 m away when it starts and 199.99376 m when it ends; it
// arrives at 0.995 s + 4.376 ms + 2 ms + 667 ns (199.95 m at the speed of light) = 1 001 376 667 ns.
// Sent at 0.996 s, 199.96 m away: in range then, but it waits for the first frame and ends at
// 1.003752 s, when robot 1 is 200.03752 m away: lost out of range.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "net_models/medium/radio_link.h"
#include "net_models/mobility/track_mobility.h"
#include "net_models/network/network.h"
#include "net_models/propagation/range_propagation.h"
#include "sim/simulator.h"
#include "tests/net_models/copy_log.h"

namespace dvpr {
namespace {

NetworkStack DrivingAway() {
  NetworkStack s;
  s.mobility = std::make_unique<TrackMobility>(std::vector<std::vector<Waypoint>>{
      {{SimTime::Zero(), {0, 0, 0}}},
      {{SimTime::Zero(), {190, 0, 0}}, {SimTime::Millis(10000), {290, 0, 0}}}});
  s.propagation = std::make_unique<RangePropagation>(*s.mobility, 200.0);
  s.access = std::make_unique<RadioLink>(RadioLinkParams{DataRate::Mbps(1), SimTime::Millis(2), 100}, 2);
  return s;
}

TEST(RadioMovingReceiver, AFrameIsHeardOnlyIfTheReceiverIsInRangeWhenItEnds) {
  Simulator sim;
  Network net(sim, 2, DrivingAway());
  testing_support::CopyLog log;
  const ObserverSubscription sub = net.Subscribe(log);
  const ChannelId all = net.InternChannel("ALL");
  const MessageTypeId type = net.InternType("dvpr.test_t");
  net.Join(NodeId(1), all);
  for (const std::int64_t ms : {995, 996}) {
    sim.ScheduleAt(SimTime::Millis(ms), [&] { net.Send(NodeId(0), all, type, std::vector<std::uint8_t>(505, 1)); });
  }
  sim.Run();
  EXPECT_EQ(log.lines, (std::vector<std::string>{"0>1 at 996000000ns: out_of_range",
                                                 "0>1 delivered at 1001376667ns"}));
}

}  // namespace
}  // namespace dvpr
