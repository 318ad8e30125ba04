// The size of a sweep, estimated before it starts (issues 31 and 53; sweep_size.h): each term
// against a count of its events worked by hand from the rules of the code that makes them (the
// link-state daemon's and the failover's timers, the network's store-and-forward retries, the
// connectivity steps), and the refusals of the configs that used to run for hours or be killed
// for memory without a word, each naming the key responsible. test_sweep_size_measured.cpp checks
// the terms against what small runs count.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "experiments/sweep/sweep_size.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

ExperimentConfig SizeConfig(const std::string& yaml) { return ParseConfig(yaml, DVPR_SOURCE_DIR, {}, "c.yaml"); }

// The message of the ConfigError CheckSweepSize throws, "" when it accepts.
std::string SizeError(const SweepSize& size, const SweepMachine& machine) {
  try {
    CheckSweepSize(size, machine, "c.yaml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

double Seconds(const RunEstimate& e, SizeTerm term) { return e.seconds[static_cast<std::size_t>(term)]; }
double Bytes(const RunEstimate& e, SizeTerm term) { return e.bytes[static_cast<std::size_t>(term)]; }

constexpr double kGiB = 1024.0 * 1024 * 1024;

// 2 robot counts x 3 runs x 2 strategies x (1 paper + 2 x 3 sim variants: 2 bandwidths x 3
// latencies, ideal adding 1 more) = 6 x 2 x 8 = 96 runs. A run of 5 robots on 1000 frames of
// dim 16: stores 1000 x 2 x (6 x 16 + 12) = 216000 bytes (each frame kept by one robot), records
// 1000 x 256 = 256000, and the verification payloads: a 25000-byte request is 17 packets of at
// most 1480 data bytes, (25064 + 17 x 22) x 8 bits at 2 Mbit/s (the fastest) = 0.1018 s on the
// wire, longer than the 3 ms it then propagates; each of its robot's 4 queues of 100 packets holds
// the one on the wire, floor(100 / 17) = 5 waiting and 1 propagating: 28 in flight and the one it
// keeps, 5 x 29 x 25000, and one being decoded = 3650000. Inputs: (1000 + 20000 training) x 16 x 4
// bytes and the paper's neighbour lists, 1000 x 64 x 8.
TEST(SweepSizeTest, RunsAndBytesPerRunWorkedByHand) {
  const ExperimentConfig c = SizeConfig(
      "robots: [2, 5]\nruns: 3\nprotocols: [paper, sim]\nstrategies: [decentralized, broadcast]\n"
      "network: {model: [point_to_point, ideal], bandwidth: [1Mbps, 2Mbps], latency: [1ms, 2ms, 3ms]}\n");
  const SweepSize size = EstimateSweepSize(c, 1000, 16);
  EXPECT_EQ(size.runs, 96.0);
  EXPECT_EQ(size.largest.robots, 5);
  EXPECT_EQ(size.largest.requests_in_flight, 28.0);
  EXPECT_EQ(size.largest.stored, 1000.0);
  EXPECT_EQ(Bytes(size.largest, SizeTerm::kStores), 216000.0 + 256000.0);
  EXPECT_EQ(Bytes(size.largest, SizeTerm::kRequests), 3650000.0);
  EXPECT_EQ(size.bytes_per_run, 4122000.0);
  EXPECT_EQ(size.input_bytes, 21000.0 * 64 + 512000.0);
  // On 10 Mbit/s with 2 ms (the defaults) a request is 20.4 ms on the wire: the same 7 a queue.
  const SweepSize sim = EstimateSweepSize(SizeConfig("robots: [2, 5]\nruns: 3\nprotocols: [sim]\n"), 1000, 16);
  EXPECT_EQ(sim.bytes_per_run, 216000.0 + 256000.0 + 5 * 29 * 25000.0 + 25000.0);
  EXPECT_EQ(sim.input_bytes, 21000.0 * 64);
  // replicate_1_r4 keeps a frame at up to 4 robots.
  const SweepSize replicated =
      EstimateSweepSize(SizeConfig("robots: [5]\nruns: 1\nprotocols: [sim]\nstrategies: [replicate_1_r4]\n"), 1000, 16);
  EXPECT_EQ(replicated.largest.stored, 4000.0);
  EXPECT_EQ(Bytes(replicated.largest, SizeTerm::kStores), 4 * 216000.0 + 256000.0);
}

// robots 2..100000 (99999 counts) x 100000 runs x 2 strategies x (1 + 1) = 4.0e10 runs; the
// default sweep (19 x 10 x 2 x 2 = 760) passes.
TEST(SweepSizeTest, ASweepOfBillionsOfRunsIsRefusedWithItsCount) {
  const ExperimentConfig huge = SizeConfig("robots: {from: 2, to: 100000}\nruns: 100000\n");
  const SweepSize size = EstimateSweepSize(huge, 4541, 128);
  EXPECT_EQ(size.runs, 99999.0 * 100000 * 2 * 2);
  EXPECT_EQ(SizeError(size, {.memory_bytes = 1e12}),
            "c.yaml: robots, runs, protocols, strategies, network: the sweep has 4e+10 runs (robot counts x runs x "
            "strategies x network variants), more than 1e+06 (days of computing); narrow it, or pass --allow-large "
            "to run it anyway");
  EXPECT_EQ(EstimateSweepSize(SizeConfig("seed: 1\n"), 4541, 128).runs, 760.0);
  EXPECT_EQ(SizeError(EstimateSweepSize(SizeConfig("seed: 1\n"), 4541, 128), {.memory_bytes = 1e12}), "");
}

// Only the radio sweeps its routing entries: point_to_point, and the radio's 2 ranges x 2
// routings, are 5 variants; 3 robot counts x 2 runs x 2 strategies x 5 = 60 runs.
TEST(SweepSizeTest, TheRadiosRoutingsMultiplyItsVariants) {
  const SweepSize size = EstimateSweepSize(
      SizeConfig("robots: [2, 3, 4]\nruns: 2\nprotocols: [sim]\nnetwork: {model: [point_to_point, radio], "
             "radio: {range: [100m, 200m]}, routing: [shortest_path, link_state]}\n"),
      1000, 16);
  EXPECT_EQ(size.runs, 60.0);
}

// 8 robots x 2^20 frames of dim 128, sim: the stores are 2^20 x 2 x (6 x 128 + 12) = 1 635 778 560
// bytes and the records 2^20 x 256 = 268 435 456 (1.77 GiB), the payloads 8 x 50 x 25000 + 25000
// (7 queues of 7 requests in flight a robot, as above); the inputs (2^20 + 20000) x 128 x 4 =
// 547 110 912 (0.51 GiB): 2.29 GiB in all, more than 2 GiB.
TEST(SweepSizeTest, ARunLargerThanTheMachinesMemoryIsRefusedWithTheEstimate) {
  const SweepSize size =
      EstimateSweepSize(SizeConfig("robots: [8]\nruns: 1\nstrategies: [decentralized]\nprotocols: [sim]\n"), 1 << 20, 128);
  EXPECT_EQ(size.runs, 1.0);
  EXPECT_EQ(size.bytes_per_run, 1635778560.0 + 268435456.0 + 10025000.0);
  EXPECT_EQ(size.input_bytes, 547110912.0);
  EXPECT_EQ(SizeError(size, {.memory_bytes = 2 * kGiB}),
            "c.yaml: robots, dataset: a run may need up to 2.29 GiB (1.77 GiB a run of descriptor stores (frames x "
            "copies x 2 x (6 dim + 12) bytes) and records (256 bytes a frame), and 0.51 GiB of inputs made once), "
            "more than this machine's 2 GiB of memory; lower dataset.frames, dataset.dim or robots, or pass "
            "--allow-large to run it anyway");
  EXPECT_EQ(SizeError(size, {.memory_bytes = 3 * kGiB}), "");
  EXPECT_EQ(SizeError(size, {.memory_bytes = 0}), "");  // memory unknown: not checked
}

// Every shipped config (KITTI 00: 4541 frames at most; staggered_kitti00's 5 robots each drive
// them) runs without --allow-large, even on a machine of 1 GiB and 2 cores. own_descriptors.yaml
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
    EXPECT_EQ(SizeError(size, {.memory_bytes = kGiB, .cores = 2}), "") << entry.path();
    ++checked;
  }
  EXPECT_GE(checked, 6);
}

// 8 robots x 2^18 frames x 128, ideal links (one request in flight): 2^18 x (1560 + 256) =
// 476 053 504 bytes of stores and records and 8 x 2 x 25000 + 25000 of payloads, 0.444 GiB a
// run; inputs (2^18 + 20000) x 512 = 0.135 GiB. On 1.5 GiB two or three runs at once fit (1.47
// GiB), four do not (1.91 GiB): threads 4, threads 8 (only the 4 runs there are), one a core.
TEST(SweepSizeTest, TheRunsInFlightAtOnceShareTheMemory) {
  const SweepSize size =
      EstimateSweepSize(SizeConfig("robots: [8]\nruns: 4\nprotocols: [sim]\nstrategies: [decentralized]\n"
                               "network: {model: [ideal]}\n"),
                        1 << 18, 128);
  EXPECT_EQ(size.runs, 4.0);
  EXPECT_EQ(size.bytes_per_run, 476053504.0 + 425000.0);
  const double memory = 1.5 * kGiB;
  EXPECT_EQ(SizeError(size, {.memory_bytes = memory, .cores = 2}), "");  // one run a core
  EXPECT_EQ(SizeError(size, {.memory_bytes = memory, .cores = 2, .threads = 3}), "");
  const std::string four =
      "c.yaml: robots, dataset: 4 runs at once (one a thread) may need up to 1.91 GiB, each up to 0.444 GiB (0.443 GiB "
      "a run of descriptor stores (frames x copies x 2 x (6 dim + 12) bytes) and records (256 bytes a frame), and "
      "0.135 GiB of inputs made once), more than this machine's 1.5 GiB of memory; lower dataset.frames, dataset.dim "
      "or robots, run fewer at once (--threads), or pass --allow-large to run it anyway";
  EXPECT_EQ(SizeError(size, {.memory_bytes = memory, .cores = 2, .threads = 4}), four);
  EXPECT_EQ(SizeError(size, {.memory_bytes = memory, .cores = 2, .threads = 8}), four);
  EXPECT_EQ(SizeError(size, {.memory_bytes = memory, .cores = 4}), four);  // threads 0: one a core
}

// 100000 runs x 2 strategies of 10 robots on 10000 frames of dim 100, sim on ideal links: a run
// is 10000^2 / 2 x 100 multiply-adds x 1e-10 s = 0.5 s of search, 2 x 10000 x 10 messages x
// 1e-6 s = 0.2 s, and 10000 verification requests of 25000 bytes x 5e-10 s = 0.125 s. 200000 x
// 0.825 s = 165000 s: 45.8 h on one core (refused), 22.9 h on two.
TEST(SweepSizeTest, ASweepOfMoreThanADayOnTheseCoresIsRefusedWithTheEstimate) {
  const SweepSize size = EstimateSweepSize(
      SizeConfig("robots: [10]\nruns: 100000\nprotocols: [sim]\nstrategies: [broadcast, decentralized]\nnetwork: {model: [ideal]}\n"),
      10000, 100);
  EXPECT_EQ(size.runs, 200000.0);
  EXPECT_NEAR(size.seconds_per_run, 0.825, 1e-12);
  EXPECT_EQ(size.input_seconds, 0.0);
  const std::string one_core =
      "c.yaml: robots, runs, strategies, network, dataset: the sweep would take about 45.8 h on 1 core (2e+05 runs "
      "of up to 0.825 s each), more than 24 h; narrow it, or pass --allow-large to run it anyway";
  EXPECT_EQ(SizeError(size, {.cores = 1}), one_core);
  EXPECT_EQ(SizeError(size, {.cores = 2, .threads = 1}), one_core);  // one thread: one core's worth
  EXPECT_EQ(SizeError(size, {.cores = 2}), "");
  // The paper protocol alone: the search only, 0.5 s a run, 27.8 h on one core.
  const SweepSize paper = EstimateSweepSize(
      SizeConfig("robots: [10]\nruns: 100000\nprotocols: [paper]\nstrategies: [broadcast, decentralized]\n"), 10000, 100);
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
  const SweepSize one_frame = EstimateSweepSize(SizeConfig(maxima), 1, 16);
  EXPECT_NEAR(one_frame.input_seconds, 1.7, 1e-9);
  const SweepSize size = EstimateSweepSize(SizeConfig(maxima), 60000, 16);
  EXPECT_NEAR(size.input_seconds, 102000.0, 1e-6);
  EXPECT_NEAR(size.seconds_per_run, 2.88, 1e-9);
  EXPECT_EQ(SizeError(size, {.cores = 2}),
            "c.yaml: robots, runs, strategies, network, dataset: the sweep would take about 28.3 h on 1 core (1 run of "
            "up to 2.88 s each, and 1.02e+05 s to make dataset.synthetic_bow's vectors), more than 24 h; narrow it, "
            "or pass --allow-large to run it anyway");
  EXPECT_EQ(SizeError(EstimateSweepSize(SizeConfig(maxima), 4541, 16), {.cores = 2}), "");  // 2.14 h
  // Its words and vectors: 60000 x (4 x 100000 + 16 x 100000 + 72) + 16 x 10^7 bytes, 112 GiB.
  EXPECT_EQ(size.bow_bytes, 120164320000.0);
  EXPECT_EQ(SizeError(size, {.memory_bytes = 16 * kGiB, .cores = 2}),
            "c.yaml: dataset.synthetic_bow: a run may need up to 112 GiB (112 GiB of inputs made once (112 GiB of it "
            "dataset.synthetic_bow's words and vectors, frames x (4 features + 16 min(features, vocabulary) + 72) + 16 "
            "vocabulary bytes)), more than this machine's 16 GiB of memory; lower dataset.synthetic_bow's features or "
            "dataset.frames, or pass --allow-large to run it anyway");
  const SweepSize defaults = EstimateSweepSize(
      SizeConfig("robots: [2]\nruns: 1\nprotocols: [paper]\nstrategies: [bow_decentralized]\n"), 4541, 16);
  EXPECT_NEAR(defaults.input_seconds, 0.247, 1e-3);
  // Descriptor strategies make no BoW vectors.
  EXPECT_EQ(EstimateSweepSize(SizeConfig("robots: [2]\n"), 60000, 16).input_seconds, 0.0);
}

// synthetic_bow's words and vectors are inputs while they are made (SyntheticBowWords, then
// TfIdfFromWords): on 1000 frames at the defaults, each frame's 500 int32 words (2000 bytes), its
// term frequencies and its tf-idf vector, at most 500 words of 8 bytes each (8000), 24 bytes for
// each of the three vectors, and the idf's two tables of the 100000 words, 8 bytes each:
// 1000 x 10072 + 1600000 = 11 672 000 bytes, beside the descriptors ((1000 + 20000) x 16 x 4) and
// the paper protocol's neighbour lists (1000 x 64 x 8). A vocabulary of 300 words bounds a
// frame's vectors at 300 words: 1000 x (4000 + 4800 + 72) + 4800. Descriptor strategies make none.
TEST(SweepSizeTest, SyntheticBowWordsAndVectorsAreInputsWorkedByHand) {
  const std::string run = "robots: [2]\nruns: 1\nprotocols: [paper]\nstrategies: [bow_decentralized]\n";
  const SweepSize defaults = EstimateSweepSize(SizeConfig(run + "dataset: {dim: 16}\n"), 1000, 16);
  EXPECT_EQ(defaults.bow_bytes, 11672000.0);
  EXPECT_EQ(defaults.input_bytes, 11672000.0 + 21000.0 * 64 + 512000.0);
  const SweepSize small = EstimateSweepSize(
      SizeConfig(run + "dataset: {dim: 16, synthetic_bow: {features: 1000, vocabulary: 300}}\n"), 1000, 16);
  EXPECT_EQ(small.bow_bytes, 8876800.0);
  const SweepSize descriptors = EstimateSweepSize(SizeConfig("robots: [2]\nruns: 1\nprotocols: [paper]\n"), 1000, 16);
  EXPECT_EQ(descriptors.bow_bytes, 0.0);
  EXPECT_EQ(descriptors.input_bytes, 21000.0 * 64 + 512000.0);
}

// The default sweep (robots 2..20, paper and sim): the largest team's run is 4541^2 / 2 x 128 x
// 1e-10 = 0.132 s of search, 2 x 4541 x 20 x 1e-6 = 0.182 s of messages and 4541 x 25000 x
// 5e-10 = 0.057 s of verification payloads, 0.370 s (0.21 s measured on average); its 760 runs
// take 2.3 min on two cores by the model.
TEST(SweepSizeTest, TheDefaultSweepsEstimateWorkedByHand) {
  const SweepSize size = EstimateSweepSize(SizeConfig("seed: 1\n"), 4541, 128);
  EXPECT_NEAR(size.seconds_per_run, 0.37037, 1e-5);
  EXPECT_EQ(SizeError(size, {.memory_bytes = kGiB, .cores = 1}), "");
}

// link_state on 4 robots sharing 204 frames: 51 each, the last at 5.0 s. The daemon beacons at 0
// and every period while the next one is at most the last frame's time: HELLOs at 0, 1, ..., 5 s
// (6 a robot, 24), TCs at 0, 2 and 4 s (3 an origin), each sent on once by every other robot in
// a connected team (3 x 4 x 4 = 48). Each of the 72 transmissions and its 3 receptions:
// 72 x 4 x 1e-6 s.
TEST(SweepSizeTest, LinkStateBeaconsCountedByHand) {
  const std::string team = "robots: [4]\nruns: 1\nprotocols: [sim]\nstrategies: [broadcast]\n";
  const SweepSize size = EstimateSweepSize(
      SizeConfig(team + "network: {model: radio, routing: {kind: link_state, hello: 1s, topology: 2s}}\n"), 204, 8);
  EXPECT_DOUBLE_EQ(size.slowest.mission_s, 5.0);
  EXPECT_EQ(size.slowest.beacons, 24.0 + 48.0);
  EXPECT_DOUBLE_EQ(Seconds(size.slowest, SizeTerm::kBeacons), 72 * 4 * 1e-6);
  // A list of routings: the link_state variant's beacons; shortest_path sends none.
  const SweepSize listed = EstimateSweepSize(
      SizeConfig(team + "network: {model: radio, routing: [shortest_path, {kind: link_state, hello: 1s, topology: 2s}]}\n"),
      204, 8);
  EXPECT_EQ(listed.slowest.beacons, 72.0);
  EXPECT_EQ(EstimateSweepSize(SizeConfig(team + "network: {model: radio, routing: shortest_path}\n"), 204, 8).slowest.beacons,
            0.0);
}

// Beacons every microsecond on the default sweep (KITTI 00, robots 2..20): the team of 20 drives
// 227 s / 20, its last frame at 22.7 s: 20 x 22 700 001 HELLOs and 400 x 22 700 001 TCs, 9.53e9
// transmissions each heard by up to 19, 1.9e5 s a run.
TEST(SweepSizeTest, BeaconsEveryMicrosecondAreRefusedNamingTheRouting) {
  const SweepSize size = EstimateSweepSize(
      SizeConfig("network: {model: radio, routing: {kind: link_state, hello: 1us, topology: 1us}}\n"), 4541, 128);
  EXPECT_EQ(size.slowest.robots, 20);
  EXPECT_EQ(size.slowest.beacons, 420.0 * 22700001);
  EXPECT_EQ(SizeError(size, {.memory_bytes = 16 * kGiB, .cores = 2}),
            "c.yaml: network.routing: the sweep would take about 2.01e+04 h on 2 cores (760 runs of up to 1.91e+05 s "
            "each, 1.91e+05 s of it for 9.53e+09 link_state HELLO and TC transmissions of 20 robots in a mission of "
            "22.7 s, each heard by up to 19), more than 24 h; lengthen network.routing's hello and topology periods, "
            "or pass --allow-large to run it anyway");
}

// Failover's heartbeats on the same team: one a robot at 0, 0.25, ..., 5.0 s (21 a robot, 84),
// each heard by the 3 others.
TEST(SweepSizeTest, FailoverHeartbeatsCountedByHand) {
  const SweepSize size = EstimateSweepSize(
      SizeConfig("robots: [4]\nruns: 1\nprotocols: [sim]\nstrategies: [broadcast]\n"
             "failover: {enabled: true, heartbeat_period: 250ms, timeout: 1s}\n"),
      204, 8);
  EXPECT_EQ(size.slowest.heartbeats, 84.0);
  EXPECT_DOUBLE_EQ(Seconds(size.slowest, SizeTerm::kHeartbeats), 84 * 4 * 1e-6);
}

// Store-and-forward on radios that never meet, 2 robots x 21 frames (the last at 2.0 s): each
// robot's broadcast query of frame k (at k / 10 s) is held and asked again at every multiple of
// 100 ms after it until the end of the mission, 20 - k times, and once past it, where it is
// dropped (Network::SetHoldHorizon): 21 - k times, 231 a robot, 462 for the team (the model:
// 420 while held, and two more a copy, 84); each robot has a retry event at 0.1, ..., 2.0 s and
// one past the end, 42. With hold_time 500 ms a copy is asked 5 times (dropped at the fifth) or
// until the end: 17 x 5 + 4 + 3 + 2 + 1 = 95 a robot, 190 copy retries, which the model (frames
// spread evenly over the mission: 42 x (0.5 - 0.5^2 / (2 x 2)) / 0.1 = 183.75, and two a copy)
// makes 267.75.
TEST(SweepSizeTest, StoreAndForwardRetriesCountedByHand) {
  const std::string team = "robots: [2]\nruns: 1\nprotocols: [sim]\nstrategies: [broadcast]\n";
  const auto network = [&](const std::string& hold) {
    return SizeConfig(team + "network: {model: radio, routing: shortest_path, "
                         "disconnected: {kind: store_and_forward, hold_time: " + hold + "}}\n");
  };
  const SweepSize size = EstimateSweepSize(network("60s"), 42, 8);
  EXPECT_DOUBLE_EQ(size.slowest.mission_s, 2.0);
  EXPECT_EQ(size.slowest.held_copies, 42.0);
  EXPECT_DOUBLE_EQ(size.slowest.retries, 420.0 + 84.0 + 42.0);
  EXPECT_DOUBLE_EQ(Seconds(size.slowest, SizeTerm::kRetries), 546 * 1e-6);
  // Each held copy 160 bytes, and its query (each its own message here) 4 x 8 + 100 bytes, far
  // below hold_bytes.
  EXPECT_EQ(Bytes(size.slowest, SizeTerm::kHeld), 42.0 * (160 + 132));
  // The retries end with the mission, however long a copy may be held.
  EXPECT_DOUBLE_EQ(EstimateSweepSize(network("100000h"), 42, 8).slowest.retries, 546.0);
  EXPECT_DOUBLE_EQ(EstimateSweepSize(network("500ms"), 42, 8).slowest.retries, 183.75 + 84.0 + 42.0);
  // 3 robots x 21 frames: a broadcast query is 2 copies, and so is a decentralized row's (the
  // broadcast its relative AUC is against runs beside it), of one message; multi_probe_2's 2
  // copies are 2 messages, each held with its bytes.
  const std::string three = "robots: [3]\nruns: 1\nprotocols: [sim]\nnetwork: {model: radio, routing: shortest_path, "
                            "disconnected: store_and_forward}\n";
  EXPECT_DOUBLE_EQ(EstimateSweepSize(SizeConfig(three + "strategies: [broadcast]\n"), 63, 8).slowest.retries,
                   1260.0 + 252.0 + 63.0);
  const SweepSize decentralized = EstimateSweepSize(SizeConfig(three + "strategies: [decentralized]\n"), 63, 8);
  EXPECT_DOUBLE_EQ(decentralized.slowest.retries, 1260.0 + 252.0 + 63.0);
  EXPECT_EQ(Bytes(decentralized.slowest, SizeTerm::kHeld), 126.0 * 160 + 63.0 * 132);
  const SweepSize probes = EstimateSweepSize(SizeConfig(three + "strategies: [multi_probe_2]\n"), 63, 8);
  EXPECT_EQ(Bytes(probes.slowest, SizeTerm::kHeld), 126.0 * 160 + 126.0 * 132);
}

// A talk window that closes after the mission keeps the network holding until it does (a robot
// may still get a way then): robot 1 talks only in [5 s, 6 s), so the team of 2 x 21 frames
// (mission 2.0 s) holds its copies until 6 s: 42 copies sent evenly over [0, 2 s], held 5 s on
// average, 2100 retries while held and two more a copy, 84, and each robot's retry events at
// 0.1, ..., 6.0 s and one past it, 122.
TEST(SweepSizeTest, ATalkWindowAfterTheMissionExtendsTheRetries) {
  const std::filesystem::path dir = testing_support::FreshTestDir("sweep_size");
  std::ofstream(dir / "schedule.csv") << "robot,start_s,end_s\n1,5,6\n";
  const SweepSize size = EstimateSweepSize(
      SizeConfig("robots: [2]\nruns: 1\nprotocols: [sim]\nstrategies: [broadcast]\nnetwork: {model: radio, routing: "
             "shortest_path, disconnected: store_and_forward, schedule: '" + (dir / "schedule.csv").string() + "'}\n"),
      42, 8);
  EXPECT_DOUBLE_EQ(size.slowest.mission_s, 2.0);
  EXPECT_DOUBLE_EQ(size.slowest.retries, 2100.0 + 84.0 + 122.0);
}

// The mission comes from the team plan: 3 robots each driving 100 frames (9.9 s), staggered by
// 10 s, take their last frame at 29.9 s; reversed together, at 9.9 s; random_routes of 20 frames
// end by the sequence's last frame time, 9.9 s. A loaded plan gives its own latest capture.
TEST(SweepSizeTest, ThePlanSetsTheMission) {
  const std::string team = "robots: [3]\nruns: 1\nprotocols: [sim]\n";
  const SweepSize staggered = EstimateSweepSize(SizeConfig(team + "dataset: {scenario: {kind: staggered, offset: 10s}}\n"), 100, 8);
  EXPECT_EQ(staggered.slowest.frames, 300.0);
  EXPECT_DOUBLE_EQ(staggered.slowest.mission_s, 29.9);
  EXPECT_EQ(staggered.plan_key, "dataset.scenario");
  const SweepSize reverse = EstimateSweepSize(SizeConfig(team + "dataset: {scenario: {kind: reverse}}\n"), 100, 8);
  EXPECT_DOUBLE_EQ(reverse.slowest.mission_s, 9.9);
  const SweepSize routes =
      EstimateSweepSize(SizeConfig(team + "dataset: {scenario: {kind: random_routes, length: 20}}\n"), 100, 8);
  EXPECT_EQ(routes.slowest.frames, 60.0);
  EXPECT_DOUBLE_EQ(routes.slowest.mission_s, 9.9);
  // A loaded plan: robot 0 at 0, 0.1 and 0.2 s, robot 1 at 5 and 5.1 s; heartbeats every second:
  // 6 a robot.
  Dataset deployment;
  deployment.fps = 10;
  deployment.descriptors = DescriptorMatrix::Zero(5, 8);
  deployment.plan = PlannedSplit({{SimTime::Zero(), SimTime::Millis(100), SimTime::Millis(200)},
                                  {SimTime::Millis(5000), SimTime::Millis(5100)}});
  const SweepSize loaded = EstimateSweepSize(
      SizeConfig("robots: [2]\nruns: 1\nprotocols: [sim]\ndataset: {scenario: {kind: staggered, offset: 5s}}\n"
             "failover: {enabled: true, heartbeat_period: 1s, timeout: 2s}\n"),
      deployment);
  EXPECT_EQ(loaded.slowest.frames, 5.0);
  EXPECT_DOUBLE_EQ(loaded.slowest.mission_s, 5.1);
  EXPECT_EQ(loaded.slowest.heartbeats, 12.0);
}

// outputs.connectivity asks who reaches whom at every frame period from 0 to the last frame:
// 3 robots x 10 frames, the last at 0.9 s, 10 steps of 3 pairs (1e-6 + 3 x 2e-7 s each); each
// step is a row per strategy and the runs' snapshots, 3 x (600 + 8 x 3) bytes.
TEST(SweepSizeTest, ConnectivityStepsCountedByHand) {
  const SweepSize size = EstimateSweepSize(
      SizeConfig("robots: [3]\nruns: 1\nprotocols: [sim]\nstrategies: [decentralized, broadcast]\n"
             "network: {model: radio}\noutputs: {connectivity: true}\n"),
      30, 8);
  EXPECT_EQ(size.slowest.connectivity_steps, 10.0);
  EXPECT_DOUBLE_EQ(Seconds(size.slowest, SizeTerm::kConnectivity), 10 * 1.6e-6);
  EXPECT_EQ(Bytes(size.slowest, SizeTerm::kConnectivity), 10.0 * 3 * 624);
}

// A staggered team of 2 robots 100000 h apart with connectivity on (once killed at 1 GB after
// 7 s): the mission is 100000 h + 454 s, 3 600 004 541 steps of 3 x 616 bytes, 6.2e3 GiB a run.
TEST(SweepSizeTest, AConnectivityRowForEveryFramePeriodOf100000HoursIsRefusedNamingThePlan) {
  const SweepSize size = EstimateSweepSize(
      SizeConfig("robots: [2]\nruns: 1\nprotocols: [sim]\ndataset: {scenario: {kind: staggered, offset: 100000h}}\n"
             "network: {model: radio}\noutputs: {connectivity: true}\n"),
      4541, 128);
  EXPECT_EQ(size.largest.connectivity_steps, 3600004541.0);
  EXPECT_EQ(SizeError(size, {.memory_bytes = 16 * kGiB, .cores = 2}),
            "c.yaml: outputs.connectivity, dataset.scenario: 2 runs at once (one a thread) may need up to 1.24e+04 "
            "GiB, each up to 6.2e+03 GiB (6.2e+03 GiB a run of connectivity rows (3.6e+09 steps x (strategies + 1) x "
            "(600 + 8 x robots) bytes), and 0.0139 GiB of inputs made once), more than this machine's 16 GiB of "
            "memory; turn outputs.connectivity off or shorten the mission, run fewer at once (--threads), or pass "
            "--allow-large to run it anyway");
}

// Verification requests of 1 000 000 bytes, 2 robots x 50 frames: 100 requests, 1e8 bytes made,
// encoded and decoded, 0.05 s. In flight: on ideal links one a robot; on 10 Mbit/s links with
// queues of 100 packets none can go (a request is 676 packets: it is dropped, and freed, as it is
// sent); with queues of 1000 it goes, 0.81 s on the wire: a robot's one queue holds the request on
// the wire and floor(1000 / 676) = 1 waiting, and one more has left it and propagates its 2 ms:
// 3. Each robot keeps its own request too, and one is being sent or decoded.
TEST(SweepSizeTest, VerificationRequestsCountedByHand) {
  const std::string team = "robots: [2]\nruns: 1\nprotocols: [sim]\nstrategies: [broadcast]\n"
                           "verification: {request_bytes: 1000000}\n";
  const SweepSize ideal = EstimateSweepSize(SizeConfig(team + "network: {model: ideal}\n"), 100, 8);
  EXPECT_EQ(ideal.largest.requests, 100.0);
  EXPECT_EQ(ideal.largest.request_bytes, 1e8);
  EXPECT_DOUBLE_EQ(Seconds(ideal.largest, SizeTerm::kRequests), 0.05);
  EXPECT_EQ(ideal.largest.requests_in_flight, 1.0);
  EXPECT_EQ(Bytes(ideal.largest, SizeTerm::kRequests), 2 * 2 * 1e6 + 1e6);
  const SweepSize dropped = EstimateSweepSize(SizeConfig(team + "network: {queue_packets: 100}\n"), 100, 8);
  EXPECT_EQ(dropped.largest.requests_in_flight, 0.0);
  EXPECT_EQ(Bytes(dropped.largest, SizeTerm::kRequests), 2 * 1e6 + 1e6);
  const SweepSize queued = EstimateSweepSize(SizeConfig(team + "network: {queue_packets: 1000}\n"), 100, 8);
  EXPECT_EQ(queued.largest.requests_in_flight, 3.0);
  EXPECT_EQ(Bytes(queued.largest, SizeTerm::kRequests), 2 * 4 * 1e6 + 1e6);
}

// request_bytes 1 GiB, the documented maximum, on the default sweep (once killed at 2 GB after
// 6 s): the team of 20 keeps 20 requests, and one at a time is made and dropped as it is sent (it
// is 725 506 packets, for queues of 100), 21 GiB a run.
TEST(SweepSizeTest, GibibyteRequestsAreRefusedNamingTheRequestSize) {
  const SweepSize size = EstimateSweepSize(SizeConfig("verification: {request_bytes: 1GiB}\n"), 4541, 128);
  EXPECT_EQ(Bytes(size.largest, SizeTerm::kRequests), 21 * kGiB);
  EXPECT_EQ(SizeError(size, {.memory_bytes = 16 * kGiB, .cores = 2}),
            "c.yaml: verification.request_bytes: 2 runs at once (one a thread) may need up to 42 GiB, each up to 21 "
            "GiB (21 GiB a run of verification payloads (20 robots x (1 kept + 0 in flight) x request_bytes, and one "
            "being sent or decoded), and 0.0139 GiB of inputs made once), more than this machine's 16 GiB of memory; "
            "lower verification.request_bytes, run fewer at once (--threads), or pass --allow-large to run it anyway");
}

}  // namespace
}  // namespace dvpr
