// Checks of the failover timeout and the dropouts against the network and the data (issue 31):
// a config whose failover would declare healthy robots lost, or whose dropout falls outside the
// run, is refused before any run, naming the key. The values are worked by hand below.
#include <string>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "experiments/sweep/sweep_checks.h"

namespace dvpr {
namespace {

// 40 frames at 10 fps: a team of 2 drives 20 frames each (the run ends at 2 s), a team of 3 at
// most ceil(40 / 3) = 14 (the run ends at 1.4 s).
std::string ErrorOf(const std::string& yaml) {
  const ExperimentConfig c =
      ParseConfig("robots: [2, 3]\nruns: 1\nprotocols: [sim]\nstrategies: [broadcast]\n" + yaml, DVPR_SOURCE_DIR, {},
                  "c.yaml");
  SharedInputs in;
  in.config = &c;
  in.deployment.fps = 10;
  in.deployment.descriptors = DescriptorMatrix::Zero(40, 8);
  in.training = DescriptorMatrix::Zero(100, 8);
  try {
    CheckSweepInputs(in, "c.yaml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

// A heartbeat is an 8 + 11 + 1 + 41 + 34 = 95-byte LCM datagram (header, "DVPR_STATUS", NUL, the
// agent_status_t with its hash, the team's authentication trailer), a 123-byte IP packet, a
// 125-byte PPP frame: 1000 bits, 1 ms at 1 Mbps. With 49 ms latency the worst delay is 50 ms, so
// a 100 ms period needs 150 ms.
TEST(SweepChecksTest, AFailoverTimeoutShorterThanPeriodPlusHeartbeatDelayIsRefused) {
  const std::string net = "network: {bandwidth: 1Mbps, latency: 49ms}\n";
  EXPECT_EQ(ErrorOf(net + "failover: {enabled: true, heartbeat_period: 100ms, timeout: 149ms}\n"),
            "c.yaml: failover.timeout: must be at least heartbeat_period + the worst delay of a heartbeat "
            "(100ms + 50ms = 150ms on network 'point-to-point 1 Mbit/s 49 ms' with 2 robots), got 149ms; "
            "a shorter one declares robots lost with nobody gone");
  EXPECT_EQ(ErrorOf(net + "failover: {enabled: true, heartbeat_period: 100ms, timeout: 150ms}\n"), "");
  // Without failover nothing is declared lost: the same timeout is not checked.
  EXPECT_EQ(ErrorOf(net + "failover: {enabled: false, heartbeat_period: 100ms, timeout: 149ms}\n"), "");
}

// A slow link override counts: 99 ms + 1 ms on robot 0 -> 1, so 100 + 100 = 200 ms.
TEST(SweepChecksTest, TheSlowestLinkOverrideSetsTheBound) {
  const std::string net =
      "network: {bandwidth: 1Mbps, latency: 49ms, links: [{src: 0, dst: 1, latency: 99ms}]}\n";
  EXPECT_NE(ErrorOf(net + "failover: {enabled: true, heartbeat_period: 100ms, timeout: 199ms}\n")
                .find("(100ms + 100ms = 200ms on network"),
            std::string::npos);
  EXPECT_EQ(ErrorOf(net + "failover: {enabled: true, heartbeat_period: 100ms, timeout: 200ms}\n"), "");
}

// On a shared medium every robot's heartbeat of one instant shares the channel: the last of 3
// waits for 3 ms of frames, 49 + 3 = 52 ms; the team of 2 needs 51 ms, which 151 ms allows.
TEST(SweepChecksTest, OnASharedMediumTheHeartbeatsOfTheWholeTeamQueue) {
  const std::string net = "network: {model: shared_medium, bandwidth: 1Mbps, latency: 49ms}\n";
  const std::string error = ErrorOf(net + "failover: {enabled: true, heartbeat_period: 100ms, timeout: 151ms}\n");
  EXPECT_NE(error.find("(100ms + 52ms = 152ms on network"), std::string::npos) << error;
  EXPECT_NE(error.find("with 3 robots), got 151ms"), std::string::npos) << error;
  EXPECT_EQ(ErrorOf(net + "failover: {enabled: true, heartbeat_period: 100ms, timeout: 152ms}\n"), "");
  // The ideal network delivers at once: any timeout longer than the period will do.
  EXPECT_EQ(ErrorOf("network: {model: ideal}\nfailover: {enabled: true, heartbeat_period: 100ms, timeout: 101ms}\n"),
            "");
}

TEST(SweepChecksTest, ADropoutAtOrAfterTheEndOfTheRunIsRefused) {
  EXPECT_EQ(ErrorOf("dropout: [{robot: 1, at: 1400ms}]\n"),
            "c.yaml: dropout[0].at: 1400ms is not inside the run of 3 robots, which ends at 1400ms "
            "(14 frames at most per robot at 10 fps)");
  EXPECT_EQ(ErrorOf("dropout: [{robot: 1, at: 1399ms}]\n"), "");
  // Robot 2 is in the team of 3 only; robot 0 of both: 2 s is past both ends.
  EXPECT_NE(ErrorOf("dropout: [{robot: 0, at: 1s}, {robot: 2, at: 1.5s}]\n").find("dropout[1].at: 1500ms is not inside"),
            std::string::npos);
  EXPECT_NE(ErrorOf("dropout: [{robot: 0, at: 2s}]\n").find("dropout[0].at: 2s is not inside the run of 2 robots, "
                                                          "which ends at 2s (20 frames"),
            std::string::npos);
}

TEST(SweepChecksTest, ARobotDroppedTwiceIsRefusedByTheConfig) {
  try {
    ParseConfig("robots: [2, 3]\ndropout: [{robot: 1, at: 1s}, {robot: 0, at: 1s}, {robot: 1, at: 2s}]\n",
                DVPR_SOURCE_DIR, {}, "c.yaml");
    FAIL() << "accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "c.yaml: dropout[2].robot: robot 1 is already dropped by dropout[0]; a robot drops out once");
  }
}

}  // namespace
}  // namespace dvpr
