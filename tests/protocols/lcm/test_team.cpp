// Real agent processes over loopback multicast, each test in its own network
// namespace: a launched team matches the simulation on the ideal network; a
// team survives one of its agents being SIGKILLed; garbage and foreign
// messages on every channel are counted and ignored.
#include <arpa/inet.h>
#include <netinet/ip.h>
#include <netinet/udp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <set>
#include <thread>
#include <functional>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <span>
#include <sstream>

#include "agents/algorithms/bow_vector.h"
#include "agents/algorithms/bow_words.h"
#include "agents/algorithms/centroid_table.h"
#include "agents/auth/message_auth.h"
#include "agents/messages/team_sync.h"
#include "agents/placement/failure_detector.h"
#include "experiments/config/config.h"
#include "experiments/domain/data/split.h"
#include "experiments/domain/strategies/run_centroids.h"
#include "experiments/protocols/inputs.h"
#include "experiments/protocols/lcm/agent_log.h"
#include "experiments/protocols/lcm/lcm_launch.h"
#include "experiments/protocols/paper/static_protocol.h"
#include "experiments/protocols/sim/sim_protocol.h"
#include "lcm_test_support.h"
#include "tests/agents/udpm/datagram_builder.h"

namespace dvpr {
namespace {

using namespace lcm_test;

class LcmTeamTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string why = IsolateNetwork();
    if (!why.empty()) GTEST_SKIP() << why;
    dir_ = TestDir();
  }
  ExperimentConfig Config() const {
    std::vector<ConfigOverride> sets;
    for (const auto& s : SmallConfigSets()) sets.push_back(ParseOverride(s));
    return LoadConfig(ConfigPath(), sets);
  }
  fs::path dir_;
};

// Datagrams the kernel dropped at the agents of `strategy` because a receive buffer was full
// (agents.csv, SO_RXQ_OVFL): UDP may lose datagrams on a loaded machine, and the receiving side
// counts every one. A test of a real team tolerates a loss only when it is counted.
std::int64_t KernelDropped(const fs::path& agents_csv, const std::string& strategy) {
  std::int64_t n = 0;
  for (const Row& r : ReadCsv(agents_csv)) {
    if (r.at("strategy") == strategy && !r.at("kernel_dropped").empty()) n += std::stoll(r.at("kernel_dropped"));
  }
  return n;
}

// A query has one correct answer when its best candidate among the frames
// certainly stored before it was searched is strictly better than every frame
// whose storing may or may not have come first. Which frames are which is
// decided in two ways:
//
// - For the simulation, by virtual time (TimedReferences): on the ideal
//   network every frame taken `slack` or more periods before the query is
//   stored everywhere before it is searched; frames of the same or a
//   neighbouring period are open (event order at equal times).
// - For the real team, by what its own log shows (LoggedReferences), with no
//   assumption about how fast the machine is: query f was published at
//   sent(f) and its last reply came back at done(f) (agent time, one clock for
//   the whole team). A frame g is stored by its responder before its last reply
//   returns, and f is searched after sent(f) and before done(f). So g was
//   certainly stored when f was searched if done(g) < sent(f), certainly not if
//   sent(g) > done(f), and open otherwise. On a loaded machine a late process
//   only widens the open band; it never turns a wrong answer into a right one.
struct Reference {
  bool unambiguous = false;
  int frame = -1;
};

// Per frame: which frames were surely stored before it was searched (+1),
// surely not (-1), or open (0).
using Order = std::function<int(int query, int candidate)>;

std::vector<Reference> References(const Dataset& data, const CentroidTable* table, int window, const Order& order) {
  const int n = static_cast<int>(data.size());
  std::vector<Reference> refs(static_cast<std::size_t>(n));
  for (int f = 0; f < n; ++f) {
    float certain = std::numeric_limits<float>::infinity(), ambiguous = certain;
    int best = -1;
    for (int g = 0; g < n; ++g) {
      if (std::abs(f - g) <= window) continue;
      // Decentralized: only the owner of f's cluster searches, over what it stores.
      if (table != nullptr && table->RouteOf(data.descriptors.row(g).data()) != table->RouteOf(data.descriptors.row(f).data())) continue;
      const int o = order(f, g);
      if (o < 0) continue;
      const float d = (data.descriptors.row(f) - data.descriptors.row(g)).squaredNorm();
      if (o > 0) {
        if (d < certain) certain = d, best = g;
      } else {
        ambiguous = std::min(ambiguous, d);
      }
    }
    refs[static_cast<std::size_t>(f)] = {certain < ambiguous, best};
  }
  return refs;
}

std::vector<Reference> TimedReferences(const Dataset& data, const CentroidTable* table, int robots, int window, int slack) {
  const SequenceSplit split = SplitSequence(static_cast<int>(data.size()), robots);
  std::vector<int> step(data.size());
  for (const FrameRange& r : split.ranges)
    for (int k = 0; k < r.size(); ++k) step[static_cast<std::size_t>(r.begin.value + k)] = k;
  return References(data, table, window, [&](int f, int g) {
    const int dk = step[static_cast<std::size_t>(f)] - step[static_cast<std::size_t>(g)];
    return dk > slack ? 1 : dk < -slack ? -1 : 0;
  });
}

struct Logged {
  std::int64_t sent = 0;  // agent time, ns
  std::int64_t done = std::numeric_limits<std::int64_t>::max();  // last reply back; max when missing
};

std::vector<Reference> LoggedReferences(const Dataset& data, const CentroidTable* table, int window,
                                        const std::vector<Logged>& times) {
  // The agents' clocks share one epoch; 1 ms of agent time covers their offsets.
  constexpr std::int64_t kMargin = 1'000'000;
  return References(data, table, window, [&](int f, int g) {
    const Logged& q = times[static_cast<std::size_t>(f)];
    const Logged& c = times[static_cast<std::size_t>(g)];
    if (c.done < std::numeric_limits<std::int64_t>::max() - kMargin && c.done + kMargin < q.sent) return 1;
    if (q.done < std::numeric_limits<std::int64_t>::max() - kMargin && c.sent > q.done + kMargin) return -1;
    return 0;
  });
}

TEST_F(LcmTeamTest, LaunchedTeamMatchesTheIdealSimulation) {
  constexpr int kRobots = 4;
  constexpr double kSpeedup = 5;
  // A team that is done leaves at once; the grace only bounds how long a robot waits for a reply
  // that is late because its process was starved on a loaded machine.
  constexpr int kGraceSeconds = 60;
  // 10 fps x 5: a frame every 20 ms of wall time, long against loopback delivery.
  std::vector<std::string> launch{Dvpr(), "launch", "--config", ConfigPath(), "--robots", std::to_string(kRobots),
                                  "--speedup", "5", "--lcm", Url(7701), "--out", (dir_ / "lcm").string(),
                                  "--timeout", "240", "--grace", std::to_string(kGraceSeconds)};
  std::vector<std::string> sim{Dvpr(), "run", ConfigPath(), "--quiet", "--out", (dir_ / "sim").string(),
                               "--set", "protocols=[sim]", "--set", "robots=[4]", "--set", "runs=1",
                               "--set", "network.model=ideal"};
  for (const auto& s : SmallConfigSets()) {
    for (auto* argv : {&launch, &sim}) {
      argv->push_back("--set");
      argv->push_back(s);
    }
  }
  const int launched = WaitFor(Spawn(launch, dir_ / "launch.out"), std::chrono::seconds(300));
  ASSERT_TRUE(WIFEXITED(launched) && WEXITSTATUS(launched) == 0) << "see " << (dir_ / "launch.out");
  const int simulated = WaitFor(Spawn(sim, dir_ / "sim.out"), std::chrono::seconds(300));
  ASSERT_TRUE(WIFEXITED(simulated) && WEXITSTATUS(simulated) == 0) << "see " << (dir_ / "sim.out");

  const ExperimentConfig config = Config();
  const SharedInputs inputs = LoadSharedInputs(config, ConfigPath());
  const Dataset& data = inputs.deployment;
  // The paper's table of run 0: k-means as every protocol runs it (experiments/domain/strategies/).
  const CentroidTable table = CentroidTable::RoundRobin(
      RunCentroids(inputs.training, config.training.run_centroids, kRobots, 0), kRobots);
  const SequenceSplit split = SplitSequence(static_cast<int>(data.size()), kRobots);
  std::map<std::string, std::map<int, Row>> sim_rows, lcm_rows;
  for (const Row& r : ReadCsv(dir_ / "sim" / "queries.csv")) sim_rows[r.at("strategy")][std::stoi(r.at("frame"))] = r;
  std::size_t lcm_count = 0;
  for (const Row& r : ReadCsv(dir_ / "lcm" / "queries.csv")) {
    lcm_rows[r.at("strategy")][std::stoi(r.at("frame"))] = r;
    ++lcm_count;
  }
  ASSERT_EQ(lcm_count, 2u * 300u);  // both strategies, every frame

  for (const std::string strategy : {"decentralized", "broadcast"}) {
    SCOPED_TRACE(strategy);
    const CentroidTable* routed = strategy == "decentralized" ? &table : nullptr;
    ASSERT_EQ(lcm_rows[strategy].size(), data.size());
    std::vector<Logged> times(data.size());
    const std::int64_t kernel_dropped = KernelDropped(dir_ / "lcm" / "agents.csv", strategy);
    int missing = 0;
    for (const auto& [frame, r] : lcm_rows[strategy]) {
      EXPECT_EQ(r.at("protocol"), "lcm");
      missing += r.at("latency_ns").empty() ? 1 : 0;
      Logged& t = times[static_cast<std::size_t>(frame)];
      t.sent = std::stoll(r.at("sent_ns"));
      // latency_ns is wall time; the agents' clock runs kSpeedup times faster.
      if (!r.at("latency_ns").empty()) t.done = t.sent + std::llround(std::stod(r.at("latency_ns")) * kSpeedup);
    }
    // A reply may be missing only when the team counted a datagram lost to a full buffer.
    if (missing > 0) {
    EXPECT_GT(kernel_dropped, 0) << missing << " replies missing, no loss counted";
  }
    const std::vector<Reference> logged = LoggedReferences(data, routed, 20, times);
    const std::vector<Reference> timed = TimedReferences(data, routed, kRobots, 20, 1);
    int checked = 0, compared = 0, late = 0;
    for (int f = 0; f < static_cast<int>(data.size()); ++f) {
      const Row& l = lcm_rows[strategy].at(f);
      const Row& s = sim_rows.at(strategy).at(f);
      const Reference& lr = logged[static_cast<std::size_t>(f)];
      const Reference& sr = timed[static_cast<std::size_t>(f)];
      const auto name = [](int g) { return g < 0 ? std::string() : std::to_string(g); };
      if (lr.unambiguous) {
        ++checked;
        EXPECT_EQ(l.at("match_frame"), name(lr.frame)) << "frame " << f << ": the real team's answer";
        if (lr.frame >= 0) {
          EXPECT_EQ(l.at("match_robot"), std::to_string(split.owner[static_cast<std::size_t>(lr.frame)].value));
        }
      }
      if (sr.unambiguous) {
        EXPECT_EQ(s.at("match_frame"), name(sr.frame)) << "frame " << f << ": the simulation's answer";
      }
      // The real run differs from the simulation where the virtual-time order called the answer
      // certain: a process ran late (counted, not an error: the logged order above decides).
      if (sr.unambiguous && l.at("match_frame") != s.at("match_frame")) ++late;
      if (lr.unambiguous && sr.unambiguous && lr.frame == sr.frame) {
        ++compared;
        EXPECT_TRUE(l.at("match_robot") == s.at("match_robot") && l.at("match_frame") == s.at("match_frame") &&
                    l.at("distance") == s.at("distance"))
            << "frame " << f << ": lcm " << l.at("match_frame") << " " << l.at("distance") << ", sim "
            << s.at("match_frame") << " " << s.at("distance");
      }
    }
    std::cout << strategy << ": " << checked << " of " << data.size()
              << " queries with one possible answer in the real run's own order are right; " << compared
              << " of them are also unambiguous in the simulation and equal it; " << late
              << " differ from the simulation where only its virtual-time order is certain (late processes)\n";
    // The real run's order leaves most queries with one answer (own earlier frames outside the
    // window, stored seconds before); a test that checked few would mean little. How many depends
    // on the machine's load, not on the code (each late process makes some order uncertain):
    // broadcast checked 274 and compared 239 on a quiet machine, 198 and 184 under a load average
    // of 8 (which failed the floor of 200 this test had). The floor is a third of the queries.
    EXPECT_GE(checked, 100);
    EXPECT_GE(compared, 50);
  }
  // The runs.csv rows are there, with the broadcast reference.
  const std::vector<Row> runs = ReadCsv(dir_ / "lcm" / "runs.csv");
  ASSERT_EQ(runs.size(), 2u);
  for (const Row& r : runs) {
    EXPECT_EQ(r.at("protocol"), "lcm");
    // The first 300 frames hold no revisit, so AUC is 0; the reference is still filled.
    EXPECT_FALSE(r.at("auc_reference").empty());
    // Every message that did not arrive was dropped by a receiver's full buffer, and counted.
    EXPECT_LE(std::stoll(r.at("dropped_messages")), KernelDropped(dir_ / "lcm" / "agents.csv", r.at("strategy")));
  }
}

// The bag-of-words counterpart of References: query f's parts (words w mod n) go to their
// owners, each scores its part against the parts of the frames it stored (the sum over shared
// words of min weights, agents/algorithms/bow_vector.h) and returns its best; the querying robot votes
// (agents/algorithms/bow_words.h). A responder's answer is certain when its best among the frames surely
// stored beats every open frame's partial score (an open frame scoring as much could win or tie);
// the query's answer is unambiguous when every responder's is.
std::vector<Reference> BowReferences(const BowData& bow, int robots, int window, const Order& order) {
  const WordOwners owners = WordOwners::Modulo(bow.vocabulary, robots);
  const SequenceSplit split = SplitSequence(static_cast<int>(bow.frames.size()), robots);
  std::vector<std::vector<BowVector>> parts;
  for (const BowVector& v : bow.frames) parts.push_back(owners.Split(v));
  const int n = static_cast<int>(bow.frames.size());
  std::vector<Reference> refs(static_cast<std::size_t>(n));
  for (int f = 0; f < n; ++f) {
    bool unambiguous = true;
    std::vector<PartialMatch> answers;
    for (int r = 0; r < robots; ++r) {
      const BowVector& part = parts[static_cast<std::size_t>(f)][static_cast<std::size_t>(r)];
      if (part.empty()) continue;
      double certain = 0.0, open = 0.0;
      int best = -1;
      for (int g = 0; g < n; ++g) {
        const int o = std::abs(f - g) <= window ? -1 : order(f, g);
        if (o < 0) continue;
        const double s = SharedMinimum(part, parts[static_cast<std::size_t>(g)][static_cast<std::size_t>(r)]);
        if (s == 0.0) continue;
        if (o == 0) open = std::max(open, s);
        else if (s > certain) certain = s, best = g;  // g ascending: ties keep the lower frame
      }
      if (open > 0.0 && open >= certain) unambiguous = false;
      if (best >= 0) answers.push_back({RobotId(r), split.owner[static_cast<std::size_t>(best)], FrameId(best), certain});
    }
    const std::optional<VotedMatch> voted = Vote(answers);
    refs[static_cast<std::size_t>(f)] = {unambiguous, voted ? voted->frame.value : -1};
  }
  return refs;
}

// A launched bow_decentralized team (BoW agents, agents/bow_robot_agent.h) against the ideal
// simulation of the same team, as LaunchedTeamMatchesTheIdealSimulation does for the
// descriptors: each run is checked against the answers its own order makes certain, and the two
// must agree (frame, robot, distance) wherever both orders leave one answer.
TEST_F(LcmTeamTest, LaunchedBowTeamMatchesTheIdealSimulation) {
  constexpr int kRobots = 4;
  // Every agent receives every datagram of the group (udpm filters channels in user space), and
  // a BoW team sends n - 1 partial queries and replies per frame: at 3x real time a receive
  // buffer (4 MB, Url) holds about 3 s of the team's traffic, so an agent starved of CPU that long
  // on a loaded machine still loses nothing.
  constexpr double kSpeedup = 3;
  std::vector<std::string> sets = SmallConfigSets();
  sets.emplace_back("strategies=[bow_decentralized]");
  std::vector<std::string> launch{Dvpr(), "launch", "--config", ConfigPath(), "--robots", std::to_string(kRobots),
                                  "--speedup", std::to_string(kSpeedup), "--lcm", Url(7705),
                                  "--out", (dir_ / "lcm").string(),
                                  "--timeout", "240", "--grace", "60"};
  std::vector<std::string> sim{Dvpr(), "run", ConfigPath(), "--quiet", "--out", (dir_ / "sim").string(),
                               "--set", "protocols=[sim]", "--set", "robots=[4]", "--set", "runs=1",
                               "--set", "network.model=ideal"};
  for (const auto& s : sets) {
    for (auto* argv : {&launch, &sim}) {
      argv->push_back("--set");
      argv->push_back(s);
    }
  }
  const int launched = WaitFor(Spawn(launch, dir_ / "launch.out"), std::chrono::seconds(300));
  ASSERT_TRUE(WIFEXITED(launched) && WEXITSTATUS(launched) == 0) << "see " << (dir_ / "launch.out");
  const int simulated = WaitFor(Spawn(sim, dir_ / "sim.out"), std::chrono::seconds(300));
  ASSERT_TRUE(WIFEXITED(simulated) && WEXITSTATUS(simulated) == 0) << "see " << (dir_ / "sim.out");

  std::vector<ConfigOverride> overrides;
  for (const auto& s : sets) overrides.push_back(ParseOverride(s));
  const ExperimentConfig config = LoadConfig(ConfigPath(), overrides);
  const SharedInputs inputs = LoadSharedInputs(config, ConfigPath());
  const Dataset& data = inputs.deployment;
  ASSERT_EQ(inputs.bow.frames.size(), data.size());
  std::map<int, Row> sim_rows, lcm_rows;
  for (const Row& r : ReadCsv(dir_ / "sim" / "queries.csv")) {
    if (r.at("strategy") == "bow_decentralized") sim_rows[std::stoi(r.at("frame"))] = r;
  }
  for (const Row& r : ReadCsv(dir_ / "lcm" / "queries.csv")) lcm_rows[std::stoi(r.at("frame"))] = r;
  ASSERT_EQ(lcm_rows.size(), data.size());
  ASSERT_EQ(sim_rows.size(), data.size());

  std::vector<Logged> times(data.size());
  const std::int64_t kernel_dropped = KernelDropped(dir_ / "lcm" / "agents.csv", "bow_decentralized");
  int missing = 0;
  for (const auto& [frame, r] : lcm_rows) {
    EXPECT_EQ(r.at("strategy"), "bow_decentralized");
    missing += r.at("latency_ns").empty() ? 1 : 0;
    Logged& t = times[static_cast<std::size_t>(frame)];
    t.sent = std::stoll(r.at("sent_ns"));
    if (!r.at("latency_ns").empty()) t.done = t.sent + std::llround(std::stod(r.at("latency_ns")) * kSpeedup);
  }
  if (missing > 0) {
    EXPECT_GT(kernel_dropped, 0) << missing << " replies missing, no loss counted";
  }
  constexpr std::int64_t kMargin = 1'000'000;  // as LoggedReferences: the agents' clock offsets
  const std::vector<Reference> logged = BowReferences(inputs.bow, kRobots, 20, [&](int f, int g) {
    const Logged& q = times[static_cast<std::size_t>(f)];
    const Logged& c = times[static_cast<std::size_t>(g)];
    if (c.done < std::numeric_limits<std::int64_t>::max() - kMargin && c.done + kMargin < q.sent) return 1;
    if (q.done < std::numeric_limits<std::int64_t>::max() - kMargin && c.sent > q.done + kMargin) return -1;
    return 0;
  });
  const SequenceSplit split = SplitSequence(static_cast<int>(data.size()), kRobots);
  std::vector<int> step(data.size());
  for (const FrameRange& r : split.ranges)
    for (int k = 0; k < r.size(); ++k) step[static_cast<std::size_t>(r.begin.value + k)] = k;
  const std::vector<Reference> timed = BowReferences(inputs.bow, kRobots, 20, [&](int f, int g) {
    const int dk = step[static_cast<std::size_t>(f)] - step[static_cast<std::size_t>(g)];
    return dk > 1 ? 1 : dk < -1 ? -1 : 0;
  });
  int checked = 0, compared = 0, late = 0;
  const auto name = [](int g) { return g < 0 ? std::string() : std::to_string(g); };
  for (int f = 0; f < static_cast<int>(data.size()); ++f) {
    const Row& l = lcm_rows.at(f);
    const Row& s = sim_rows.at(f);
    const Reference& lr = logged[static_cast<std::size_t>(f)];
    const Reference& sr = timed[static_cast<std::size_t>(f)];
    if (lr.unambiguous) {
      ++checked;
      EXPECT_EQ(l.at("match_frame"), name(lr.frame)) << "frame " << f << ": the real team's answer";
    }
    if (sr.unambiguous) {
      EXPECT_EQ(s.at("match_frame"), name(sr.frame)) << "frame " << f << ": the simulation's answer";
    }
    if (sr.unambiguous && l.at("match_frame") != s.at("match_frame")) ++late;
    if (lr.unambiguous && sr.unambiguous && lr.frame == sr.frame) {
      ++compared;
      EXPECT_TRUE(l.at("match_robot") == s.at("match_robot") && l.at("match_frame") == s.at("match_frame") &&
                  l.at("distance") == s.at("distance"))
          << "frame " << f << ": lcm " << l.at("match_frame") << " " << l.at("distance") << ", sim "
          << s.at("match_frame") << " " << s.at("distance");
    }
  }
  std::cout << "bow_decentralized: " << checked << " of " << data.size()
            << " queries with one possible answer in the real run's own order are right; " << compared
            << " of them are also unambiguous in the simulation and equal it; " << late
            << " differ from the simulation where only its virtual-time order is certain (late processes)\n";
  // As above, a floor against a vacuous test, not a measure of the code (237 and 216 on a quiet
  // machine; fewer when processes run late).
  EXPECT_GE(checked, 100);
  EXPECT_GE(compared, 50);
  const std::vector<Row> runs = ReadCsv(dir_ / "lcm" / "runs.csv");
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].at("protocol"), "lcm");
  EXPECT_LE(std::stoll(runs[0].at("dropped_messages")), kernel_dropped);
}

// A broadcast team of 4 (every query is searched by every robot, so the victim matters whatever
// the routing's balance) whose robot 2 is SIGKILLed by its own process at 2.05 s of agent time
// (`dropout:`, between its frames 20 and 21: agent time is the team's shared clock, so nothing
// depends on when the test or any process happens to be scheduled; a timer due runs before a
// datagram is read, so the victim answers nothing sent after it). The others must still finish
// (at their deadline: robot 2 never announces done), and each of their queries taken after
// 2.05 s (frames 21..74 of each: 3 x 54 = 162) is counted as lost.
TEST_F(LcmTeamTest, KilledAgentDoesNotHangTheOthers) {
  constexpr int kRobots = 4, kVictim = 2, kPort = 7702;
  const SimTime kDeath = SimTime::Millis(2050);
  const std::string strategy = "broadcast";
  std::vector<pid_t> pids;
  for (int r = 0; r < kRobots; ++r) {
    // Grace 10 s: the survivors wait for robot 2 until then. A survivor whose process was starved
    // on a loaded machine has answered its backlog long before, so no message between survivors
    // is still under way when they leave (with 2 s, one was now and then, and counted dropped).
    std::vector<std::string> argv = AgentArgv(r, kRobots, strategy, kPort, 5.0, dir_ / ("r" + std::to_string(r) + ".log"), 10.0);
    argv.push_back("--set");
    argv.push_back("dropout=[{robot: " + std::to_string(kVictim) + ", at: 2050ms}]");
    pids.push_back(Spawn(argv, dir_ / ("r" + std::to_string(r) + ".out")));
  }
  const int victim_status = WaitFor(pids[kVictim], std::chrono::seconds(240));
  ASSERT_TRUE(WIFSIGNALED(victim_status) && WTERMSIG(victim_status) == SIGKILL) << "see " << dir_;

  std::vector<std::optional<AgentLog>> logs(kRobots);
  int after_death = 0;
  for (int r = 0; r < kRobots; ++r) {
    if (r == kVictim) continue;
    // Deadline: the team's last frame (75 frames at 50 fps: 1.5 s) + 10 s grace, after start-up.
    const int status = WaitFor(pids[static_cast<std::size_t>(r)], std::chrono::seconds(240));
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "robot " << r << " hung or failed; see " << dir_;
    logs[static_cast<std::size_t>(r)] = ReadAgentLog(dir_ / ("r" + std::to_string(r) + ".log"));
    const AgentLog& log = *logs[static_cast<std::size_t>(r)];
    EXPECT_EQ(log.end_reason, "deadline");
    EXPECT_EQ(log.queries.size(), 75u);  // every frame taken
    for (const QueryRecord& q : log.queries) {
      if (q.sent <= kDeath) continue;
      ++after_death;
      EXPECT_FALSE(q.Complete()) << "robot " << r << " frame " << q.frame.value << " answered by the dead robot";
    }
  }
  EXPECT_EQ(after_death, 3 * 54);
  EXPECT_FALSE(fs::exists(dir_ / ("r" + std::to_string(kVictim) + ".log")));
  const ExperimentConfig config = Config();
  const SharedInputs inputs = LoadSharedInputs(config, ConfigPath());
  const GatheredRun g = GatherTeam(config, inputs, strategy, kRobots, 0, logs, kNotApplicable);
  EXPECT_EQ(g.missing_robots, std::vector<int>{kVictim});
  EXPECT_EQ(g.queries, 3 * 75);
  EXPECT_GE(g.incomplete, 3 * 54) << "queries the dead robot never answered must be counted as lost";
  EXPECT_EQ(g.rows.runs.front().queries, 3 * 75);
  std::int64_t dropped_to_victim = 0;
  for (const LinkRow& l : g.rows.links) {
    if (l.dst == kVictim) {
      EXPECT_EQ(l.dropped, l.messages);
      dropped_to_victim += l.dropped;
    }
  }
  EXPECT_GT(dropped_to_victim, 0);
  EXPECT_EQ(g.rows.runs.front().dropped_messages, dropped_to_victim);
}

// Failover in a real team under `dvpr launch`: decentralized, 4 robots, 75 frames each (7.5 s of
// agent time at speedup 1). `dropout:` makes the victim's process SIGKILL itself at 1 s of agent
// time (after its frame 10); failover declares a robot lost after 2 s of agent time without a
// heartbeat; the detector's timers and the frames run in agent-time order (a timer due runs
// before a datagram is read), so a starved survivor still declares the victim lost before its
// later frames, which leave 4.5 s of queries to check. No timing is assumed beyond that: each survivor's own log says
// when it declared the victim lost, and every query of its own that the table routes to the
// victim and that it took after that instant must have been answered (by the successor). A
// survivor that was starved on a loaded machine and suspected for a moment is routed around,
// which costs recall, never an answer. Queries to the victim before the detection may be lost.
TEST_F(LcmTeamTest, KilledAgentsClustersAreServedByItsSuccessorAfterDetection) {
  constexpr int kRobots = 4;
  std::vector<std::string> sets = SmallConfigSets();
  for (const char* s : {"strategies=[decentralized]", "failover.enabled=true", "failover.timeout=2s"}) sets.emplace_back(s);
  std::vector<ConfigOverride> overrides;
  for (const auto& s : sets) overrides.push_back(ParseOverride(s));
  const ExperimentConfig config = LoadConfig(ConfigPath(), overrides);
  const SharedInputs inputs = LoadSharedInputs(config, ConfigPath());
  const Dataset& data = inputs.deployment;
  const CentroidTable table = CentroidTable::RoundRobin(
      RunCentroids(inputs.training, config.training.run_centroids, kRobots, 0), kRobots);
  // The victim: the robot the table sends most of the other robots' frames to (the first 300
  // frames of KITTI 00 fall into few clusters; a robot that owns none would test nothing).
  const SequenceSplit split = SplitSequence(static_cast<int>(data.size()), kRobots);
  std::vector<int> routed_from_others(kRobots, 0);
  for (int f = 0; f < static_cast<int>(data.size()); ++f) {
    const RobotId owner = table.RouteOf(data.descriptors.row(f).data());
    if (owner != split.owner[static_cast<std::size_t>(f)]) ++routed_from_others[static_cast<std::size_t>(owner.value)];
  }
  const int victim = static_cast<int>(std::max_element(routed_from_others.begin(), routed_from_others.end()) -
                                      routed_from_others.begin());
  ASSERT_GT(routed_from_others[static_cast<std::size_t>(victim)], 0);
  sets.push_back("dropout=[{robot: " + std::to_string(victim) + ", at: 1s}]");

  std::vector<std::string> launch{Dvpr(), "launch", "--config", ConfigPath(), "--robots", std::to_string(kRobots),
                                  "--speedup", "1", "--lcm", Url(7704), "--out", (dir_ / "lcm").string(),
                                  "--timeout", "300", "--grace", "15"};
  for (const auto& s : sets) {
    launch.push_back("--set");
    launch.push_back(s);
  }
  const int launched = WaitFor(Spawn(launch, dir_ / "launch.out"), std::chrono::seconds(400));
  // The dropped robot's SIGKILL is what the config asked for: launch exits 0.
  ASSERT_TRUE(WIFEXITED(launched) && WEXITSTATUS(launched) == 0) << "see " << (dir_ / "launch.out");

  const auto log_of = [&](int r) { return dir_ / "lcm" / "agents" / ("decentralized_robot" + std::to_string(r) + ".log"); };
  EXPECT_FALSE(fs::exists(log_of(victim))) << "the victim was not killed";
  int after = 0, lost_before = 0;
  for (int r = 0; r < kRobots; ++r) {
    if (r == victim) continue;
    SCOPED_TRACE("robot " + std::to_string(r));
    const AgentLog log = ReadAgentLog(log_of(r));
    EXPECT_EQ(log.queries.size(), 75u);
    const auto it = std::find_if(log.lost.begin(), log.lost.end(), [&](const LostRobot& l) { return l.robot == RobotId(victim); });
    ASSERT_NE(it, log.lost.end()) << "the victim was never declared lost";
    for (const QueryRecord& q : log.queries) {
      if (table.RouteOf(data.descriptors.row(q.frame.value).data()) != RobotId(victim)) continue;
      if (q.sent > it->detected) {
        ++after;
        EXPECT_TRUE(q.Complete()) << "frame " << q.frame.value << " taken after the victim was declared lost";
      } else {
        lost_before += q.Complete() ? 0 : 1;
      }
    }
  }
  std::cout << "victim robot " << victim << ": " << after << " queries to its clusters after its detection, all answered; "
            << lost_before << " before it lost\n";
  EXPECT_GT(after, 0);
}

// Garbage bytes, truncated messages, messages of the wrong type, a query whose
// length field lies, and well-formed messages from robots outside the team,
// on every channel the agents listen to, all run long: counted, ignored, and
// the team still finishes with every reply.
TEST_F(LcmTeamTest, GarbageOnEveryChannelIsCountedAndIgnored) {
  constexpr int kRobots = 3, kPort = 7703;
  std::vector<pid_t> pids;
  for (int r = 0; r < kRobots; ++r) {
    // Grace 60 s: every robot must end all_done, however long a starved process takes.
    pids.push_back(Spawn(AgentArgv(r, kRobots, "decentralized", kPort, 5.0, dir_ / ("r" + std::to_string(r) + ".log"), 60.0),
                         dir_ / ("r" + std::to_string(r) + ".out")));
  }
  LcmTransport noise(Url(kPort));
  std::vector<std::string> channels{"DVPR_STATUS", "DVPR_QUERY_ALL"};
  for (int r = 0; r < kRobots; ++r) {
    for (const char* prefix : {"DVPR_QUERY_", "DVPR_PROBE_", "DVPR_STORE_", "DVPR_MATCH_", "DVPR_VREQ_", "DVPR_VRES_"}) {
      channels.push_back(prefix + std::to_string(r));
    }
  }
  query_t foreign_query;
  foreign_query.robot = 99;  // not in the team
  foreign_query.frame = 5;
  foreign_query.dim = 128;
  foreign_query.descriptor.assign(128, 0.5f);
  const std::vector<std::uint8_t> full = Encode(foreign_query);
  const std::vector<std::uint8_t> truncated(full.begin(), full.begin() + 30);
  std::vector<std::uint8_t> lying = full;
  lying[22] = 0x7f;  // dim claims 32k floats
  lying[23] = 0xff;
  match_t wrong_type{};  // zeroed: encoding uninitialised fields is undefined (Release -Werror=maybe-uninitialized)
  agent_status_t foreign_status;
  foreign_status.robot = 1;
  foreign_status.robots = kRobots;
  foreign_status.team_key = 42;  // another team
  const std::vector<std::vector<std::uint8_t>> payloads{
      {}, {0x00}, {0xde, 0xad, 0xbe, 0xef, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17},
      truncated, lying, Encode(wrong_type), full, Encode(foreign_status)};

  // Each payload goes out twice: as it is (no tag: counted unauthenticated, never decoded) and
  // sealed with the team's secret by an insider speaking as robot 99 (a holder of the secret that
  // is no robot of the team): those reach the decoders, which count them malformed or foreign.
  auth::MessageAuth insider(auth::ReadSecretFile(TeamSecret(dir_)), 99);
  std::vector<int> status(kRobots, -2);
  int rounds = 0;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(240);
  auto running = [&] { return std::count(status.begin(), status.end(), -2) > 0; };
  while (running() && std::chrono::steady_clock::now() < give_up) {
    for (const auto& c : channels) {
      for (const auto& p : payloads) {
        noise.PublishRaw(c, p);
        std::vector<std::uint8_t> sealed = p;
        insider.Seal(c, sealed);
        noise.PublishRaw(c, sealed);
      }
    }
    ++rounds;
    noise.RunUntilWall(std::chrono::steady_clock::now() + std::chrono::milliseconds(30));
    for (int r = 0; r < kRobots; ++r) {
      int st = 0;
      if (status[static_cast<std::size_t>(r)] == -2 && waitpid(pids[static_cast<std::size_t>(r)], &st, WNOHANG) > 0) {
        status[static_cast<std::size_t>(r)] = st;
      }
    }
  }
  std::vector<AgentLog> logs;
  std::uint64_t kernel_dropped = 0;
  for (int r = 0; r < kRobots; ++r) {
    if (status[static_cast<std::size_t>(r)] == -2) status[static_cast<std::size_t>(r)] = WaitFor(pids[static_cast<std::size_t>(r)], std::chrono::seconds(1));
    ASSERT_TRUE(WIFEXITED(status[static_cast<std::size_t>(r)]) && WEXITSTATUS(status[static_cast<std::size_t>(r)]) == 0)
        << "robot " << r << "; see " << dir_;
    logs.push_back(ReadAgentLog(dir_ / ("r" + std::to_string(r) + ".log")));
    kernel_dropped += logs.back().kernel_dropped;
  }
  for (int r = 0; r < kRobots; ++r) {
    const AgentLog& log = logs[static_cast<std::size_t>(r)];
    // The noise can fill a starved agent's receive buffer: a query may then miss a reply (and its
    // robot end at the deadline), but only when the loss was counted.
    const auto incomplete = std::count_if(log.queries.begin(), log.queries.end(), [](const QueryRecord& q) { return !q.Complete(); });
    if (incomplete > 0 || log.end_reason != "all_done") {
      EXPECT_GT(kernel_dropped, 0u) << "robot " << r << ": " << incomplete << " queries incomplete, no loss counted";
    }
    EXPECT_EQ(log.queries.size(), 100u);
    EXPECT_GT(log.malformed, 0u) << "robot " << r;
    EXPECT_GT(log.foreign, 0u) << "robot " << r;
    EXPECT_GT(log.unauthenticated, 0u) << "robot " << r;
    std::cout << "robot " << r << ": " << log.malformed << " malformed, " << log.foreign << " foreign, " << incomplete
              << " incomplete, over " << rounds << " rounds of noise (" << kernel_dropped << " dropped by full buffers)\n";
  }
}

// --- hostile networks ---

// The frames each robot of a decentralized team stores: those the table of run 0 routes to it
// (each query is kept by its cluster's owner, and only there).
std::vector<std::int64_t> StoredByPlacement(const ExperimentConfig& config, int robots) {
  const SharedInputs inputs = LoadSharedInputs(config, ConfigPath());
  const CentroidTable table = CentroidTable::RoundRobin(
      RunCentroids(inputs.training, config.training.run_centroids, robots, 0), robots);
  std::vector<std::int64_t> stored(static_cast<std::size_t>(robots), 0);
  for (int f = 0; f < static_cast<int>(inputs.deployment.size()); ++f) {
    ++stored[static_cast<std::size_t>(table.RouteOf(inputs.deployment.descriptors.row(f).data()).value)];
  }
  return stored;
}

std::vector<std::string> SmallLaunch(const fs::path& out, int port, int robots, const std::vector<std::string>& extra,
                                     int speedup = 5) {
  std::vector<std::string> launch{Dvpr(), "launch", "--config", ConfigPath(), "--robots", std::to_string(robots),
                                  "--speedup", std::to_string(speedup), "--lcm", Url(port), "--out", out.string(),
                                  "--timeout", "240", "--grace", "60"};
  std::vector<std::string> sets = SmallConfigSets();
  sets.insert(sets.end(), extra.begin(), extra.end());
  for (const auto& s : sets) {
    launch.push_back("--set");
    launch.push_back(s);
  }
  return launch;
}

// What a launched decentralized team stored, per robot (per_robot.csv), and its agents' rows.
// UDP may lose a datagram on a loaded machine, and the agents count each one (kernel_dropped): a
// query lost on its way leaves its owner with one frame fewer and no reply. So each robot stores
// exactly its table's frames when nothing was lost, and never more (a merged team stores more:
// the other team's frames); a reply may be missing only when a loss was counted.
void ExpectTheTeamsOwnResults(const fs::path& out, const std::vector<std::int64_t>& stored, std::size_t frames) {
  const std::int64_t dropped = KernelDropped(out / "agents.csv", "decentralized");
  std::vector<std::int64_t> got;
  for (const Row& r : ReadCsv(out / "per_robot.csv")) got.push_back(std::stoll(r.at("stored")));
  if (dropped == 0) {
    EXPECT_EQ(got, stored) << out;
  } else {
    ASSERT_EQ(got.size(), stored.size()) << out;
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_LE(got[i], stored[i]) << out << " robot " << i;
  }
  EXPECT_EQ(ReadCsv(out / "queries.csv").size(), frames) << out;
  int missing = 0;
  for (const Row& r : ReadCsv(out / "queries.csv")) missing += r.at("latency_ns").empty() ? 1 : 0;
  if (missing > 0) {
    EXPECT_GT(dropped, 0) << out << ": " << missing << " replies missing, no loss counted";
  }
}

// Two launches of one config on one URL at once: each launch draws its own team nonce, so the two
// teams take neither each other's heartbeats nor each other's messages (each robot's sender is
// learned from its own team's heartbeats). Each stores exactly what its own table routes to each
// robot (merged, robots stored both teams' frames: issue 31 saw 376 instead of 248), and every
// agent counts the other team as unauthenticated (another secret). The teams must run at once for that: at speedup 1 each
// runs 15 s of frames after its start barrier, far longer than one launch's agents may start
// after the other's on a loaded machine (at speedup 5 a run lasts 3 s, which loading the inputs
// under a load average of 8 can exceed).
TEST_F(LcmTeamTest, TwoLaunchesOfOneConfigOnOneUrlAreTwoTeams) {
  constexpr int kRobots = 3;
  const std::vector<std::string> extra{"strategies=[decentralized]", "dataset.frames=150"};
  const pid_t a = Spawn(SmallLaunch(dir_ / "a", 7706, kRobots, extra, 1), dir_ / "a.out");
  const pid_t b = Spawn(SmallLaunch(dir_ / "b", 7706, kRobots, extra, 1), dir_ / "b.out");
  for (const auto& [pid, name] : {std::pair{a, "a"}, std::pair{b, "b"}}) {
    const int status = WaitFor(pid, std::chrono::seconds(300));
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "see " << (dir_ / (std::string(name) + ".out"));
  }
  std::vector<ConfigOverride> overrides;
  for (const auto& s : SmallConfigSets()) overrides.push_back(ParseOverride(s));
  for (const auto& s : extra) overrides.push_back(ParseOverride(s));
  const std::vector<std::int64_t> stored = StoredByPlacement(LoadConfig(ConfigPath(), overrides), kRobots);
  ASSERT_EQ(std::accumulate(stored.begin(), stored.end(), std::int64_t{0}), 150);
  for (const char* name : {"a", "b"}) {
    SCOPED_TRACE(name);
    ExpectTheTeamsOwnResults(dir_ / name, stored, 150);
    for (const Row& r : ReadCsv(dir_ / name / "agents.csv")) {
      // The other team's messages carry another launch's secret: their tags do not verify.
      EXPECT_GT(std::stoll(r.at("unauthenticated")), 0) << "robot " << r.at("robot") << " never heard the other team";
    }
  }
}

// Sends `datagram` to the group on `port` through the raw socket `raw`, as if `from` had sent it
// (the raw socket writes the IP and UDP headers, source address and port included). True when sent.
bool SendAs(int raw, const sockaddr_in& from, int port, std::span<const std::uint8_t> datagram) {
  std::vector<std::uint8_t> packet(sizeof(iphdr) + sizeof(udphdr) + datagram.size());
  auto* ip = reinterpret_cast<iphdr*>(packet.data());
  ip->version = 4;
  ip->ihl = 5;
  ip->ttl = 1;
  ip->protocol = IPPROTO_UDP;
  ip->saddr = from.sin_addr.s_addr;
  inet_pton(AF_INET, "239.255.76.67", &ip->daddr);
  auto* udp = reinterpret_cast<udphdr*>(packet.data() + sizeof(iphdr));
  udp->source = from.sin_port;
  udp->dest = htons(static_cast<std::uint16_t>(port));
  udp->len = htons(static_cast<std::uint16_t>(sizeof(udphdr) + datagram.size()));
  std::copy(datagram.begin(), datagram.end(), packet.begin() + sizeof(iphdr) + sizeof(udphdr));
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_addr.s_addr = ip->daddr;
  return sendto(raw, packet.data(), packet.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to) > 0;
}

// A socket (close-on-exec: agents started later do not inherit it) that hears the group on
// `port`; its address goes to *group. -1 when it cannot be made.
int ListenOnGroup(int port, sockaddr_in* group) {
  const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  const int on = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
  ip_mreq m{};
  inet_pton(AF_INET, "239.255.76.67", &m.imr_multiaddr);
  setsockopt(fd, IPPROTO_IP, IP_ADD_MEMBERSHIP, &m, sizeof m);
  *group = sockaddr_in{};
  group->sin_family = AF_INET;
  group->sin_addr = m.imr_multiaddr;
  group->sin_port = htons(static_cast<std::uint16_t>(port));
  if (bind(fd, reinterpret_cast<const sockaddr*>(group), sizeof *group) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

// Sends every datagram of the group once more, from its own sender (a raw socket writes the IP
// and UDP headers, so the copy has the original's source address and port): a network that
// duplicates every packet.
class DuplicatingRelay {
 public:
  explicit DuplicatingRelay(int port) : port_(port) {
    sockaddr_in group{};
    listen_ = ListenOnGroup(port, &group);
    raw_ = socket(AF_INET, SOCK_RAW | SOCK_CLOEXEC, IPPROTO_RAW);
    ok_ = listen_ >= 0 && raw_ >= 0;
    if (ok_) thread_ = std::thread([this] { Loop(); });
  }
  ~DuplicatingRelay() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    close(listen_);
    close(raw_);
  }
  bool ok() const { return ok_; }
  std::uint64_t copies() const { return copies_; }

 private:
  void Loop() {
    std::vector<std::uint8_t> buffer(65536);
    std::set<std::string> seen;  // sender, size and LCM header of each datagram relayed
    while (!stop_) {
      pollfd p{listen_, POLLIN, 0};
      timespec wait{0, 20000000};
      if (ppoll(&p, 1, &wait, nullptr) <= 0) continue;
      sockaddr_in from{};
      socklen_t length = sizeof from;
      const ssize_t n = recvfrom(listen_, buffer.data(), buffer.size(), 0, reinterpret_cast<sockaddr*>(&from), &length);
      if (n <= 0) continue;
      std::string key(reinterpret_cast<const char*>(&from.sin_addr), 4);
      key.append(reinterpret_cast<const char*>(&from.sin_port), 2);
      key += std::to_string(n) + ":";
      key.append(reinterpret_cast<const char*>(buffer.data()), static_cast<std::size_t>(std::min<ssize_t>(n, 20)));
      if (!seen.insert(key).second) continue;  // our own copy coming back
      if (SendAs(raw_, from, port_, std::span<const std::uint8_t>(buffer.data(), static_cast<std::size_t>(n)))) ++copies_;
    }
  }

  int port_;
  int listen_ = -1, raw_ = -1;
  bool ok_ = false;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> copies_{0};
  std::thread thread_;
};

// Every datagram arrives twice (the relay's copy has the original's sender and sequence
// number): each agent recognises and counts the copies and takes each message once, so the team
// stores exactly what a clean network gives (its table's routing, worked out here).
TEST_F(LcmTeamTest, ADuplicatingNetworkGivesTheCountsOfACleanOne) {
  constexpr int kRobots = 3;
  DuplicatingRelay relay(7707);
  if (!relay.ok()) GTEST_SKIP() << "no raw socket for the duplicating relay";
  const std::vector<std::string> extra{"strategies=[decentralized]", "dataset.frames=150"};
  const int status = WaitFor(Spawn(SmallLaunch(dir_ / "lcm", 7707, kRobots, extra), dir_ / "launch.out"),
                             std::chrono::seconds(300));
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "see " << (dir_ / "launch.out");
  EXPECT_GT(relay.copies(), 0u);
  std::vector<ConfigOverride> overrides;
  for (const auto& s : SmallConfigSets()) overrides.push_back(ParseOverride(s));
  for (const auto& s : extra) overrides.push_back(ParseOverride(s));
  ExpectTheTeamsOwnResults(dir_ / "lcm", StoredByPlacement(LoadConfig(ConfigPath(), overrides), kRobots), 150);
  for (const Row& r : ReadCsv(dir_ / "lcm" / "agents.csv")) {
    EXPECT_GT(std::stoll(r.at("duplicates")), 0) << "robot " << r.at("robot");
    EXPECT_EQ(r.at("malformed_datagrams"), "0") << "robot " << r.at("robot");
  }
  const std::vector<Row> links = ReadCsv(dir_ / "lcm" / "links.csv");
  for (const Row& l : links) {
    EXPECT_LE(std::stoll(l.at("dropped")), 0) << "a message was lost or, taken twice, hid a loss";
  }
}

// The UDP sockets of `pid` (inodes from /proc/PID/fd), with their receive queues and drop counts
// from /proc/net/udp: what the kernel still holds for the process, and what it dropped.
struct SocketQueue {
  std::int64_t queued = 0;
  std::int64_t drops = 0;
};
std::vector<SocketQueue> UdpQueuesOf(pid_t pid, int port) {
  std::set<std::string> inodes;
  const fs::path fds = "/proc/" + std::to_string(pid) + "/fd";
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(fds, ec)) {
    const std::string target = fs::read_symlink(e.path(), ec).string();
    if (target.rfind("socket:[", 0) == 0) inodes.insert(target.substr(8, target.size() - 9));
  }
  std::vector<SocketQueue> queues;
  std::ifstream udp("/proc/net/udp");
  std::string line;
  std::getline(udp, line);
  char hex_port[8];
  std::snprintf(hex_port, sizeof hex_port, ":%04X", port);
  while (std::getline(udp, line)) {
    std::istringstream in(line);
    std::string slot, local, remote, state, queues_text, timer, retransmits, uid, timeout, inode, ref, pointer, drops;
    in >> slot >> local >> remote >> state >> queues_text >> timer >> retransmits >> uid >> timeout >> inode >> ref >>
        pointer >> drops;
    if (inodes.count(inode) == 0 || local.size() < 5 || local.substr(local.size() - 5) != hex_port) continue;
    queues.push_back({std::stoll(queues_text.substr(queues_text.find(':') + 1), nullptr, 16), std::stoll(drops)});
  }
  return queues;
}

// The crafted fragment of issue 31 (2^28 bytes claimed, offset 0xFFFFFFF0) and 10^5 datagrams
// malformed by construction reach the agents of a team, which count every one and go on to a
// complete run. Two of a team of three wait in the start barrier (their third is not started
// yet) while the test sends, 200 datagrams at a time, each batch once the kernel holds nothing
// more for them (/proc/net/udp: an event, not a time); then robot 2 starts and the team runs.
TEST_F(LcmTeamTest, TheWrappingFragmentAndAHundredThousandHostileDatagramsAreCountedAndSurvived) {
  constexpr int kRobots = 3, kPort = 7708;
  std::vector<pid_t> pids;
  const auto argv = [&](int r) {
    std::vector<std::string> a = AgentArgv(r, kRobots, "decentralized", kPort, 5.0, dir_ / ("r" + std::to_string(r) + ".log"), 60.0);
    a.insert(a.end(), {"--barrier-timeout", "1000", "--set", "dataset.frames=150"});
    return a;
  };
  for (int r = 0; r < 2; ++r) pids.push_back(Spawn(argv(r), dir_ / ("r" + std::to_string(r) + ".out")));
  const int sender = socket(AF_INET, SOCK_DGRAM, 0);
  ASSERT_GE(sender, 0);
  sockaddr_in group{};
  group.sin_family = AF_INET;
  inet_pton(AF_INET, "239.255.76.67", &group.sin_addr);
  group.sin_port = htons(kPort);
  const auto send = [&](const std::vector<std::uint8_t>& d) {
    sendto(sender, d.data(), d.size(), 0, reinterpret_cast<const sockaddr*>(&group), sizeof group);
  };
  // Both receive sockets open (an agent opens its socket before loading its inputs).
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(240);
  const auto drained = [&] {
    for (const pid_t pid : {pids[0], pids[1]}) {
      const std::vector<SocketQueue> q = UdpQueuesOf(pid, kPort);
      if (q.size() != 1 || q[0].queued != 0) return false;
    }
    return true;
  };
  const auto wait_until_drained = [&] {
    while (!drained() && std::chrono::steady_clock::now() < give_up) {
      timespec ts{0, 1000000};
      ppoll(nullptr, 0, &ts, nullptr);
    }
    return std::chrono::steady_clock::now() < give_up;
  };
  ASSERT_TRUE(wait_until_drained()) << "the agents never opened their sockets; see " << dir_;
  send(udpm_test::WrappingFragment());
  udpm_test::HostileDatagrams hostile(31);
  for (int sent = 0; sent < 100000;) {
    for (int k = 0; k < 200; ++k, ++sent) send(hostile.Next());
    ASSERT_TRUE(wait_until_drained()) << "after " << sent << " datagrams; see " << dir_;
  }
  close(sender);
  for (int r = 0; r < 2; ++r) {
    const pid_t pid = pids[static_cast<std::size_t>(r)];
    EXPECT_EQ(waitpid(pid, nullptr, WNOHANG), 0) << "robot " << r << " did not survive the flood; see " << dir_;
  }
  pids.push_back(Spawn(argv(2), dir_ / "r2.out"));
  for (int r = 0; r < kRobots; ++r) {
    const int status = WaitFor(pids[static_cast<std::size_t>(r)], std::chrono::seconds(300));
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "robot " << r << "; see " << dir_;
    const AgentLog log = ReadAgentLog(dir_ / ("r" + std::to_string(r) + ".log"));
    EXPECT_EQ(log.queries.size(), 50u);
    for (const QueryRecord& q : log.queries) EXPECT_TRUE(q.Complete()) << "robot " << r << " frame " << q.frame.value;
    if (r < 2) {
      // Every one counted: read and found malformed, or dropped by a full buffer (and counted).
      EXPECT_LE(log.malformed_datagrams, 100001u) << "robot " << r;
      EXPECT_GE(log.malformed_datagrams + log.kernel_dropped, 100001u) << "robot " << r;
    } else {
      EXPECT_EQ(log.malformed_datagrams, 0u);  // it started after the flood
    }
    std::cout << "robot " << r << ": " << log.malformed_datagrams << " malformed datagrams, " << log.kernel_dropped
              << " dropped by a full buffer, " << log.datagrams << " datagrams\n";
  }
}


// The peak resident memory of `pid` (VmHWM of /proc/PID/status), in bytes; -1 when unreadable.
std::int64_t PeakMemory(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stoll(line.substr(6)) * 1024;  // "VmHWM:  1234 kB"
  }
  return -1;
}

// A forger on the team's group (issue 53), who knows everything anyone listening learns - the
// heartbeats with their team key, every sender's address, port and sequence numbers - but not the
// team's secret. For each heartbeat of robot 0 it hears it sends that heartbeat relabelled as
// robot 1's (team key included, robot 0's trailer kept), and from robot 0's own address and port
// (a raw socket) 64 datagrams numbered as robot 0's next messages; it runs from before robot 1
// starts to the end of the run.
class Forger {
 public:
  explicit Forger(int port) : port_(port) {
    // Close-on-exec: the agents the test starts must not inherit the forger's sockets (its
    // listening one would be a second socket of theirs on the group's port).
    listen_ = ListenOnGroup(port, &group_);
    raw_ = socket(AF_INET, SOCK_RAW | SOCK_CLOEXEC, IPPROTO_RAW);
    own_ = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    ok_ = listen_ >= 0 && raw_ >= 0 && own_ >= 0;
    if (ok_) thread_ = std::thread([this] { Loop(); });
  }
  ~Forger() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    close(listen_);
    close(raw_);
    close(own_);
  }
  bool ok() const { return ok_; }
  std::uint64_t relabelled() const { return relabelled_; }
  std::uint64_t spoofed() const { return spoofed_; }
  // While paused it only listens (the test's flood then waits for quiet queues).
  void Pause(bool paused) { paused_ = paused; }
  // Sends `d` from the forger's own socket.
  void Send(const std::vector<std::uint8_t>& d) const {
    sendto(own_, d.data(), d.size(), 0, reinterpret_cast<const sockaddr*>(&group_), sizeof group_);
  }

 private:
  void Spoof(const sockaddr_in& from, const std::vector<std::uint8_t>& d) {
    if (SendAs(raw_, from, port_, d)) ++spoofed_;
  }

  void Loop() {
    std::vector<std::uint8_t> buffer(65536);
    const std::string status = "DVPR_STATUS";
    while (!stop_) {
      pollfd p{listen_, POLLIN, 0};
      timespec wait{0, 20000000};
      if (ppoll(&p, 1, &wait, nullptr) <= 0) continue;
      sockaddr_in from{};
      socklen_t length = sizeof from;
      const ssize_t n = recvfrom(listen_, buffer.data(), buffer.size(), 0, reinterpret_cast<sockaddr*>(&from), &length);
      if (paused_) continue;
      // A heartbeat: "LC02", seqno, "DVPR_STATUS" NUL, agent_status_t, then the 34-byte trailer.
      const std::size_t header = 8 + status.size() + 1;
      if (n < static_cast<ssize_t>(header + 34) || std::memcmp(buffer.data(), "LC02", 4) != 0 ||
          std::memcmp(buffer.data() + 8, status.c_str(), status.size() + 1) != 0) {
        continue;
      }
      const std::size_t payload = static_cast<std::size_t>(n) - header - 34;
      std::optional<agent_status_t> s = Decode<agent_status_t>(std::span<const std::uint8_t>(buffer.data() + header, payload));
      if (!s || s->robot != 0) continue;
      const std::uint32_t seqno = (std::uint32_t{buffer[4]} << 24) | (std::uint32_t{buffer[5]} << 16) |
                                  (std::uint32_t{buffer[6]} << 8) | buffer[7];
      // Robot 0's heartbeat, relabelled as robot 1's, with robot 0's trailer.
      s->robot = 1;
      std::vector<std::uint8_t> forged = Encode(*s);
      forged.insert(forged.end(), buffer.begin() + static_cast<std::ptrdiff_t>(header + payload), buffer.begin() + n);
      Send(udpm_test::Small(seqno, status, forged));
      ++relabelled_;
      // Robot 0's next 64 sequence numbers, from its own address and port.
      for (std::uint32_t k = 1; k <= 64; ++k) Spoof(from, udpm_test::Small(seqno + k, status, {0xde, 0xad}));
    }
  }

  int port_;
  int listen_ = -1, raw_ = -1, own_ = -1;
  sockaddr_in group_{};
  bool ok_ = false;
  std::atomic<bool> stop_{false}, paused_{false};
  std::atomic<std::uint64_t> relabelled_{0}, spoofed_{0};
  std::thread thread_;
};

// One forger on the group (class Forger) and 240 MB sent to the two agents that wait for their
// third: the team completes as without the forger - every robot's 100 queries answered, each
// robot storing exactly what its table routes to it (the forged heartbeat once took robot 1's
// identity and robot 0 completed 22 of 150 queries; the spoofed datagrams made robot 1 store 218
// frames of 248) - counts what it dropped as unauthenticated, and stays within its documented
// bound on memory (docs/security.md: nothing unauthenticated is held; at most --hold-bytes are,
// and unfinished messages hold at most 2 x the largest message + 16 MiB; the 240 MB once grew
// an agent by 238 MiB). The flood goes out 60 kB at a time, each once the agents' kernel queues
// are empty (an event, not a time).
TEST_F(LcmTeamTest, AForgerOnTheGroupChangesNothingAndIsCounted) {
  constexpr int kRobots = 3, kPort = 7709;
  Forger forger(kPort);
  if (!forger.ok()) GTEST_SKIP() << "no raw socket for the forger";
  std::vector<pid_t> pids(kRobots, -1);
  const auto argv = [&](int r) {
    std::vector<std::string> a = AgentArgv(r, kRobots, "decentralized", kPort, 5.0, dir_ / ("r" + std::to_string(r) + ".log"), 60.0);
    a.insert(a.end(), {"--barrier-timeout", "1000", "--set", "strategies=[decentralized]"});
    return a;
  };
  for (int r : {0, 2}) pids[static_cast<std::size_t>(r)] = Spawn(argv(r), dir_ / ("r" + std::to_string(r) + ".out"));
  // A failed assertion leaves no agent behind (they would wait 1000 s for their team).
  struct KillLeftovers {
    std::vector<pid_t>& pids;
    ~KillLeftovers() {
      for (const pid_t pid : pids) {
        if (pid > 0 && waitpid(pid, nullptr, WNOHANG) == 0) {
          kill(pid, SIGKILL);
          waitpid(pid, nullptr, 0);
        }
      }
    }
  } leftovers{pids};
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(240);
  const auto drained = [&] {
    for (const int r : {0, 2}) {
      const std::vector<SocketQueue> q = UdpQueuesOf(pids[static_cast<std::size_t>(r)], kPort);
      if (q.size() != 1 || q[0].queued != 0) return false;
    }
    return true;
  };
  const auto wait_until = [&](const std::function<bool()>& done) {
    while (!done() && std::chrono::steady_clock::now() < give_up) {
      timespec ts{0, 1000000};
      ppoll(nullptr, 0, &ts, nullptr);
    }
    return std::chrono::steady_clock::now() < give_up;
  };
  // Robot 0 announces itself (it has loaded its inputs) and the forger answers it; then the
  // forger pauses until the flood is over, and both waiting agents read everything so far.
  ASSERT_TRUE(wait_until([&] { return forger.relabelled() > 0; })) << "see " << dir_;
  forger.Pause(true);
  ASSERT_TRUE(wait_until(drained)) << "see " << dir_;
  std::vector<std::int64_t> before;
  for (const int r : {0, 2}) before.push_back(PeakMemory(pids[static_cast<std::size_t>(r)]));
  // 240 MB on the channels the waiting agents hold for later: 4000 datagrams of 60 000 bytes.
  const std::vector<std::uint8_t> filler(60000 - 32, 0x5a);
  for (int sent = 0; sent < 4000;) {
    for (int k = 0; k < 20; ++k, ++sent) {
      forger.Send(udpm_test::Small(static_cast<std::uint32_t>(sent), sent % 2 == 0 ? "DVPR_QUERY_0" : "DVPR_QUERY_2", filler));
    }
    ASSERT_TRUE(wait_until(drained)) << "after " << sent << " datagrams; see " << dir_;
  }
  for (std::size_t i = 0; i < 2; ++i) {
    const pid_t pid = pids[i == 0 ? 0 : 2];
    const std::int64_t grew = PeakMemory(pid) - before[i];
    // --hold-bytes (16 MiB) and the unfinished messages' bound (2 x (1000 + 1 MiB + 34) + 16 MiB).
    const std::int64_t bound = (16 << 20) + 2 * (1000 + (1 << 20) + 34) + (16 << 20);
    EXPECT_LT(grew, bound) << "robot " << (i == 0 ? 0 : 2) << " grew by " << grew << " bytes";
    std::cout << "robot " << (i == 0 ? 0 : 2) << ": peak memory grew by " << grew / 1024 << " KiB with 240 MB sent\n";
  }
  forger.Pause(false);
  pids[1] = Spawn(argv(1), dir_ / "r1.out");
  std::vector<AgentLog> logs;
  for (int r = 0; r < kRobots; ++r) {
    const int status = WaitFor(pids[static_cast<std::size_t>(r)], std::chrono::seconds(300));
    pids[static_cast<std::size_t>(r)] = -1;  // reaped
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "robot " << r << "; see " << dir_;
    logs.push_back(ReadAgentLog(dir_ / ("r" + std::to_string(r) + ".log")));
  }
  EXPECT_GT(forger.spoofed(), 64u);
  std::vector<ConfigOverride> overrides;
  for (const auto& s : SmallConfigSets()) overrides.push_back(ParseOverride(s));
  const std::vector<std::int64_t> stored = StoredByPlacement(LoadConfig(ConfigPath(), overrides), kRobots);
  for (int r = 0; r < kRobots; ++r) {
    const AgentLog& log = logs[static_cast<std::size_t>(r)];
    EXPECT_EQ(log.queries.size(), 100u) << "robot " << r;
    const auto complete = std::count_if(log.queries.begin(), log.queries.end(), [](const QueryRecord& q) { return q.Complete(); });
    if (log.kernel_dropped == 0) {
      // Nothing lost: exactly the clean team's results.
      EXPECT_EQ(complete, 100) << "robot " << r;
      EXPECT_EQ(log.load.stored, stored[static_cast<std::size_t>(r)]) << "robot " << r;
    } else {
      EXPECT_LE(log.load.stored, stored[static_cast<std::size_t>(r)]) << "robot " << r;
    }
    if (log.kernel_dropped == 0) {
      EXPECT_EQ(log.end_reason, "all_done") << "robot " << r;
    }
    EXPECT_GT(log.unauthenticated, 0u) << "robot " << r;
    EXPECT_EQ(log.held_dropped, 0u) << "robot " << r;
    EXPECT_LE(log.held_bytes_peak, std::uint64_t{16} << 20) << "robot " << r;
    std::cout << "robot " << r << ": " << complete << " of 100 queries complete, stored " << log.load.stored << " (table: "
              << stored[static_cast<std::size_t>(r)] << "), " << log.unauthenticated << " unauthenticated, "
              << log.foreign << " foreign, " << log.kernel_dropped << " dropped by a full buffer\n";
  }
  // The waiting agents counted at least the flood they read (or the kernel dropped and counted it).
  for (const int r : {0, 2}) {
    const AgentLog& log = logs[static_cast<std::size_t>(r)];
    EXPECT_GE(log.unauthenticated + log.kernel_dropped, 2000u) << "robot " << r;
  }
}

}  // namespace
}  // namespace dvpr
