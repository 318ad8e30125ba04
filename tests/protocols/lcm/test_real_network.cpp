// Real agents talk over the real network; with a radio config each receiving agent emulates the
// radio's range (emulated_range.h; tests/protocols/lcm/test_team_radio.cpp runs a team). What a
// launched team cannot emulate - several networks, several radios, relays, store-and-forward -
// is refused by dvpr launch and dvpr agent before any process starts, naming the key.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "experiments/protocols/lcm/agent_process.h"

namespace dvpr {
namespace {

std::string ErrorOf(const ExperimentConfig& c) {
  try {
    CheckRealNetwork(c, "my.yaml");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(RealNetworkTest, OneRadioWithDirectRoutingIsEmulated) {
  ExperimentConfig c;
  EXPECT_EQ(ErrorOf(c), "");
  c.network.model = {LinkModelKind::kRadio};
  EXPECT_EQ(ErrorOf(c), "");
}

TEST(RealNetworkTest, WhatARealTeamCannotEmulateIsRefusedNamingTheKey) {
  ExperimentConfig c;
  c.network.model = {LinkModelKind::kPointToPoint, LinkModelKind::kRadio};
  EXPECT_EQ(ErrorOf(c), "my.yaml: network.model: a launched team runs on one network: give radio alone");
  c.network.model = {LinkModelKind::kRadio};
  c.network.radio = {PropagationParams::Radio(), PropagationParams::Radio()};
  c.network.radio[1].range_m = 300;
  EXPECT_EQ(ErrorOf(c), "my.yaml: network.radio.range: a launched team has one radio: give one range");
  c.network.radio.resize(1);
  c.network.routing = {NextHopEntry{.kind = NextHopKind::kShortestPath, .link_state = {}}};
  EXPECT_EQ(ErrorOf(c),
            "my.yaml: network.routing: real agents emulate the radio's range only, without relays: use direct");
  c.network.routing = {NextHopEntry{}};
  c.network.disconnected.kind = DisconnectedKind::kStoreAndForward;
  EXPECT_EQ(ErrorOf(c),
            "my.yaml: network.disconnected: real agents emulate the radio's range only, without store-and-forward: "
            "use drop");
}

TEST(RealNetworkTest, TalkWindowsAreRefusedOnEveryModel) {
  ExperimentConfig c;
  c.network.schedule = "/somewhere/windows.csv";
  c.network.windows = {ScheduledWindow{0, TalkWindow{SimTime::Seconds(1), SimTime::Seconds(2)}}};
  EXPECT_EQ(ErrorOf(c), "my.yaml: network.schedule: talk windows are simulated only (dvpr run); a launched team's "
                        "agents do not emulate them");
}

}  // namespace
}  // namespace dvpr
