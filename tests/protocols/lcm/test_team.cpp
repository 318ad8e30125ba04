// Real agent processes over loopback multicast, each test in its own network
// namespace: a launched team matches the simulation on the ideal network; a
// team survives one of its agents being SIGKILLed; garbage and foreign
// messages on every channel are counted and ignored.
#include <algorithm>
#include <cmath>
#include <functional>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

#include "agents/bow_vector.h"
#include "agents/bow_words.h"
#include "agents/centroid_table.h"
#include "agents/failure_detector.h"
#include "agents/team_sync.h"
#include "experiments/protocols/lcm/agent_log.h"
#include "experiments/config/config.h"
#include "experiments/protocols/inputs.h"
#include "experiments/protocols/lcm/lcm_launch.h"
#include "experiments/protocols/sim/sim_protocol.h"
#include "experiments/data/split.h"
#include "experiments/protocols/paper/static_protocol.h"
#include "experiments/strategies/run_centroids.h"
#include "lcm_test_support.h"

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

using Row = std::map<std::string, std::string>;

std::vector<Row> ReadCsv(const fs::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream hs(line);
  for (std::string c; std::getline(hs, c, ',');) header.push_back(c);
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    Row row;
    std::stringstream ls(line);
    std::size_t i = 0;
    for (std::string c; i < header.size(); ++i) {
      if (!std::getline(ls, c, ',')) c.clear();
      row[header[i]] = c;
    }
    rows.push_back(row);
  }
  return rows;
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
  // The paper's table of run 0: k-means as every protocol runs it (experiments/strategies/).
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
    for (const auto& [frame, r] : lcm_rows[strategy]) {
      EXPECT_EQ(r.at("protocol"), "lcm");
      EXPECT_FALSE(r.at("latency_ns").empty()) << "frame " << frame << ": a reply is missing";
      Logged& t = times[static_cast<std::size_t>(frame)];
      t.sent = std::stoll(r.at("sent_ns"));
      // latency_ns is wall time; the agents' clock runs kSpeedup times faster.
      if (!r.at("latency_ns").empty()) t.done = t.sent + std::llround(std::stod(r.at("latency_ns")) * kSpeedup);
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
    // window, stored seconds before); a test that checked few would mean little.
    EXPECT_GT(checked, 200);
    EXPECT_GT(compared, 150);
  }
  // The runs.csv rows are there, with the broadcast reference.
  const std::vector<Row> runs = ReadCsv(dir_ / "lcm" / "runs.csv");
  ASSERT_EQ(runs.size(), 2u);
  for (const Row& r : runs) {
    EXPECT_EQ(r.at("protocol"), "lcm");
    // The first 300 frames hold no revisit, so AUC is 0; the reference is still filled.
    EXPECT_FALSE(r.at("auc_reference").empty());
    EXPECT_EQ(r.at("dropped_messages"), "0");
  }
}

// The bag-of-words counterpart of References: query f's parts (words w mod n) go to their
// owners, each scores its part against the parts of the frames it stored (the sum over shared
// words of min weights, agents/bow_vector.h) and returns its best; the querying robot votes
// (agents/bow_words.h). A responder's answer is certain when its best among the frames surely
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
  for (const auto& [frame, r] : lcm_rows) {
    EXPECT_EQ(r.at("strategy"), "bow_decentralized");
    EXPECT_FALSE(r.at("latency_ns").empty()) << "frame " << frame << ": a reply is missing";
    Logged& t = times[static_cast<std::size_t>(frame)];
    t.sent = std::stoll(r.at("sent_ns"));
    if (!r.at("latency_ns").empty()) t.done = t.sent + std::llround(std::stod(r.at("latency_ns")) * kSpeedup);
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
  EXPECT_GT(checked, 150);
  EXPECT_GT(compared, 100);
  const std::vector<Row> runs = ReadCsv(dir_ / "lcm" / "runs.csv");
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].at("protocol"), "lcm");
  EXPECT_EQ(runs[0].at("dropped_messages"), "0");
}

// Starts a broadcast team of 4 (every query is searched by every robot, so
// the victim matters whatever the routing's balance), SIGKILLs robot 2 once
// it has taken some frames; the others must still finish (at their deadline:
// robot 2 never announces done), and their queries it never answered are
// counted as lost.
TEST_F(LcmTeamTest, KilledAgentDoesNotHangTheOthers) {
  constexpr int kRobots = 4, kVictim = 2, kPort = 7702;
  const std::string strategy = "broadcast";
  std::vector<pid_t> pids;
  for (int r = 0; r < kRobots; ++r) {
    // Grace 10 s: the survivors wait for robot 2 until then. A survivor whose process was starved
    // on a loaded machine has answered its backlog long before, so no message between survivors
    // is still under way when they leave (with 2 s, one was now and then, and counted dropped).
    pids.push_back(Spawn(AgentArgv(r, kRobots, strategy, kPort, 5.0, dir_ / ("r" + std::to_string(r) + ".log"), 10.0),
                         dir_ / ("r" + std::to_string(r) + ".out")));
  }
  // Watch the heartbeats until the victim is well into its frames.
  LcmTransport watcher(Url(kPort));
  int victim_frames = 0;
  Subscription sub = watcher.Subscribe<agent_status_t>("DVPR_STATUS", [&](const agent_status_t& s) {
    if (s.robot == kVictim) victim_frames = std::max(victim_frames, s.frames_taken);
  });
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(240);
  while (victim_frames < 20 && std::chrono::steady_clock::now() < give_up) {
    watcher.RunUntilWall(std::chrono::steady_clock::now() + std::chrono::milliseconds(20));
  }
  ASSERT_GE(victim_frames, 20) << "the team never started; see " << dir_;
  ASSERT_EQ(kill(pids[kVictim], SIGKILL), 0);
  EXPECT_EQ(WaitFor(pids[kVictim], std::chrono::seconds(10)), SIGKILL);

  std::vector<std::optional<AgentLog>> logs(kRobots);
  for (int r = 0; r < kRobots; ++r) {
    if (r == kVictim) continue;
    // Deadline: the team's last frame (75 frames at 50 fps: 1.5 s) + 10 s grace, after start-up.
    const int status = WaitFor(pids[static_cast<std::size_t>(r)], std::chrono::seconds(120), &watcher);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "robot " << r << " hung or failed; see " << dir_;
    logs[static_cast<std::size_t>(r)] = ReadAgentLog(dir_ / ("r" + std::to_string(r) + ".log"));
    EXPECT_EQ(logs[static_cast<std::size_t>(r)]->end_reason, "deadline");
    EXPECT_EQ(logs[static_cast<std::size_t>(r)]->queries.size(), 75u);  // every frame taken
  }
  const ExperimentConfig config = Config();
  const SharedInputs inputs = LoadSharedInputs(config, ConfigPath());
  const GatheredRun g = GatherTeam(config, inputs, strategy, kRobots, 0, logs, kNotApplicable);
  EXPECT_EQ(g.missing_robots, std::vector<int>{kVictim});
  EXPECT_EQ(g.queries, 3 * 75);
  // Every survivor query after the kill waited for robot 2 in vain.
  EXPECT_GE(g.incomplete, 3 * (75 - 20 - 5)) << "queries the dead robot never answered must be counted as lost";
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
// agent time at speedup 2). `dropout:` makes the victim's process SIGKILL itself at 1 s of agent
// time (after its frame 10); failover declares a robot lost after 2 s of agent time (1 s of
// wall time) without a heartbeat. No timing is assumed beyond that: each survivor's own log says
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
                                  "--speedup", "2", "--lcm", Url(7704), "--out", (dir_ / "lcm").string(),
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

  std::vector<int> status(kRobots, -2);
  int rounds = 0;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(240);
  auto running = [&] { return std::count(status.begin(), status.end(), -2) > 0; };
  while (running() && std::chrono::steady_clock::now() < give_up) {
    for (const auto& c : channels) {
      for (const auto& p : payloads) noise.PublishRaw(c, p);
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
  for (int r = 0; r < kRobots; ++r) {
    if (status[static_cast<std::size_t>(r)] == -2) status[static_cast<std::size_t>(r)] = WaitFor(pids[static_cast<std::size_t>(r)], std::chrono::seconds(1));
    ASSERT_TRUE(WIFEXITED(status[static_cast<std::size_t>(r)]) && WEXITSTATUS(status[static_cast<std::size_t>(r)]) == 0)
        << "robot " << r << "; see " << dir_;
    const AgentLog log = ReadAgentLog(dir_ / ("r" + std::to_string(r) + ".log"));
    EXPECT_EQ(log.end_reason, "all_done") << "robot " << r;
    EXPECT_EQ(log.queries.size(), 100u);
    for (const QueryRecord& q : log.queries) EXPECT_TRUE(q.Complete()) << "robot " << r << " frame " << q.frame.value;
    EXPECT_GT(log.malformed, 0u) << "robot " << r;
    EXPECT_GT(log.foreign, 0u) << "robot " << r;
    std::cout << "robot " << r << ": " << log.malformed << " malformed, " << log.foreign << " foreign, over " << rounds
              << " rounds of noise\n";
  }
}

}  // namespace
}  // namespace dvpr
