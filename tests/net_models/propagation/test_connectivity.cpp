// Who reaches whom (net_models/propagation/connectivity.h): small hand-made teams whose graphs are worked
// out by hand.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "net_models/mobility/fixed_mobility.h"
#include "net_models/mobility/track_mobility.h"
#include "net_models/propagation/connectivity.h"
#include "net_models/propagation/range_propagation.h"

namespace dvpr {
namespace {

// 4 robots on a line 150 m apart, range 200 m: 0-1, 1-2, 2-3 in range (300 m and more is not).
TEST(Connectivity, ALineOfFourIsOneComponentThreeHopsLong) {
  const FixedMobility line({Position{0, 0, 0}, Position{150, 0, 0}, Position{300, 0, 0}, Position{450, 0, 0}});
  RangePropagation range(line, 200.0);
  const ConnectivitySnapshot s = ConnectivityAt(range, 4, SimTime::Seconds(1));
  EXPECT_EQ(s.at, SimTime::Seconds(1));
  EXPECT_EQ(s.pairs_in_range, 3);
  EXPECT_EQ(s.components, 1);
  EXPECT_TRUE(s.connected());
  EXPECT_EQ(s.largest_component, 4);
  EXPECT_EQ(s.max_hops, 3);
  // Ordered pairs: 6 at 1 hop, 4 at 2, 2 at 3: (3*1 + 2*2 + 1*3) * 2 / 12 = 20 / 12.
  EXPECT_DOUBLE_EQ(s.mean_hops, 20.0 / 12.0);
  EXPECT_EQ(s.in_range, (std::vector<int>{1, 2, 2, 1}));  // the ends have one neighbour
}

// {0, 1, 2} within 100 m of each other, {3, 4} 50 m apart, the clusters 1 km apart.
TEST(Connectivity, TwoClustersAreTwoComponents) {
  const FixedMobility m({Position{0, 0, 0}, Position{100, 0, 0}, Position{50, 0, 50}, Position{1000, 0, 0},
                         Position{1000, 0, 50}});
  RangePropagation range(m, 120.0);
  const ConnectivitySnapshot s = ConnectivityAt(range, 5, SimTime::Zero());
  EXPECT_EQ(s.pairs_in_range, 4);  // 0-1, 0-2 (70.7 m), 1-2 (70.7 m), 3-4
  EXPECT_EQ(s.components, 2);
  EXPECT_FALSE(s.connected());
  EXPECT_EQ(s.largest_component, 3);
  EXPECT_EQ(s.max_hops, 1);
  EXPECT_DOUBLE_EQ(s.mean_hops, 1.0);  // 8 ordered pairs, each one hop
  EXPECT_EQ(s.in_range, (std::vector<int>{2, 2, 2, 1, 1}));
}

TEST(Connectivity, NobodyInRangeHasNoHops) {
  const FixedMobility m({Position{0, 0, 0}, Position{500, 0, 0}, Position{0, 0, 500}});
  RangePropagation range(m, 100.0);
  const ConnectivitySnapshot s = ConnectivityAt(range, 3, SimTime::Zero());
  EXPECT_EQ(s.pairs_in_range, 0);
  EXPECT_EQ(s.components, 3);
  EXPECT_EQ(s.largest_component, 1);
  EXPECT_EQ(s.mean_hops, 0.0);
  EXPECT_EQ(s.max_hops, 0);
  EXPECT_EQ(s.in_range, (std::vector<int>{0, 0, 0}));
  const ConnectivitySnapshot alone = ConnectivityAt(range, 1, SimTime::Zero());
  EXPECT_TRUE(alone.connected());
  EXPECT_EQ(alone.largest_component, 1);
}

// Robot 1 drives from 300 m to 100 m from robot 0 over 2 s (100 m/s): out of a 150 m range
// until t = 1.5 s, in range from then on.
TEST(Connectivity, OverTimeFollowsTheTracks) {
  const TrackMobility m({{Waypoint{SimTime::Zero(), Position{0, 0, 0}}},
                         {Waypoint{SimTime::Zero(), Position{300, 0, 0}},
                          Waypoint{SimTime::Seconds(2), Position{100, 0, 0}}}});
  RangePropagation range(m, 150.0);
  const auto over = ConnectivityOver(range, 2, SimTime::Millis(500), SimTime::Seconds(2.2));
  ASSERT_EQ(over.size(), 5u);  // 0, 0.5, 1, 1.5, 2 s
  const std::vector<int> expected_pairs{0, 0, 0, 1, 1};
  for (std::size_t i = 0; i < over.size(); ++i) {
    EXPECT_EQ(over[i].at, SimTime::Millis(500) * static_cast<std::int64_t>(i));
    EXPECT_EQ(over[i].pairs_in_range, expected_pairs[i]) << i;
    EXPECT_EQ(over[i].components, 2 - expected_pairs[i]) << i;
  }
  EXPECT_EQ(ConnectivityOver(range, 2, SimTime::Seconds(1), SimTime::Zero()).size(), 1u);
  EXPECT_THROW(ConnectivityOver(range, 2, SimTime::Zero(), SimTime::Seconds(1)), std::invalid_argument);
  EXPECT_THROW(ConnectivityAt(range, 0, SimTime::Zero()), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
