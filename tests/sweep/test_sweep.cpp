// Sweep expansion: cross-product counts, order and seeds.
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "experiments/domain/strategies/run_centroids.h"
#include "experiments/sweep/sweep.h"

namespace dvpr {
namespace {

ExperimentConfig Config(const std::string& yaml) {
  return ParseConfig(yaml, DVPR_SOURCE_DIR, {}, "sweep.yaml");
}

TEST(Sweep, CrossProductCounts) {
  const ExperimentConfig c = Config(
      "robots: {from: 2, to: 5}\nruns: 3\nprotocols: [paper, sim]\n"
      "network: {model: [point_to_point, shared_medium], bandwidth: [1Mbps, 10Mbps], "
      "latency: [1ms, 5ms, 9ms]}\n");
  const auto networks = ExpandNetworks(c.network);
  EXPECT_EQ(networks.size(), 2u * 2u * 3u);
  const auto specs = ExpandSweep(c, networks);
  // paper: 4 robot counts x 3 runs; sim: the same for each of the 12 networks.
  EXPECT_EQ(specs.size(), 4u * 3u + 12u * 4u * 3u);
  for (std::size_t i = 0; i < specs.size(); ++i) EXPECT_EQ(specs[i].index, i);
  EXPECT_EQ(specs.front().protocol, "paper");
  EXPECT_EQ(specs.front().network, nullptr);
  EXPECT_EQ(specs.back().protocol, "sim");
  EXPECT_EQ(specs.back().network->params.latency, SimTime::Millis(9));
  ASSERT_EQ(specs.back().strategies.size(), 2u);
  EXPECT_EQ(specs.back().strategies[0].name, "decentralized");
  EXPECT_EQ(specs.back().strategies[1].name, "broadcast");
}

// The radio sweeps its ranges like bandwidths; other models have no radio entries.
TEST(Sweep, RadioRangesAreVariantsOfTheRadioOnly) {
  const ExperimentConfig c = Config(
      "network: {model: [point_to_point, radio], bandwidth: [1Mbps, 10Mbps], "
      "radio: {propagation: range, range: [100m, 0.3km]}}\n");
  const auto v = ExpandNetworks(c.network);
  ASSERT_EQ(v.size(), 2u + 2u * 2u);  // point_to_point per bandwidth, the radio per range and bandwidth
  EXPECT_EQ(NetworkName(v[0].label), "point-to-point 1 Mbit/s 2 ms");
  EXPECT_EQ(NetworkName(v[2].label), "radio 1 Mbit/s 2 ms range 100m");
  EXPECT_EQ(v[2].label.range_m, 100.0);  // the number, beside the text
  EXPECT_EQ(NetworkName(v[3].label), "radio 10 Mbit/s 2 ms range 100m");
  EXPECT_EQ(NetworkName(v[5].label), "radio 10 Mbit/s 2 ms range 300m");
  EXPECT_EQ(v[5].label.range_m, 300.0);
  EXPECT_TRUE(std::isnan(v[0].label.range_m));
  EXPECT_EQ(v[5].params.model, LinkModelKind::kRadio);
  EXPECT_EQ(PropagationOf(v[5].params).range_m, 300.0);
  EXPECT_EQ(PropagationOf(v[2].params).range_m, 100.0);
  EXPECT_FALSE(PropagationOf(v[0].params).NeedsPositions());  // point-to-point: the full mesh
  const ExperimentConfig ld =
      Config("network: {model: radio, radio: {propagation: log_distance, log_distance: {exponent: 2}}}\n");
  const auto w = ExpandNetworks(ld.network);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(NetworkName(w[0].label), "radio 10 Mbit/s 2 ms log_distance");
  EXPECT_TRUE(std::isnan(w[0].label.range_m));
  EXPECT_EQ(PropagationOf(w[0].params).kind, PropagationKind::kLogDistance);
  EXPECT_EQ(PropagationOf(w[0].params).log_distance.exponent, 2.0);
}

// wifi has its own rate: one variant however many bandwidths and latencies the others sweep, its
// label's bandwidth the wifi rate and no latency; over the radio, one per radio entry.
TEST(Sweep, WifiIsOneVariantAtItsOwnRate) {
  const ExperimentConfig c = Config(
      "network: {model: [csma, wifi], bandwidth: [1Mbps, 10Mbps], latency: [1ms, 5ms], wifi: {rate: 54Mbps}}\n");
  const auto v = ExpandNetworks(c.network);
  ASSERT_EQ(v.size(), 2u * 2u + 1u);
  EXPECT_EQ(NetworkName(v[0].label), "csma 1 Mbit/s 1 ms");
  EXPECT_EQ(v[4].params.model, LinkModelKind::kWifi);
  EXPECT_EQ(v[4].params.wifi.rate, DataRate::Mbps(54));
  EXPECT_EQ(v[4].label.bandwidth_bps, 54e6);
  EXPECT_TRUE(std::isnan(v[4].label.latency_ms));
  EXPECT_EQ(NetworkName(v[4].label), "wifi 54 Mbit/s");
  const ExperimentConfig r = Config(
      "network: {model: wifi, wifi: {rate: 6Mbps, propagation: radio}, radio: {range: [100m, 200m]}}\n");
  const auto w = ExpandNetworks(r.network);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(PropagationOf(w[1].params).kind, PropagationKind::kRange);
  EXPECT_EQ(PropagationOf(w[1].params).range_m, 200.0);
  EXPECT_EQ(NetworkName(w[1].label), "wifi 6 Mbit/s range 200m");
  EXPECT_FALSE(PropagationOf(v[4].params).NeedsPositions());  // wifi without propagation radio: the full mesh
}

TEST(Sweep, IdealNetworkIsOneVariant) {
  const ExperimentConfig c =
      Config("network: {model: [ideal, point_to_point], bandwidth: [1Mbps, 2Mbps, 3Mbps]}\n");
  const auto networks = ExpandNetworks(c.network);
  ASSERT_EQ(networks.size(), 4u);
  EXPECT_EQ(networks[0].label.model, "ideal");
  EXPECT_EQ(networks[3].label.bandwidth_bps, 3e6);
  EXPECT_EQ(networks[3].index, 3);
}

// A swept queue or MTU is in the variant's name, so two variants never share one; a single value
// is not named. VariantLabels are ExpandNetworks' labels.
TEST(Sweep, SweptQueuesAndMtusAreNamed) {
  const ExperimentConfig c = Config("network: {model: point_to_point, queue_packets: [8, 100], mtu: 1500B}\n");
  const auto v = ExpandNetworks(c.network);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(NetworkName(v[0].label), "point-to-point 10 Mbit/s 2 ms queue 8 packets");
  EXPECT_EQ(NetworkName(v[1].label), "point-to-point 10 Mbit/s 2 ms queue 100 packets");
  const std::vector<NetworkLabel> labels = VariantLabels(c.network);
  ASSERT_EQ(labels.size(), 2u);
  EXPECT_EQ(labels[1].queue_packets, 100);
  EXPECT_EQ(labels[1].mtu_bytes, 0);
}

// RunSeed(seed, robots, run) = MixSeed(MixSeed(seed, robots), run), worked out independently of
// the C++ by tests/tools/run_seeds.py (a Python SplitMix64): `run_seeds.py 42 2 3 7 --runs 4` and
// `run_seeds.py 43 3 --runs 3`.
const std::map<std::pair<int, int>, std::uint64_t> kSeeds42 = {
    {{2, 0}, 7565664945503846093ULL},  {{2, 1}, 17629773509443312625ULL},
    {{2, 2}, 15895690633813842488ULL}, {{2, 3}, 12014855358635969890ULL},
    {{3, 0}, 1581913778274440802ULL},  {{3, 1}, 6644840181122403294ULL},
    {{3, 2}, 3620815527072446484ULL},  {{3, 3}, 10331844246122223827ULL},
    {{7, 0}, 9051001750061520609ULL},  {{7, 1}, 8950214677219389925ULL},
    {{7, 2}, 17037602249466143853ULL}, {{7, 3}, 2263089242217735002ULL}};

TEST(Sweep, SeedsFromConfigSeedRobotsAndRun) {
  const ExperimentConfig c = Config("seed: 42\nrobots: [2, 3]\nruns: 4\nprotocols: [paper, sim]\n");
  const auto networks = ExpandNetworks(c.network);
  const auto specs = ExpandSweep(c, networks);
  ASSERT_EQ(specs.size(), 2u * 2u * 4u);
  for (const auto& s : specs) {
    // The same (robots, run) has the same seed in paper and sim.
    EXPECT_EQ(s.seed, kSeeds42.at({s.robots, s.run})) << s.protocol << " n=" << s.robots << " run " << s.run;
  }
}

TEST(Sweep, AddingRobotCountsChangesNoOtherSeedAndTheConfigSeedChangesAll) {
  const ExperimentConfig more = Config("seed: 42\nrobots: [2, 3, 7]\nruns: 4\nprotocols: [paper]\n");
  const auto networks = ExpandNetworks(more.network);
  const auto specs = ExpandSweep(more, networks);
  ASSERT_EQ(specs.size(), 3u * 4u);
  for (const auto& s : specs) EXPECT_EQ(s.seed, kSeeds42.at({s.robots, s.run})) << "n=" << s.robots << " run " << s.run;
  const ExperimentConfig other = Config("seed: 43\nrobots: [3]\nruns: 3\nprotocols: [paper]\n");
  const auto other_networks = ExpandNetworks(other.network);
  const auto other_specs = ExpandSweep(other, other_networks);
  ASSERT_EQ(other_specs.size(), 3u);
  EXPECT_EQ(other_specs[0].seed, 7761149020981011001ULL);
  EXPECT_EQ(other_specs[1].seed, 10141735264401666570ULL);
  EXPECT_EQ(other_specs[2].seed, 13757119887038879975ULL);  // seed 42 gave 3620815527072446484
}

}  // namespace
}  // namespace dvpr
