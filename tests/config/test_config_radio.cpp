// network.model radio and its network.radio section (docs/config.md): read (a `range` list is
// one entry per range; tests/sweep expands them into network variants), written back only for
// a radio config, and every bad value one error naming its key.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "tests/config/config_test_support.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

using testing_support::ErrorOf;
using testing_support::Parse;
// The error begins with `prefix` (the file, the key and the start of the problem).
using testing_support::starts_with;

TEST(ConfigRadioTest, ARangeListIsOneEntryPerRange) {
  const ExperimentConfig c = Parse(
      "network: {model: [point_to_point, radio], bandwidth: 1Mbps, radio: {propagation: range, range: [100m, 0.3km]}}\n");
  ASSERT_EQ(c.network.radio.size(), 2u);
  EXPECT_EQ(c.network.radio[0].range_m, 100.0);
  EXPECT_EQ(c.network.radio[1].range_m, 300.0);
}

TEST(ConfigRadioTest, LogDistanceKeysAreReadAndDefaultsAreNs3s) {
  const ExperimentConfig c = Parse(
      "network: {model: radio, radio: {propagation: log_distance, log_distance: {exponent: 2.5, "
      "reference_distance: 2m, sensitivity_dbm: -90, shadowing_db: 4, shadowing_window: 500ms}}}\n");
  ASSERT_EQ(c.network.radio.size(), 1u);
  const LogDistanceParams& l = c.network.radio[0].log_distance;
  EXPECT_EQ(c.network.radio[0].kind, PropagationKind::kLogDistance);
  EXPECT_EQ(l.exponent, 2.5);
  EXPECT_EQ(l.reference_distance_m, 2.0);
  EXPECT_EQ(l.reference_loss_db, 46.6777);  // not given: ns-3's default
  EXPECT_EQ(l.tx_power_dbm, 16.0206);
  EXPECT_EQ(l.sensitivity_dbm, -90.0);
  EXPECT_EQ(l.shadowing_db, 4.0);
  EXPECT_EQ(l.shadowing_window_s, 0.5);
}

TEST(ConfigRadioTest, RadioConfigReadsBackAndOthersAreWrittenWithoutTheSection) {
  for (const char* yaml :
       {"network: {model: radio, radio: {range: [150m, 1.5km]}, routing: shortest_path}\n",
        "network: {model: radio, radio: {propagation: log_distance, log_distance: {shadowing_db: 2}}}\n"}) {
    const ExperimentConfig c = Parse(yaml);
    const std::string emitted = EmitConfig(c);
    EXPECT_EQ(ParseConfig(emitted, "/nonexistent", {}, "config.yaml"), c) << emitted;
  }
  // The key, not the word: the emitted dataset path may hold "radio" (a checkout in .../radio/).
  const std::string plain = EmitConfig(Parse("{}"));
  EXPECT_EQ(plain.find("\n  radio:"), std::string::npos) << plain;
  EXPECT_EQ(plain.find("\n  routing:"), std::string::npos) << plain;
  EXPECT_NE(EmitConfig(Parse("network: {model: radio}\n")).find("\n  radio:"), std::string::npos);
}

TEST(ConfigRadioTest, BadRadioValuesNameTheirKey) {
  starts_with(ErrorOf("network: {model: radio, radio: {range: 0m}}\n"), "test.yaml: network.radio.range: must be in");
  starts_with(ErrorOf("network: {model: radio, radio: {range: -5m}}\n"),
              "test.yaml: network.radio.range: expected a length with a unit");
  starts_with(ErrorOf("network: {model: radio, radio: {range: 200}}\n"),
              "test.yaml: network.radio.range: expected a length with a unit");
  starts_with(ErrorOf("network: {model: radio, radio: {range: .nan}}\n"),
              "test.yaml: network.radio.range: expected a length with a unit");
  starts_with(ErrorOf("network: {model: radio, radio: {range: [100m, 100m]}}\n"),
              "test.yaml: network.radio.range[1]: listed twice");
  starts_with(ErrorOf("network: {model: radio, radio: {propagation: two_ray}}\n"),
              "test.yaml: network.radio.propagation: unknown value 'two_ray' (expected one of: range, log_distance)");
  starts_with(ErrorOf("network: {model: radio, radio: {propagation: log_distance, range: 100m}}\n"),
              "test.yaml: network.radio.range: applies to propagation range");
  starts_with(ErrorOf("network: {model: radio, radio: {log_distance: {exponent: 3}}}\n"),
              "test.yaml: network.radio.log_distance: applies to propagation log_distance");
  starts_with(ErrorOf("network: {model: radio, radio: {propagation: log_distance, log_distance: {exponent: 0.5}}}\n"),
              "test.yaml: network.radio.log_distance.exponent: ");
  starts_with(ErrorOf("network: {model: radio, radio: {propagation: log_distance, log_distance: {gain: 3}}}\n"),
              "test.yaml: network.radio.log_distance.gain: unknown key");
  starts_with(ErrorOf("network: {model: point_to_point, radio: {range: 100m}}\n"),
              "test.yaml: network.radio: applies to model radio, which network.model does not list");
  starts_with(ErrorOf("network: {model: radio, radio: {colour: red}}\n"), "test.yaml: network.radio.colour: unknown key");
  starts_with(ErrorOf("network: {model: radio, routing: flooding}\n"),
              "test.yaml: network.routing: unknown value 'flooding' (expected one of: direct, shortest_path, link_state)");
}

// network.radio may list radio maps (a range sweep beside a log_distance radio): one variant each,
// read back as written, a repeat refused.
TEST(ConfigRadioTest, RadioMayBeAListOfMaps) {
  const ExperimentConfig c = Parse(
      "network: {model: radio, radio: [{propagation: range, range: [100m, 200m]},\n"
      "          {propagation: log_distance, log_distance: {tx_power_dbm: 20, sensitivity_dbm: -96}}]}\n");
  ASSERT_EQ(c.network.radio.size(), 3u);
  EXPECT_EQ(c.network.radio[0].range_m, 100.0);
  EXPECT_EQ(c.network.radio[1].range_m, 200.0);
  EXPECT_EQ(c.network.radio[2].kind, PropagationKind::kLogDistance);
  EXPECT_EQ(c.network.radio[2].log_distance.tx_power_dbm, 20.0);
  // 10^((20 - 46.6777 + 96) / 30) = 10^2.31074 = 204.52 m
  EXPECT_NEAR(c.network.radio[2].log_distance.MeanRangeM(), 204.52, 0.01);
  const std::string emitted = EmitConfig(c);
  EXPECT_EQ(ParseConfig(emitted, "/nonexistent", {}, "config.yaml"), c) << emitted;
  const std::string error =
      ErrorOf("network: {model: radio, radio: [{range: 100m}, {propagation: range, range: [50m, 100m]}]}\n");
  EXPECT_EQ(error.rfind("test.yaml: network.radio[1]: repeats a radio listed before", 0), 0u) << error;
}

// network.routing (docs/network_model.md, "Routing"): a name, link_state's map, or a list of them
// (one radio variant each); only with a radio; every bad value one error naming its key.
TEST(ConfigRadioTest, RoutingIsOneEntryOrAListAndLinkStateTakesItsPeriods) {
  EXPECT_EQ(Parse("network: {model: radio}\n").network.routing, std::vector<NextHopEntry>{NextHopEntry{}});
  const ExperimentConfig c = Parse(
      "network: {model: [point_to_point, radio], routing: [shortest_path, link_state,\n"
      "          {kind: link_state, hello: 1s, topology: 3s}]}\n");
  ASSERT_EQ(c.network.routing.size(), 3u);
  EXPECT_EQ(c.network.routing[0].kind, NextHopKind::kShortestPath);
  EXPECT_EQ(c.network.routing[1].kind, NextHopKind::kLinkState);
  EXPECT_EQ(c.network.routing[1].link_state.hello, SimTime::Seconds(2));     // OLSR's defaults
  EXPECT_EQ(c.network.routing[1].link_state.topology, SimTime::Seconds(5));
  EXPECT_EQ(c.network.routing[2].link_state.hello, SimTime::Seconds(1));
  EXPECT_EQ(c.network.routing[2].link_state.topology, SimTime::Seconds(3));
  const std::string emitted = EmitConfig(c);
  EXPECT_EQ(ParseConfig(emitted, "/nonexistent", {}, "config.yaml"), c) << emitted;
}

TEST(ConfigRadioTest, BadRoutingValuesNameTheirKey) {
  starts_with(ErrorOf("network: {model: point_to_point, routing: link_state}\n"),
              "test.yaml: network.routing: applies to model radio, which network.model does not list");
  starts_with(ErrorOf("network: {model: radio, routing: [link_state, link_state]}\n"),
              "test.yaml: network.routing[1]: is listed twice");
  starts_with(ErrorOf("network: {model: radio, routing: []}\n"), "test.yaml: network.routing: ");
  starts_with(ErrorOf("network: {model: radio, routing: {hello: 2s}}\n"),
              "test.yaml: network.routing: a map needs its kind (link_state)");
  starts_with(ErrorOf("network: {model: radio, routing: {kind: shortest_path, hello: 2s}}\n"),
              "test.yaml: network.routing.hello: applies to link_state; shortest_path sends no beacons");
  starts_with(ErrorOf("network: {model: radio, routing: {kind: link_state, hello: 0s}}\n"),
              "test.yaml: network.routing.hello: must be in [1ns, 1h], got 0s");
  starts_with(ErrorOf("network: {model: radio, routing: {kind: link_state, topology: 2h}}\n"),
              "test.yaml: network.routing.topology: must be in [1ns, 1h], got 2h");
  starts_with(ErrorOf("network: {model: radio, routing: {kind: link_state, tc: 5s}}\n"),
              "test.yaml: network.routing.tc: unknown key");
}

// network.disconnected (docs/network_model.md, "Disconnection"): a name or a map, read back as
// written, only with a radio, and every bad value one error naming its key.
TEST(ConfigRadioTest, DisconnectedIsDropOrStoreAndForward) {
  EXPECT_EQ(Parse("network: {model: radio}\n").network.disconnected, DisconnectedParams{});
  const ExperimentConfig plain = Parse("network: {model: radio, routing: shortest_path, disconnected: store_and_forward}\n");
  EXPECT_EQ(plain.network.disconnected.kind, DisconnectedKind::kStoreAndForward);
  EXPECT_EQ(plain.network.disconnected.hold_bytes, Bytes(10'000'000));      // 10MB
  EXPECT_EQ(plain.network.disconnected.hold_time, SimTime::Seconds(60));   // 60s
  const ExperimentConfig c = Parse(
      "network: {model: radio, routing: shortest_path,\n"
      "          disconnected: {kind: store_and_forward, hold_bytes: 2MiB, hold_time: 90s}}\n");
  EXPECT_EQ(c.network.disconnected.hold_bytes, Bytes(2 * 1024 * 1024));
  EXPECT_EQ(c.network.disconnected.hold_time, SimTime::Seconds(90));
  const std::string emitted = EmitConfig(c);
  EXPECT_EQ(ParseConfig(emitted, "/nonexistent", {}, "config.yaml"), c) << emitted;
  EXPECT_EQ(EmitConfig(Parse("network: {model: radio, disconnected: drop}\n")).find("disconnected"), std::string::npos);
}

TEST(ConfigRadioTest, BadDisconnectedValuesNameTheirKey) {
  starts_with(ErrorOf("network: {model: point_to_point, disconnected: store_and_forward}\n"),
              "test.yaml: network.disconnected: applies to model radio, which network.model does not list");
  starts_with(ErrorOf("network: {model: radio, disconnected: hold}\n"),
              "test.yaml: network.disconnected: unknown value 'hold' (expected one of: drop, store_and_forward)");
  starts_with(ErrorOf("network: {model: radio, disconnected: {hold_bytes: 1MB}}\n"),
              "test.yaml: network.disconnected: a map needs its kind");
  starts_with(ErrorOf("network: {model: radio, disconnected: {kind: drop, hold_time: 5s}}\n"),
              "test.yaml: network.disconnected.hold_time: applies to store_and_forward");
  starts_with(ErrorOf("network: {model: radio, disconnected: {kind: store_and_forward, hold_bytes: 0B}}\n"),
              "test.yaml: network.disconnected.hold_bytes: must be in");
  starts_with(ErrorOf("network: {model: radio, disconnected: {kind: store_and_forward, hold_bytes: 2000GiB}}\n"),
              "test.yaml: network.disconnected.hold_bytes: must be in");
  starts_with(ErrorOf("network: {model: radio, disconnected: {kind: store_and_forward, hold_bytes: 100}}\n"),
              "test.yaml: network.disconnected.hold_bytes: ");
  starts_with(ErrorOf("network: {model: radio, disconnected: {kind: store_and_forward, hold_time: 0s}}\n"),
              "test.yaml: network.disconnected.hold_time: must be in");
  starts_with(ErrorOf("network: {model: radio, disconnected: {kind: store_and_forward, hold_time: -1s}}\n"),
              "test.yaml: network.disconnected.hold_time: ");
  starts_with(ErrorOf("network: {model: radio, disconnected: {kind: store_and_forward, ttl: 5}}\n"),
              "test.yaml: network.disconnected.ttl: unknown key");
  starts_with(ErrorOf("network: {model: radio, disconnected: [drop]}\n"),
              "test.yaml: network.disconnected: expected drop, or a map");
}

// Issue 53: with direct routing every copy goes straight to its destination (or is lost out of
// range), so store-and-forward has nothing to hold - it would have dropped silently - except
// what a sender sends outside its talk window. Refused without a network.schedule, naming both
// keys; a routing list that relays, or talk windows, give it something to hold.
TEST(ConfigRadioTest, StoreAndForwardWithDirectRoutingNeedsTalkWindows) {
  const std::string refused =
      "test.yaml: network.disconnected: store_and_forward holds nothing with network.routing: direct (every copy goes "
      "straight to its destination, or is lost out of range): use shortest_path or link_state routing, or a "
      "network.schedule, or drop";
  EXPECT_EQ(ErrorOf("network: {model: radio, disconnected: store_and_forward}\n"), refused);  // direct: the default
  EXPECT_EQ(ErrorOf("network: {model: radio, routing: direct, disconnected: {kind: store_and_forward, hold_time: 5s}}\n"),
            refused);
  EXPECT_EQ(ErrorOf("network: {model: radio, routing: [direct, link_state], disconnected: store_and_forward}\n"),
            "(no error)");
  const std::filesystem::path dir = testing_support::FreshTestDir("config_radio");
  std::ofstream(dir / "windows.csv") << "robot,start_s,end_s\n1,1,2\n";
  const ExperimentConfig c = Parse("network: {model: radio, disconnected: store_and_forward, schedule: " +
                                   (dir / "windows.csv").string() + "}\n");
  EXPECT_EQ(c.network.disconnected.kind, DisconnectedKind::kStoreAndForward);
  EXPECT_EQ(c.network.windows.size(), 1u);
}

}  // namespace
}  // namespace dvpr
