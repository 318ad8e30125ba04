// The sweep-size model (sweep_size.h) against what small runs measure (issue 53: estimates stay
// within a factor of 3 of what a run measures, a test per term). Each test runs a team of a few
// robots on a prefix of KITTI 00 as `dvpr run` does (LoadSharedInputs, RunSweepInMemory), takes
// the count a term estimates from what the run reports - radio.csv's routing transmissions,
// messages.csv's rows and times, runs.csv's messages and duration, per_robot.csv's stored,
// connectivity.csv's rows; for store-and-forward's retries, which no file counts, the held
// copies' times and the simulator's events - and checks the estimate with the loaded inputs
// (EstimateSweepSize(config, deployment), what `dvpr run` checks) against it: at least what the
// run did, at most three times it. The counts in the comments are those of the runs when the
// tests were written.
#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "experiments/domain/strategies/run_placement.h"
#include "experiments/protocols/inputs.h"
#include "experiments/protocols/sim/simulation.h"
#include "experiments/protocols/strategy_inputs.h"
#include "experiments/sweep/run_sweep.h"
#include "experiments/sweep/sweep.h"
#include "experiments/sweep/sweep_size.h"
#include "lcmtypes/channels/channels.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

// At least the measured count (up to the estimate's rounding in its sums of doubles) and at most
// three times it.
void ExpectWithinThree(double estimate, double measured, const std::string& what) {
  EXPECT_GT(measured, 0) << what << ": the run did none";
  EXPECT_GE(estimate * (1 + 1e-9), measured) << what << ": the estimate " << estimate << " is below the run's "
                                             << measured;
  EXPECT_LE(estimate, 3 * measured) << what << ": the estimate " << estimate << " is more than 3 x the run's "
                                    << measured;
}

// The most copies of `role` one robot had on their way at once: sent and not yet delivered (a
// copy delivered at the instant another is sent has left first).
double MostInFlight(const std::vector<MessageRow>& rows, const std::string& role) {
  std::map<int, std::vector<std::pair<std::int64_t, int>>> changes;  // by sender: (time, +1 sent or -1 arrived)
  for (const MessageRow& m : rows) {
    if (m.role != role || !m.delivered_ns) continue;
    changes[m.src].emplace_back(m.sent_ns, 1);
    changes[m.src].emplace_back(*m.delivered_ns, -1);
  }
  int most = 0;
  for (auto& [robot, c] : changes) {
    std::sort(c.begin(), c.end());
    int now = 0;
    for (const auto& [t, d] : c) most = std::max(most, now += d);
  }
  return most;
}

// The failover heartbeats sent (messages.csv has a row per copy).
double HeartbeatsSent(const std::vector<MessageRow>& rows) {
  std::set<std::pair<int, std::int64_t>> sent;  // (robot, time)
  for (const MessageRow& m : rows) {
    if (channels::KindOf(m.channel) == channels::ChannelKind::kStatus) sent.emplace(m.src, m.sent_ns);
  }
  return static_cast<double>(sent.size());
}

class MeasuredSweepTest : public ::testing::Test {
 protected:
  // Loads a config of `dataset` (KITTI 00's poses), a small training set, one run of the sim
  // protocol and `rest`, and gives the sweep's estimate with the loaded inputs.
  SweepSize Load(const std::string& dataset, const std::string& rest) {
    config_ = ParseConfig("name: measured\nseed: 1\ndataset: " + dataset + "\ntraining: {synthetic: {samples: 500}}\n"
                          "runs: 1\nprotocols: [sim]\n" + rest,
                          DVPR_SOURCE_DIR, {}, "measured.yaml");
    inputs_ = LoadSharedInputs(config_, "measured.yaml");
    inputs_.out_dir = testing_support::FreshTestDir("sweep_size_measured");
    return EstimateSweepSize(config_, inputs_.deployment);
  }
  // The sweep's one run (robot count, run, network variant), all its strategies.
  RunOutput Run() const {
    std::vector<RunOutput> out = RunSweepInMemory(inputs_, {.threads = 1, .progress = false});
    EXPECT_EQ(out.size(), 1u);
    return out.empty() ? RunOutput{} : std::move(out.front());
  }
  // The team running broadcast on `network` as the sim protocol runs it, its log kept: the held
  // copies, every copy's row, the simulator's events and the time of the last.
  SimRunLog BroadcastLog(const NetworkModelParams& network) const {
    SimRunParams p;
    p.scenario.robots = config_.sweep.robots.front();
    p.scenario.agent = config_.agent;
    p.scenario.network = network;
    p.outputs.record_messages = true;
    const RunPlacement routing =
        BuildRunPlacement(ParseStrategy("broadcast"), StrategyInputsOf(inputs_), p.scenario.robots, 0);
    return RunSimulation(inputs_.deployment, *routing.As<StatelessFamily>()->team, p);
  }
  ExperimentConfig config_;
  SharedInputs inputs_;
};

// link_state on 5 robots sharing 153 frames (31 each, the last at 3.0 s), all in range of each
// other, HELLOs every 700 ms and TCs every 1300 ms: 5 x 5 HELLOs and 5 x 5 x 3 TC transmissions
// (each origin's TC sent on once by every other robot) by the model, 100; radio.csv's
// routing_transmissions 100.
TEST_F(MeasuredSweepTest, LinkStateBeaconsAgainstRadioCsv) {
  const SweepSize size = Load("{frames: 153, dim: 8}",
                              "robots: [5]\nstrategies: [broadcast]\noutputs: {figures: false}\n"
                              "network: {model: radio, radio: {range: 100km}, "
                              "routing: {kind: link_state, hello: 700ms, topology: 1300ms}}\n");
  const RunOutput out = Run();
  ASSERT_EQ(out.radio.size(), 1u);
  const double transmissions = static_cast<double>(out.radio[0].routing_transmissions);
  ExpectWithinThree(size.slowest.beacons, transmissions, "link_state beacons");
}

// Failover's heartbeats, 4 robots x 51 frames (the last at 5.0 s), every 250 ms from 0: 4 x 21 by
// the model, 84; messages.csv has 83 (robot 0's first, at 0 before the others listen, has no copy).
TEST_F(MeasuredSweepTest, FailoverHeartbeatsAgainstMessagesCsv) {
  const SweepSize size = Load("{frames: 204, dim: 8}",
                              "robots: [4]\nstrategies: [broadcast]\nnetwork: {model: ideal}\n"
                              "failover: {enabled: true, heartbeat_period: 250ms, timeout: 1s}\n"
                              "outputs: {figures: false, messages: true}\n");
  const RunOutput out = Run();
  ExpectWithinThree(size.slowest.heartbeats, HeartbeatsSent(out.messages), "failover heartbeats");
}

// Store-and-forward on radios that never meet (1 mm), 2 robots x 21 frames (the last at 2.0 s):
// the 42 broadcast queries are held (the model: 42), each until the first retry past the end of
// the mission, at 2.1 s, where it is dropped; the query of frame k is asked again 21 - k times
// (462 in all, from the copies' times and the run's end), and each robot retries at 0.1, ...,
// 2.1 s (42: the events the run has more than the same run with `drop`): 504. The model: 420
// while held, two more a copy (84) and the robots' 42, 546.
TEST_F(MeasuredSweepTest, StoreAndForwardRetriesAgainstTheSimulatorsEvents) {
  const SweepSize size = Load("{frames: 42, dim: 8}",
                              "robots: [2]\nstrategies: [broadcast]\noutputs: {figures: false}\n"
                              "network: {model: radio, radio: {range: 1mm}, routing: shortest_path, "
                              "disconnected: {kind: store_and_forward, hold_time: 60s}}\n");
  const std::vector<NetworkVariant> networks = ExpandNetworks(config_.network);
  ASSERT_EQ(networks.size(), 1u);
  NetworkModelParams drop = networks[0].params;
  drop.disconnected.kind = DisconnectedKind::kDrop;
  const SimRunLog held = BroadcastLog(networks[0].params);
  const SimRunLog dropped = BroadcastLog(drop);
  ExpectWithinThree(size.slowest.held_copies, static_cast<double>(held.routes.held), "copies held");
  // Every copy is held from its sending to the run's last event, the retry that drops it, and
  // asked again at every multiple of the retry period in between.
  const std::int64_t retry = networks[0].params.disconnected.retry.ns();
  double copy_retries = 0;
  for (const MessageRow& m : held.messages) {
    if (m.dropped) copy_retries += static_cast<double>(held.end.ns() / retry - m.sent_ns / retry);
  }
  ASSERT_GT(held.events, dropped.events);
  const double holder_retries = static_cast<double>(held.events - dropped.events);
  ExpectWithinThree(size.slowest.retries, copy_retries + holder_retries, "store-and-forward retries");
}

// Verification requests of 200 kB over 10 Mbit/s point-to-point links with queues of 1000
// packets, 4 robots x 75 frames, every match outside the 50-frame window verified: one request a
// query at most, 300 by the model; messages.csv has 290 (262 delivered, 28 lost at a full
// queue). In flight: a request is 136 packets, 0.162 s on the wire; a robot's 3 queues hold the
// one on the wire, floor(1000 / 136) = 7 waiting and 1 propagating each, 27 by the model; one
// robot had 13 on their way at once (messages.csv's times: its requests go as its queries'
// replies come in, bunched on the loaded links).
TEST_F(MeasuredSweepTest, VerificationRequestsAgainstMessagesCsv) {
  const SweepSize size = Load("{frames: 300, dim: 8}",
                              "robots: [4]\nstrategies: [broadcast]\nevaluation: {suppression_frames: 50}\n"
                              "verification: {max_distance: 1000000, request_bytes: 200000}\n"
                              "network: {model: point_to_point, queue_packets: 1000}\n"
                              "outputs: {figures: false, messages: true}\n");
  const RunOutput out = Run();
  const double requests = static_cast<double>(std::count_if(
      out.messages.begin(), out.messages.end(), [](const MessageRow& m) { return m.role == "verify_request"; }));
  ExpectWithinThree(size.largest.requests, requests, "verification requests");
  ExpectWithinThree(size.largest.request_bytes, requests * 200000, "verification request bytes");
  ExpectWithinThree(size.largest.requests_in_flight, MostInFlight(out.messages, "verify_request"),
                    "one robot's verification requests in flight");
}

// 4 robots x 50 frames on ideal links, every match verified: 2 x 200 x 4 = 1600 query and reply
// copies by the model against runs.csv's messages (broadcast's 1230: 600 queries, 600 replies, 15
// verification requests and results); 200 x 3 descriptors kept for replicate_1_r3 against
// per_robot.csv's stored (572; broadcast keeps each frame once, 200).
TEST_F(MeasuredSweepTest, MessagesAndStoresAgainstRunsAndPerRobotCsv) {
  const SweepSize size = Load("{frames: 200, dim: 8}",
                              "robots: [4]\nstrategies: [broadcast, replicate_1_r3]\nnetwork: {model: ideal}\n"
                              "evaluation: {suppression_frames: 0}\nverification: {max_distance: 1000000}\n"
                              "outputs: {figures: false}\n");
  const RunOutput out = Run();
  double messages = 0;
  for (const RunResult& r : out.runs) messages = std::max(messages, static_cast<double>(r.messages));
  ExpectWithinThree(size.slowest.messages, messages, "query, reply and verification copies");
  std::map<std::string, double> stored;  // by strategy
  for (const RobotLoadRow& r : out.per_robot) stored[r.key.strategy] += static_cast<double>(r.stored);
  ASSERT_EQ(stored.size(), 2u);
  ExpectWithinThree(size.largest.stored, std::max(stored["broadcast"], stored["replicate_1_r3"]), "descriptors kept");
}

// outputs.connectivity on 3 robots x 10 frames (the last at 0.9 s): a step every frame period
// from 0, 10 by the model; connectivity.csv has 10 rows for each strategy.
TEST_F(MeasuredSweepTest, ConnectivityStepsAgainstConnectivityCsv) {
  const SweepSize size = Load("{frames: 30, dim: 8}",
                              "robots: [3]\nstrategies: [decentralized, broadcast]\nnetwork: {model: radio}\n"
                              "outputs: {figures: false, connectivity: true}\n");
  const RunOutput out = Run();
  std::map<std::string, double> rows;  // by strategy
  for (const ConnectivityRow& r : out.connectivity) ++rows[r.key.strategy];
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& [strategy, count] : rows) ExpectWithinThree(size.largest.connectivity_steps, count, strategy);
}

// A staggered team of 3 robots 2.5 s apart, each driving 30 frames (2.9 s): the plan's last
// frame at 7.9 s, from the offsets before the plan is loaded and from the loaded plan, as
// runs.csv's duration (the last frame's time and one frame period, 8.0 s) says; the terms that
// last the mission follow it: 80 connectivity steps (connectivity.csv: 80 rows) and 3 x 16
// heartbeats every 500 ms (messages.csv: 47).
TEST_F(MeasuredSweepTest, APlansOffsetsSetTheMissionAsTheRunMeasuresIt) {
  const SweepSize size = Load("{frames: 30, dim: 8, scenario: {kind: staggered, offset: 2500ms}}",
                              "robots: [3]\nstrategies: [broadcast]\nnetwork: {model: radio, radio: {range: 100km}}\n"
                              "failover: {enabled: true, heartbeat_period: 500ms, timeout: 2s}\n"
                              "outputs: {figures: false, connectivity: true, messages: true}\n");
  const SweepSize before_loading = EstimateSweepSize(config_, 30, 8);
  const RunOutput out = Run();
  ASSERT_EQ(out.runs.size(), 1u);
  const double mission_s = out.runs[0].duration_s - 1 / config_.dataset.fps;
  ExpectWithinThree(size.slowest.mission_s, mission_s, "the loaded plan's mission");
  ExpectWithinThree(before_loading.slowest.mission_s, mission_s, "the offsets' mission");
  const double steps = static_cast<double>(out.connectivity.size());
  ExpectWithinThree(size.largest.connectivity_steps, steps, "connectivity steps");
  ExpectWithinThree(size.slowest.heartbeats, HeartbeatsSent(out.messages), "heartbeats over the plan");
}

}  // namespace
}  // namespace dvpr
