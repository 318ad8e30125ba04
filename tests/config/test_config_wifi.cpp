// network.model csma and wifi and the network.wifi section (docs/config.md): read, written back
// only for a wifi config, and every bad value one error naming its key.
#include <string>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "tests/config/config_test_support.h"

namespace dvpr {
namespace {

using testing_support::ErrorOf;
using testing_support::Parse;
using testing_support::starts_with;

TEST(ConfigWifiTest, WifiKeysAreReadWithNs3Defaults) {
  const ExperimentConfig c = Parse("network: {model: [csma, wifi], wifi: {rate: 54Mbps}}\n");
  EXPECT_EQ(c.network.wifi.rate, DataRate::Mbps(54));
  EXPECT_EQ(c.network.wifi.basic_rate, DataRate::Mbps(6));  // not given: 802.11a's lowest
  EXPECT_EQ(c.network.wifi_propagation, std::vector<PropagationParams>{PropagationParams{}});  // the full mesh
  const ExperimentConfig r =
      Parse("network: {model: wifi, wifi: {rate: 6Mbps, basic_rate: 12Mbps, propagation: radio}, radio: {range: 150m}}\n");
  EXPECT_EQ(r.network.wifi.basic_rate, DataRate::Mbps(12));
  EXPECT_EQ(r.network.wifi_propagation, r.network.radio);  // the radio's entries
  ASSERT_EQ(r.network.radio.size(), 1u);
  EXPECT_EQ(r.network.radio[0].range_m, 150.0);
}

TEST(ConfigWifiTest, WifiConfigReadsBackAndOthersAreWrittenWithoutTheSection) {
  for (const char* yaml : {"network: {model: wifi, wifi: {rate: 24Mbps}}\n",
                           "network: {model: wifi, wifi: {rate: 9Mbps, propagation: radio}, radio: {range: 90m}}\n",
                           "network: {model: [shared_medium, csma]}\n"}) {
    const ExperimentConfig c = Parse(yaml);
    const std::string emitted = EmitConfig(c);
    EXPECT_EQ(ParseConfig(emitted, "/nonexistent", {}, "config.yaml"), c) << emitted;
  }
  EXPECT_EQ(EmitConfig(Parse("{}")).find("\n  wifi:"), std::string::npos);
}

TEST(ConfigWifiTest, BadWifiValuesAreOneErrorNamingTheKey) {
  // A rate outside 802.11a's set, for data and for the basic rate.
  starts_with(ErrorOf("network: {model: wifi, wifi: {rate: 11Mbps}}\n"), "test.yaml: network.wifi");
  EXPECT_NE(ErrorOf("network: {model: wifi, wifi: {rate: 11Mbps}}\n").find("6, 9, 12, 18, 24, 36, 48, 54"),
            std::string::npos);
  starts_with(ErrorOf("network: {model: wifi, wifi: {rate: 54Mbps, basic_rate: 5Mbps}}\n"), "test.yaml: network.wifi");
  // A wifi model without its rate, or without the section at all.
  starts_with(ErrorOf("network: {model: wifi, wifi: {basic_rate: 6Mbps}}\n"), "test.yaml: network.wifi.rate: ");
  starts_with(ErrorOf("network: {model: wifi}\n"), "test.yaml: network.wifi: model wifi needs this section");
  // The section without the model, an unknown key, an unknown propagation.
  starts_with(ErrorOf("network: {model: point_to_point, wifi: {rate: 54Mbps}}\n"),
              "test.yaml: network.wifi: applies to model wifi");
  starts_with(ErrorOf("network: {model: wifi, wifi: {rate: 54Mbps, slots: -3}}\n"), "test.yaml: network.wifi");
  starts_with(ErrorOf("network: {model: wifi, wifi: {rate: 54Mbps, propagation: air}}\n"),
              "test.yaml: network.wifi.propagation: ");
  // A loss model on a medium access that decides later, and the radio section on a full mesh.
  starts_with(ErrorOf("network: {model: csma, loss: {model: bernoulli, p: 0.1}}\n"),
              "test.yaml: network.loss: a loss model needs a medium access that decides at send time, not model csma");
  starts_with(ErrorOf("network: {model: wifi, wifi: {rate: 54Mbps}, loss: {model: bernoulli, p: 0.1}}\n"),
              "test.yaml: network.loss: ");
  starts_with(ErrorOf("network: {model: wifi, wifi: {rate: 54Mbps}, radio: {range: 100m}}\n"),
              "test.yaml: network.radio: applies to model radio, or wifi with propagation radio");
  // A negative queue.
  starts_with(ErrorOf("network: {model: csma, queue_packets: -1}\n"), "test.yaml: network.queue_packets: ");
}

}  // namespace
}  // namespace dvpr
