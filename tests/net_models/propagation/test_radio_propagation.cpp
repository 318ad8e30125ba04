// The radio's propagation models (net_models/propagation/range_propagation.h, log_distance_propagation.h)
// and their parameters, on robots placed by hand, against values worked out in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "net_models/mobility/fixed_mobility.h"
#include "net_models/propagation/log_distance_propagation.h"
#include "net_models/propagation/propagation_params.h"
#include "net_models/propagation/range_propagation.h"

namespace dvpr {
namespace {

std::vector<Reception> Reach(PropagationModel& m, int src, std::vector<NodeId> receivers, SimTime now = {}) {
  std::vector<Reception> out(receivers.size());
  m.Reach(NodeId(src), receivers, now, out);
  return out;
}

TEST(RangePropagation, HearsUpToTheRangeOnTheGroundPlaneWithTheAirsDelay) {
  // Robot 1 150 m away along x; robot 2 exactly 200 m away (120, 160) in x-z; robot 3 200.001 m
  // away along z; robot 4 150 m along x but 1 km up (y points down: ignored).
  const FixedMobility m({{0, 0, 0}, {150, 0, 0}, {120, 0, 160}, {0, 0, 200.001}, {150, -1000, 0}});
  RangePropagation r(m, 200.0);
  EXPECT_EQ(r.Name(), "range(200m)");
  const auto out = Reach(r, 0, {NodeId(1), NodeId(2), NodeId(3), NodeId(4)});
  EXPECT_TRUE(out[0].reaches);
  EXPECT_EQ(out[0].delay, SimTime::Nanos(500));  // 150 / 299792458 s = 500.35 ns
  EXPECT_TRUE(out[1].reaches);
  EXPECT_EQ(out[1].delay, SimTime::Nanos(667));  // 200 / c = 667.13 ns
  EXPECT_FALSE(out[2].reaches);
  EXPECT_TRUE(out[3].reaches);
  EXPECT_EQ(out[3].delay, SimTime::Nanos(500));
}

TEST(RangePropagation, RefusesARangeThatIsNotPositiveAndFinite) {
  const FixedMobility m({{0, 0, 0}});
  for (const double bad : {0.0, -1.0, std::nan(""), 2e9}) {
    try {
      RangePropagation(m, bad);
      ADD_FAILURE() << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("range: must be in (0, 1000000000], got ", 0), 0u) << e.what();
    }
  }
}

// ns-3's defaults: 16.0206 dBm sent, 46.6777 dB at 1 m, exponent 3, heard from -82 dBm.
TEST(LogDistancePropagation, ReceivedPowerIsNs3sLogDistanceLoss) {
  const FixedMobility m({{0, 0, 0}, {10, 0, 0}, {60, 0, 0}, {0, 0, 0.5}, {51, 0, 0}, {52, 0, 0}});
  LogDistancePropagation p(m, LogDistanceParams{}, 1);
  // 10 m: 46.6777 + 30 log10(10) = 76.6777 dB; 16.0206 - 76.6777 = -60.6571 dBm.
  EXPECT_NEAR(p.ReceivedDbm(10), -60.6571, 1e-9);
  // 60 m: 46.6777 + 30 x 1.778151 = 100.0222 dB; -84.0016 dBm.
  EXPECT_NEAR(p.ReceivedDbm(60), -84.00155, 1e-4);
  // Below the reference distance the loss stays 46.6777 dB: -30.6571 dBm.
  EXPECT_NEAR(p.ReceivedDbm(0.5), -30.6571, 1e-9);
  // Heard iff at least -82 dBm: up to 10^((16.0206 - 46.6777 + 82) / 30) = 10^1.71143 = 51.455 m.
  EXPECT_NEAR(LogDistanceParams{}.MeanRangeM(), 51.4553, 1e-3);
  const auto out = Reach(p, 0, {NodeId(1), NodeId(2), NodeId(3), NodeId(4), NodeId(5)});
  EXPECT_TRUE(out[0].reaches);
  EXPECT_EQ(out[0].delay, SimTime::Nanos(33));  // 10 m / c = 33.36 ns
  EXPECT_FALSE(out[1].reaches);
  EXPECT_TRUE(out[2].reaches);
  EXPECT_TRUE(out[3].reaches);   // 51 m
  EXPECT_FALSE(out[4].reaches);  // 52 m
}

TEST(LogDistancePropagation, ShadowingIsFixedPerPairAndWindowAndNormal) {
  std::vector<Position> line;
  for (int i = 0; i < 200; ++i) line.push_back(Position{static_cast<double>(i), 0, 0});
  const FixedMobility m(line);
  LogDistanceParams params;
  params.shadowing_db = 4.0;
  params.shadowing_window_s = 2.0;
  const LogDistancePropagation p(m, params, 7);
  // Both directions and the whole window [2 s, 4 s) see one value; the next window another.
  const double s = p.ShadowingDb(NodeId(3), NodeId(9), SimTime::Seconds(2.0));
  EXPECT_EQ(p.ShadowingDb(NodeId(9), NodeId(3), SimTime::Seconds(3.999)), s);
  EXPECT_NE(p.ShadowingDb(NodeId(3), NodeId(9), SimTime::Seconds(4.0)), s);
  EXPECT_NE(LogDistancePropagation(m, params, 8).ShadowingDb(NodeId(3), NodeId(9), SimTime::Seconds(2.0)), s);
  // Over the 19900 pairs of 200 robots the draws have mean 0 and standard deviation 4 dB: the
  // sample mean's standard error is 4 / sqrt(19900) = 0.028 dB, the deviation's about 0.02 dB;
  // the bounds are over 7 standard errors wide (and the seed is fixed, so this never flakes).
  double sum = 0, squares = 0;
  int n = 0;
  for (int a = 0; a < 200; ++a) {
    for (int b = a + 1; b < 200; ++b) {
      const double x = p.ShadowingDb(NodeId(a), NodeId(b), SimTime::Zero());
      sum += x;
      squares += x * x;
      ++n;
    }
  }
  const double mean = sum / n;
  EXPECT_NEAR(mean, 0.0, 0.2);
  EXPECT_NEAR(std::sqrt(squares / n - mean * mean), 4.0, 0.15);
  // Without shadowing the answer is the path loss alone.
  const LogDistancePropagation none(m, LogDistanceParams{}, 7);
  EXPECT_EQ(none.ShadowingDb(NodeId(3), NodeId(9), SimTime::Seconds(2.0)), 0.0);
}

TEST(PropagationParams, NamesAndBadValuesNameTheirField) {
  EXPECT_EQ(ParsePropagationKind("range"), PropagationKind::kRange);
  // The full mesh only where asked for: a radio's propagation is over positions.
  EXPECT_EQ(ParsePropagationKind("full_mesh", /*with_full_mesh=*/true), PropagationKind::kFullMesh);
  EXPECT_THROW(ParsePropagationKind("full_mesh"), std::invalid_argument);
  EXPECT_FALSE(PropagationParams{}.NeedsPositions());
  EXPECT_TRUE(PropagationParams::Radio().NeedsPositions());
  EXPECT_EQ(PropagationParams::Radio().range_m, 200.0);
  EXPECT_EQ(ParsePropagationKind("log_distance"), PropagationKind::kLogDistance);
  EXPECT_EQ(ToString(PropagationKind::kLogDistance), "log_distance");
  try {
    ParsePropagationKind("two_ray");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown value 'two_ray' (expected one of: range, log_distance)");
  }
  const auto error_of = [](PropagationParams r) {
    try {
      r.Validate();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(none)");
  };
  PropagationParams r;
  EXPECT_EQ(error_of(r), "(none)");
  r.log_distance.exponent = 0.5;
  EXPECT_EQ(error_of(r), "log_distance.exponent: must be in [1, 10], got 0.5");
  r = PropagationParams{};
  r.log_distance.shadowing_db = std::nan("");
  EXPECT_EQ(error_of(r).rfind("log_distance.shadowing_db: must be in [0, 30], got ", 0), 0u);
  r = PropagationParams{};
  r.log_distance.reference_distance_m = 0;
  EXPECT_EQ(error_of(r), "log_distance.reference_distance: must be in (0, 1000000000], got 0");
  r = PropagationParams{};
  r.range_m = -3;
  EXPECT_EQ(error_of(r), "range: must be in (0, 1000000000], got -3");
}

}  // namespace
}  // namespace dvpr
