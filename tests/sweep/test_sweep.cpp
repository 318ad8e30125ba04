// Sweep expansion: cross-product counts, order and seeds.
#include <set>

#include <gtest/gtest.h>

#include "sim/random_bits.h"
#include "experiments/config/config.h"
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
  EXPECT_EQ(specs.back().strategies, (std::vector<std::string>{"decentralized", "broadcast"}));
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

TEST(Sweep, SeedsFromConfigSeedRobotsAndRun) {
  const ExperimentConfig c = Config("seed: 42\nrobots: [2, 3]\nruns: 4\nprotocols: [paper, sim]\n");
  const auto networks = ExpandNetworks(c.network);
  const auto specs = ExpandSweep(c, networks);
  std::set<std::uint64_t> distinct;
  for (const auto& s : specs) {
    EXPECT_EQ(s.seed, MixSeed(MixSeed(42, static_cast<std::uint64_t>(s.robots)),
                              static_cast<std::uint64_t>(s.run)));
    distinct.insert(s.seed);
  }
  EXPECT_EQ(distinct.size(), 2u * 4u);  // same (robots, run) -> same seed in paper and sim
  // Adding robot counts changes no existing seed.
  const ExperimentConfig more = Config("seed: 42\nrobots: [2, 3, 7]\nruns: 4\n");
  EXPECT_EQ(RunSeed(42, 3, 2), RunSeed(more.seed, 3, 2));
  EXPECT_NE(RunSeed(42, 3, 2), RunSeed(43, 3, 2));
}

}  // namespace
}  // namespace dvpr
