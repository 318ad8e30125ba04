// Checks of the failover timeout and the dropouts against the network and the data (issue 31):
// a config whose failover would declare healthy robots lost, or whose dropout falls outside the
// run, is refused before any run, naming the key. The values are worked by hand below.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "experiments/sweep/sweep_checks.h"
#include "experiments/sweep/sweep_size.h"

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

// A heartbeat is an 8 + 11 + 1 + 41 = 61-byte LCM datagram (header, "DVPR_STATUS", NUL, the
// agent_status_t with its hash), an 89-byte IP packet, a 91-byte PPP frame: 728 bits, 1 ms at
// 728 kbps. With 49 ms latency the worst delay is 50 ms, so a 100 ms period needs 150 ms.
TEST(SweepChecksTest, AFailoverTimeoutShorterThanPeriodPlusHeartbeatDelayIsRefused) {
  const std::string net = "network: {bandwidth: 728kbps, latency: 49ms}\n";
  EXPECT_EQ(ErrorOf(net + "failover: {enabled: true, heartbeat_period: 100ms, timeout: 149ms}\n"),
            "c.yaml: failover.timeout: must be at least heartbeat_period + the worst delay of a heartbeat "
            "(100ms + 50ms = 150ms on network 'point_to_point 728kbps 49ms' with 2 robots), got 149ms; "
            "a shorter one declares robots lost with nobody gone");
  EXPECT_EQ(ErrorOf(net + "failover: {enabled: true, heartbeat_period: 100ms, timeout: 150ms}\n"), "");
  // Without failover nothing is declared lost: the same timeout is not checked.
  EXPECT_EQ(ErrorOf(net + "failover: {enabled: false, heartbeat_period: 100ms, timeout: 149ms}\n"), "");
}

// A slow link override counts: 99 ms + 1 ms on robot 0 -> 1, so 100 + 100 = 200 ms.
TEST(SweepChecksTest, TheSlowestLinkOverrideSetsTheBound) {
  const std::string net =
      "network: {bandwidth: 728kbps, latency: 49ms, links: [{src: 0, dst: 1, latency: 99ms}]}\n";
  EXPECT_NE(ErrorOf(net + "failover: {enabled: true, heartbeat_period: 100ms, timeout: 199ms}\n")
                .find("(100ms + 100ms = 200ms on network"),
            std::string::npos);
  EXPECT_EQ(ErrorOf(net + "failover: {enabled: true, heartbeat_period: 100ms, timeout: 200ms}\n"), "");
}

// On a shared medium every robot's heartbeat of one instant shares the channel: the last of 3
// waits for 3 ms of frames, 49 + 3 = 52 ms; the team of 2 needs 51 ms, which 151 ms allows.
TEST(SweepChecksTest, OnASharedMediumTheHeartbeatsOfTheWholeTeamQueue) {
  const std::string net = "network: {model: shared_medium, bandwidth: 728kbps, latency: 49ms}\n";
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

ExperimentConfig Config(const std::string& yaml) { return ParseConfig(yaml, DVPR_SOURCE_DIR, {}, "c.yaml"); }

// 2 robot counts x 3 runs x 2 strategies x (1 paper + 2 x 3 sim variants: 2 bandwidths x 3
// latencies, ideal adding 1 more) = 6 x 2 x 8 = 96 runs. A run of 5 robots on 1000 frames of
// dim 16: 5 x 1000 x 16 x 4 = 320000 bytes of descriptors + 1000 x 64 x 8 = 512000 of lists.
TEST(SweepSizeTest, RunsAndBytesPerRunWorkedByHand) {
  const ExperimentConfig c = Config(
      "robots: [2, 5]\nruns: 3\nprotocols: [paper, sim]\nstrategies: [decentralized, broadcast]\n"
      "network: {model: [point_to_point, ideal], bandwidth: [1Mbps, 2Mbps], latency: [1ms, 2ms, 3ms]}\n");
  const SweepSize size = EstimateSweepSize(c, 1000, 16);
  EXPECT_EQ(size.runs, 96.0);
  EXPECT_EQ(size.bytes_per_run, 832000.0);
  EXPECT_EQ(EstimateSweepSize(Config("robots: [2, 5]\nruns: 3\nprotocols: [sim]\n"), 1000, 16).bytes_per_run,
            320000.0);
}

// robots 2..100000 (99999 counts) x 100000 runs x 2 strategies x (1 + 1) = 4.0e10 runs; the
// default sweep (19 x 10 x 2 x 2 = 760) passes.
TEST(SweepSizeTest, ASweepOfBillionsOfRunsIsRefusedWithItsCount) {
  const ExperimentConfig huge = Config("robots: {from: 2, to: 100000}\nruns: 100000\n");
  const SweepSize size = EstimateSweepSize(huge, 4541, 128);
  EXPECT_EQ(size.runs, 99999.0 * 100000 * 2 * 2);
  try {
    CheckSweepSize(size, 1e12, "c.yaml");
    FAIL() << "accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "c.yaml: robots, runs, protocols, strategies, network: the sweep has 4e+10 runs (robot counts x runs x "
              "strategies x network variants), more than 1e+06 (days of computing); narrow it, or pass --allow-large "
              "to run it anyway");
  }
  EXPECT_EQ(EstimateSweepSize(Config("seed: 1\n"), 4541, 128).runs, 760.0);
  EXPECT_NO_THROW(CheckSweepSize(EstimateSweepSize(Config("seed: 1\n"), 4541, 128), 1e12, "c.yaml"));
}

// 4 GiB of descriptors (8 robots x 2^20 frames x 128 x 4 = 2^32 bytes, sim only) on a 2 GiB machine.
TEST(SweepSizeTest, ARunLargerThanTheMachinesMemoryIsRefusedWithTheEstimate) {
  const SweepSize size = EstimateSweepSize(Config("robots: [8]\nprotocols: [sim]\n"), 1 << 20, 128);
  EXPECT_EQ(size.bytes_per_run, 4294967296.0);
  try {
    CheckSweepSize(size, 2147483648.0, "c.yaml");
    FAIL() << "accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, 98),
              "c.yaml: robots, dataset: a run may need up to 4 GiB (largest team x frames x dim x 4 bytes of desc");
    EXPECT_NE(std::string(e.what()).find("more than this machine's 2 GiB of memory"), std::string::npos);
  }
  EXPECT_NO_THROW(CheckSweepSize(size, 4294967296.0, "c.yaml"));
  EXPECT_NO_THROW(CheckSweepSize(size, 0, "c.yaml"));  // memory unknown: not checked
}

// Every shipped config (KITTI 00: 4541 frames at most) runs without --allow-large, even on a
// machine of 1 GiB: at most 20 robots x 4541 x 128 x 4 = 46.5 MB a run. own_descriptors.yaml
// names the user's files, which the source tree does not hold; it is read with the KITTI poses.
TEST(SweepSizeTest, EveryShippedConfigPassesWithoutTheFlag) {
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(DVPR_SOURCE_DIR) / "experiments/configs")) {
    if (entry.path().extension() != ".yaml") continue;
    std::vector<ConfigOverride> overrides;
    if (entry.path().filename() == "own_descriptors.yaml") {
      overrides = {ParseOverride("dataset={poses: data/kitti/00_poses.txt, dim: 128}"),
                   ParseOverride("training={source: deployment}")};
    }
    const ExperimentConfig c = LoadConfig(entry.path(), overrides);
    const SweepSize size = EstimateSweepSize(c, c.dataset.frames.value_or(4541), c.dataset.dim);
    EXPECT_NO_THROW(CheckSweepSize(size, 1024.0 * 1024 * 1024, entry.path().string())) << entry.path();
    ++checked;
  }
  EXPECT_GE(checked, 6);
}

}  // namespace
}  // namespace dvpr
