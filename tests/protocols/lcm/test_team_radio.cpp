// A launched team on a radio config (experiments/protocols/lcm/emulated_range.h): the real
// processes talk over the real (loopback) network, and each receiving agent drops every message
// whose sender is out of its range at agent time. On radios of 1 mm no robot of the KITTI 00
// split is ever in range of another, so after the start no teammate's message gets through:
// each robot serves and stores only its own frames of its own clusters, a query for another
// robot's cluster gets no reply, and every agent counts what it dropped (agents.csv
// out_of_range). The start barrier is the real network's (before agent time 0 everyone hears
// everyone), so the team starts at all. On radios of 10 000 km nothing is dropped.
#include <sys/wait.h>

#include <chrono>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agents/algorithms/centroid_table.h"
#include "experiments/config/config.h"
#include "experiments/domain/data/split.h"
#include "experiments/domain/strategies/run_centroids.h"
#include "experiments/protocols/inputs.h"
#include "lcm_test_support.h"

namespace dvpr {
namespace {

using namespace lcm_test;
constexpr int kRobots = 4;
constexpr int kFrames = 200;

std::vector<std::string> Sets(const std::string& range) {
  std::vector<std::string> sets = SmallConfigSets();
  for (const std::string& s : std::vector<std::string>{"strategies=[decentralized]",
                                                       "dataset.frames=" + std::to_string(kFrames), "network.model=radio",
                                                       "network.radio={propagation: range, range: " + range + "}"}) {
    sets.push_back(s);
  }
  return sets;
}

// Runs the launch; false (with the reason recorded) when it did not exit 0.
bool Launch(const fs::path& out, int port, const std::string& range) {
  std::vector<std::string> argv{Dvpr(),   "launch", "--config", ConfigPath(), "--robots", std::to_string(kRobots),
                                "--speedup", "5",   "--lcm",    Url(port),    "--out",    out.string(),
                                "--timeout", "240", "--grace",  "1"};
  for (const auto& s : Sets(range)) argv.insert(argv.end(), {"--set", s});
  const int status = WaitFor(Spawn(argv, out.string() + ".out"), std::chrono::seconds(300));
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "see " << out.string() << ".out";
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

class LcmRadioTeamTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string why = IsolateNetwork();
    if (!why.empty()) GTEST_SKIP() << why;
    dir_ = TestDir();
  }
  fs::path dir_;
};

TEST_F(LcmRadioTeamTest, OutOfRangeDatagramsAreDroppedAtTheReceiverAndCounted) {
  ASSERT_TRUE(Launch(dir_ / "mm", 7721, "1mm"));
  // Worked out here from the table of run 0: robot r keeps its own frames of its own clusters;
  // its other frames' queries go to robots it never hears from.
  std::vector<ConfigOverride> overrides;
  for (const auto& s : Sets("1mm")) overrides.push_back(ParseOverride(s));
  const ExperimentConfig config = LoadConfig(ConfigPath(), overrides);
  const SharedInputs inputs = LoadSharedInputs(config, ConfigPath());
  const CentroidTable table =
      CentroidTable::RoundRobin(RunCentroids(inputs.training, config.training.run_centroids, kRobots, 0), kRobots);
  const SequenceSplit split = SplitSequence(kFrames, kRobots);
  std::vector<std::int64_t> own(kRobots, 0);
  std::map<int, bool> answerable;  // by frame: routed to the robot that takes it
  for (int r = 0; r < kRobots; ++r) {
    const FrameRange& range = split.ranges[static_cast<std::size_t>(r)];
    for (int k = 0; k < range.size(); ++k) {
      const int f = range.begin.value + k;
      const bool mine = table.RouteOf(inputs.deployment.descriptors.row(f).data()).value == r;
      own[static_cast<std::size_t>(r)] += mine ? 1 : 0;
      answerable[f] = mine;
    }
  }
  std::vector<std::int64_t> stored;
  for (const Row& r : ReadCsv(dir_ / "mm" / "per_robot.csv")) stored.push_back(std::stoll(r.at("stored")));
  EXPECT_EQ(stored, own);
  int answered = 0, expected_answered = 0;
  for (const Row& q : ReadCsv(dir_ / "mm" / "queries.csv")) {
    const bool got = !q.at("latency_ns").empty();
    EXPECT_EQ(got, answerable.at(std::stoi(q.at("frame")))) << "frame " << q.at("frame");
    answered += got ? 1 : 0;
  }
  for (const auto& [f, mine] : answerable) expected_answered += mine ? 1 : 0;
  EXPECT_EQ(answered, expected_answered);
  EXPECT_LT(answered, kFrames);  // some queries had to cross the team
  // Every robot sent queries and heartbeats to the others after the start, and each dropped
  // what reached it.
  const std::vector<Row> agents = ReadCsv(dir_ / "mm" / "agents.csv");
  ASSERT_EQ(agents.size(), static_cast<std::size_t>(kRobots));
  for (const Row& a : agents) EXPECT_GT(std::stoll(a.at("out_of_range")), 0) << "robot " << a.at("robot");
}

TEST_F(LcmRadioTeamTest, ARangeThatCoversTheTeamDropsNothing) {
  ASSERT_TRUE(Launch(dir_ / "km", 7722, "10000km"));
  for (const Row& a : ReadCsv(dir_ / "km" / "agents.csv")) EXPECT_EQ(a.at("out_of_range"), "0") << "robot " << a.at("robot");
}

}  // namespace
}  // namespace dvpr
