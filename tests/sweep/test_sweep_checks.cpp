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
    CheckSweepSize(size, {.memory_bytes = 1e12}, "c.yaml");
    FAIL() << "accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "c.yaml: robots, runs, protocols, strategies, network: the sweep has 4e+10 runs (robot counts x runs x "
              "strategies x network variants), more than 1e+06 (days of computing); narrow it, or pass --allow-large "
              "to run it anyway");
  }
  EXPECT_EQ(EstimateSweepSize(Config("seed: 1\n"), 4541, 128).runs, 760.0);
  EXPECT_NO_THROW(CheckSweepSize(EstimateSweepSize(Config("seed: 1\n"), 4541, 128), {.memory_bytes = 1e12}, "c.yaml"));
}

// 4 GiB of descriptors (8 robots x 2^20 frames x 128 x 4 = 2^32 bytes, sim only) on a 2 GiB machine.
TEST(SweepSizeTest, ARunLargerThanTheMachinesMemoryIsRefusedWithTheEstimate) {
  // One run (1.96 h by the time model: 2^40 / 2 x 128 x 1e-10 s of search, 16.8 s of messages).
  const SweepSize size =
      EstimateSweepSize(Config("robots: [8]\nruns: 1\nstrategies: [decentralized]\nprotocols: [sim]\n"), 1 << 20, 128);
  EXPECT_EQ(size.runs, 1.0);
  EXPECT_EQ(size.bytes_per_run, 4294967296.0);
  try {
    CheckSweepSize(size, {.memory_bytes = 2147483648.0}, "c.yaml");
    FAIL() << "accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, 98),
              "c.yaml: robots, dataset: a run may need up to 4 GiB (largest team x frames x dim x 4 bytes of desc");
    EXPECT_NE(std::string(e.what()).find("more than this machine's 2 GiB of memory"), std::string::npos);
  }
  EXPECT_NO_THROW(CheckSweepSize(size, {.memory_bytes = 4294967296.0}, "c.yaml"));
  EXPECT_NO_THROW(CheckSweepSize(size, {.memory_bytes = 0}, "c.yaml"));  // memory unknown: not checked
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
    EXPECT_NO_THROW(CheckSweepSize(size, {.memory_bytes = 1024.0 * 1024 * 1024, .cores = 2}, entry.path().string()))
        << entry.path();
    ++checked;
  }
  EXPECT_GE(checked, 6);
}

// The message of the ConfigError CheckSweepSize throws, "" when it accepts.
std::string SizeError(const SweepSize& size, const SweepMachine& machine) {
  try {
    CheckSweepSize(size, machine, "c.yaml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

// 8 robots x 2^18 frames x 128 x 4 bytes = 2^30 bytes (1 GiB) a run, 4 runs, on 3 GiB: two or
// three at once fit, four do not (threads 4, and threads 8 runs only the 4 runs there are).
TEST(SweepSizeTest, TheRunsInFlightAtOnceShareTheMemory) {
  const SweepSize size =
      EstimateSweepSize(Config("robots: [8]\nruns: 4\nprotocols: [sim]\nstrategies: [decentralized]\n"
                               "network: {model: [ideal]}\n"),
                        1 << 18, 128);
  EXPECT_EQ(size.runs, 4.0);
  EXPECT_EQ(size.bytes_per_run, 1073741824.0);
  const double memory = 3.0 * 1073741824.0;
  EXPECT_EQ(SizeError(size, {.memory_bytes = memory, .cores = 2}), "");  // one run a core: 2 GiB
  EXPECT_EQ(SizeError(size, {.memory_bytes = memory, .cores = 2, .threads = 3}), "");
  const std::string four =
      "c.yaml: robots, dataset: 4 runs at once (one a thread) may need up to 4 GiB, each up to 1 GiB (largest team "
      "x frames x dim x 4 bytes of descriptors, and the paper protocol's neighbour lists), more than this machine's "
      "3 GiB of memory; lower dataset.frames, dataset.dim or robots, run fewer at once (--threads), or pass "
      "--allow-large to run it anyway";
  EXPECT_EQ(SizeError(size, {.memory_bytes = memory, .cores = 2, .threads = 4}), four);
  EXPECT_EQ(SizeError(size, {.memory_bytes = memory, .cores = 2, .threads = 8}), four);
  EXPECT_EQ(SizeError(size, {.memory_bytes = memory, .cores = 4}), four);  // threads 0: one a core
}

// 100000 runs x 2 strategies of 10 robots on 10000 frames of dim 100, sim: a run is 10000^2 / 2 x 100
// multiply-adds x 1e-10 s = 0.5 s of search plus 2 x 10000 x 10 messages x 1e-6 s = 0.2 s.
// 200000 x 0.7 s = 140000 s: 38.9 h on one core (refused), 19.4 h on two.
TEST(SweepSizeTest, ASweepOfMoreThanADayOnTheseCoresIsRefusedWithTheEstimate) {
  const SweepSize size = EstimateSweepSize(
      Config("robots: [10]\nruns: 100000\nprotocols: [sim]\nstrategies: [broadcast, decentralized]\nnetwork: {model: [ideal]}\n"),
      10000, 100);
  EXPECT_EQ(size.runs, 200000.0);
  EXPECT_NEAR(size.seconds_per_run, 0.7, 1e-12);
  EXPECT_EQ(size.input_seconds, 0.0);
  const std::string one_core =
      "c.yaml: robots, runs, strategies, network, dataset: the sweep would take about 38.9 h on 1 core (2e+05 runs "
      "of up to 0.7 s each), more than 24 h; narrow it, or pass --allow-large to run it anyway";
  EXPECT_EQ(SizeError(size, {.cores = 1}), one_core);
  EXPECT_EQ(SizeError(size, {.cores = 2, .threads = 1}), one_core);  // one thread: one core's worth
  EXPECT_EQ(SizeError(size, {.cores = 2}), "");
  // The paper protocol alone: the search only, 0.5 s a run, 27.8 h on one core.
  const SweepSize paper = EstimateSweepSize(
      Config("robots: [10]\nruns: 100000\nprotocols: [paper]\nstrategies: [broadcast, decentralized]\n"), 10000, 100);
  EXPECT_NEAR(paper.seconds_per_run, 0.5, 1e-12);
  EXPECT_NE(SizeError(paper, {.cores = 1}).find("about 27.8 h on 1 core (2e+05 runs of up to 0.5 s each)"),
            std::string::npos);
}

// synthetic_bow examines every landmark of the square of side 2 x range_m around a frame:
// (2 x 1000)^2 x 10 = 4e7 at its maxima, 1.7 s a frame; 60000 frames take 102000 s (28.3 h)
// before the one run (60000^2 / 2 x 16 x 1e-10 = 2.88 s). Its defaults (range 40 m, 0.2
// landmarks per m^2): 80^2 x 0.2 = 1280 landmarks, 54.4 us a frame, 0.247 s for 4541 frames.
TEST(SweepSizeTest, SyntheticBowAtItsMaximaIsCountedBeforeTheRuns) {
  const std::string maxima =
      "robots: [2]\nruns: 1\nprotocols: [paper]\nstrategies: [bow_decentralized]\n"
      "dataset: {dim: 16, synthetic_bow: {features: 100000, vocabulary: 10000000, landmark_density: 10, "
      "range_m: 1000, field_of_view_deg: 360}}\n";
  const SweepSize one_frame = EstimateSweepSize(Config(maxima), 1, 16);
  EXPECT_NEAR(one_frame.input_seconds, 1.7, 1e-9);
  const SweepSize size = EstimateSweepSize(Config(maxima), 60000, 16);
  EXPECT_NEAR(size.input_seconds, 102000.0, 1e-6);
  EXPECT_NEAR(size.seconds_per_run, 2.88, 1e-9);
  EXPECT_EQ(SizeError(size, {.cores = 2}),
            "c.yaml: robots, runs, strategies, network, dataset: the sweep would take about 28.3 h on 1 core (1 run of "
            "up to 2.88 s each, and 1.02e+05 s to make dataset.synthetic_bow's vectors), more than 24 h; narrow it, "
            "or pass --allow-large to run it anyway");
  EXPECT_EQ(SizeError(EstimateSweepSize(Config(maxima), 4541, 16), {.cores = 2}), "");  // 2.14 h
  const SweepSize defaults = EstimateSweepSize(
      Config("robots: [2]\nruns: 1\nprotocols: [paper]\nstrategies: [bow_decentralized]\n"), 4541, 16);
  EXPECT_NEAR(defaults.input_seconds, 0.247, 1e-3);
  // Descriptor strategies make no BoW vectors.
  EXPECT_EQ(EstimateSweepSize(Config("robots: [2]\n"), 60000, 16).input_seconds, 0.0);
}

// The default sweep (robots 2..20, paper and sim): the largest team's run is 4541^2 / 2 x 128 x
// 1e-10 = 0.132 s of search plus 2 x 4541 x 20 x 1e-6 = 0.182 s of messages, 0.314 s (0.21 s
// measured on average); its 760 runs take 2.0 min on two cores by the model.
TEST(SweepSizeTest, TheDefaultSweepsEstimateWorkedByHand) {
  const SweepSize size = EstimateSweepSize(Config("seed: 1\n"), 4541, 128);
  EXPECT_NEAR(size.seconds_per_run, 0.31361, 1e-5);
  EXPECT_EQ(SizeError(size, {.memory_bytes = 1024.0 * 1024 * 1024, .cores = 1}), "");
}

}  // namespace
}  // namespace dvpr
