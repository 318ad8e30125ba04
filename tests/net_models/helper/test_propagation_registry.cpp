// A third propagation model is its class and one registration line: the test's wall (a robot
// hears another only on its own side of the plane x = 0) is registered for the scope of a test,
// named in a network's parameters like the shipped ones, and built by MakeNetworkStack, which
// knows none of them by name (propagation_registry.h).
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "net_models/helper/network_helper.h"
#include "net_models/mobility/fixed_mobility.h"
#include "net_models/network/network.h"
#include "net_models/propagation/propagation_registry.h"
#include "sim/simulator.h"
#include "tests/net_models/copy_log.h"

namespace dvpr {
namespace {

constexpr PropagationKind kWall{"test_wall"};

class WallPropagation final : public PropagationModel {
 public:
  explicit WallPropagation(const MobilityModel& mobility) : mobility_(mobility) {}

 private:
  void DoReach(NodeId src, std::span<const NodeId> receivers, SimTime now, std::span<Reception> out) override {
    const bool west = mobility_.PositionOf(src, now).x < 0;
    for (std::size_t i = 0; i < receivers.size(); ++i) {
      out[i].reaches = (mobility_.PositionOf(receivers[i], now).x < 0) == west;
    }
  }
  std::string_view DoName() const override { return "test_wall"; }
  bool DoChangesOverTime() const override { return false; }
  const MobilityModel& mobility_;
};

PropagationModelInfo WallInfo() {
  return {kWall, true, [](const PropagationParams&, const MobilityModel& m, std::uint64_t) {
            return std::make_unique<WallPropagation>(m);
          }};
}

// A radio at 1 Mbit/s with 5 ms latency over the named propagation; robots 0 and 1 west of the
// wall, robot 2 east of it.
NetworkModelParams RadioOver(PropagationKind kind) {
  NetworkModelParams p;
  p.model = LinkModelKind::kRadio;
  p.bandwidth = DataRate::Mbps(1);
  p.latency = SimTime::Millis(5);
  p.propagation = PropagationParams{.kind = kind};
  return p;
}

std::unique_ptr<MobilityModel> ThreeRobots() {
  return std::make_unique<FixedMobility>(std::vector<Position>{{-10, 0, 0}, {-20, 0, 0}, {10, 0, 0}});
}

TEST(PropagationRegistry, ARegisteredModelIsBuiltByNameAndDecidesWhoHears) {
  const PropagationRegistration wall(WallInfo());  // the one registration line
  EXPECT_EQ(ParsePropagationKind("test_wall"), kWall);

  Simulator sim;
  Network net(sim, 3, MakeNetworkStack(RadioOver(kWall), 3, /*run_seed=*/1, ThreeRobots()));
  EXPECT_EQ(net.propagation().Name(), "test_wall");
  testing_support::CopyLog log;
  const ObserverSubscription subscription = net.Subscribe(log);
  const ChannelId all = net.InternChannel("ALL");
  const MessageTypeId type = net.InternType("dvpr.test_t");
  for (int i = 0; i < 3; ++i) net.Join(NodeId(i), all);
  // 505 bytes of payload are a 547-byte frame: 4.376 ms at 1 Mbit/s, then 5 ms of latency. The
  // robot west of the wall hears it; the one east of it does not (when the frame starts).
  net.Send(NodeId(0), all, type, std::vector<std::uint8_t>(505, 1));
  sim.Run();
  EXPECT_EQ(log.lines, (std::vector<std::string>{"0>2 at 0ns: out_of_range", "0>1 delivered at 9376000ns"}));
}

TEST(PropagationRegistry, AModelGoneOrTakenIsRefusedByName) {
  {
    const PropagationRegistration wall(WallInfo());
    EXPECT_THROW(PropagationRegistry::Global().Add(WallInfo()), std::logic_error);  // the name is taken
    EXPECT_THROW(PropagationRegistry::Global().Add({PropagationKind{"test_empty"}, true, {}}), std::logic_error);
  }
  // Out of its scope the wall is unknown again, to the config's names and to the helper.
  try {
    ParsePropagationKind("test_wall");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown value 'test_wall' (expected one of: range, log_distance)");
  }
  try {
    (void)MakeNetworkStack(RadioOver(kWall), 3, 1, ThreeRobots());
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "propagation: unknown model 'test_wall'");
  }
  // The shipped models stay, in their order.
  std::vector<std::string> names;
  for (const PropagationModelInfo& m : PropagationRegistry::Global().models()) names.emplace_back(m.kind.name());
  EXPECT_EQ(names, (std::vector<std::string>{"full_mesh", "range", "log_distance"}));
}

}  // namespace
}  // namespace dvpr
