// `dvpr launch` when agents cannot run: what every agent would refuse (an LCM URL that is not
// udpm or does not open, more robots than frames) the launcher refuses before it starts any;
// `dvpr agent` refuses a missing log folder before it starts; otherwise each failed
// agent's first error line is printed, a team that never ran gets no rows, and launch exits 1.
// When no team ran, no result folder appears (not even a half-written one); when one strategy's
// agents all fail, only the teams that ran have rows.
#include <algorithm>
#include <fstream>
#include <utility>

#include "lcm_test_support.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

using namespace lcm_test;
using testing_support::RunProgram;
using testing_support::Slurp;

std::vector<std::string> LaunchArgv(const std::string& lcm_url, const fs::path& out) {
  std::vector<std::string> a{Dvpr(),    "launch",  "--config", ConfigPath(), "--robots", "2", "--speedup", "10",
                             "--lcm",   lcm_url,   "--out",    out.string(), "--timeout", "120", "--grace", "5"};
  for (const auto& s : SmallConfigSets()) {
    a.push_back("--set");
    a.push_back(s);
  }
  return a;
}

// Everything in `dir` whose name starts with `prefix` (temporary result folders are ".dvpr-run-...").
std::vector<std::string> NamesStartingWith(const fs::path& dir, const std::string& prefix) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) == 0) names.push_back(name);
  }
  return names;
}

// `dvpr launch` of 100 frames with `strategies` on its own port, where every recluster_c2_p50
// agent refuses to run: its exit status and what it printed. Checks the refusal of both robots
// and that the team is reported as not run.
std::pair<int, std::string> LaunchWithRefusedReclustering(int port, const std::string& strategies, const fs::path& dir) {
  std::vector<std::string> argv = LaunchArgv(Url(port), dir / "out");
  for (const std::string& s : {std::string("dataset.frames=100"), "strategies=" + strategies}) {
    argv.push_back("--set");
    argv.push_back(s);
  }
  const int status = WaitFor(Spawn(argv, dir / "launch.out"), std::chrono::seconds(240));
  std::string printed = Slurp(dir / "launch.out");
  for (const std::string robot : {"0", "1"}) {
    const std::string cause = "launch: recluster_c2_p50 robot " + robot +
                              ": exit 1: dvpr: error: --strategy: 'recluster_c2_p50' re-clusters during the run";
    EXPECT_NE(printed.find(cause), std::string::npos) << "missing: " << cause << "\nin:\n" << printed;
  }
  EXPECT_NE(printed.find("launch: recluster_c2_p50: no agent ran, no rows written\n"), std::string::npos) << printed;
  return {status, std::move(printed)};
}

// One line of output, exactly (LCM's own texts run over several: issue 31).
void ExpectOneLine(const std::string& printed) {
  EXPECT_EQ(std::count(printed.begin(), printed.end(), '\n'), 1) << printed;
}

// Only udpm:// makes a team: another provider is refused as a malformed flag (exit 2) by
// launch and by agent, before anything runs or is opened. file://X?mode=w would have been
// LCM's log file X, opened for writing (and emptied) by liblcm: X stays as it was.
TEST(LaunchFailureTest, ProvidersOtherThanUdpmAreRefusedBeforeAnythingIsOpened) {
  const fs::path dir = TestDir();
  const fs::path precious = dir / "precious.log";
  std::ofstream(precious) << "an LCM log someone keeps\n";
  for (const std::string& url : {"file://" + precious.string() + "?mode=w", std::string("memq://"),
                                std::string("nosuchprovider://nowhere"), std::string("udpm://10.1.2.3:7667")}) {
    SCOPED_TRACE(url);
    const int launch = WaitFor(Spawn(LaunchArgv(url, dir / "out"), dir / "launch.out"), std::chrono::seconds(240));
    const std::string printed = Slurp(dir / "launch.out");
    ASSERT_TRUE(WIFEXITED(launch)) << printed;
    EXPECT_EQ(WEXITSTATUS(launch), 2) << printed;
    EXPECT_EQ(printed.rfind("dvpr launch: --lcm: LCM URL '" + url + "': ", 0), 0u) << printed;
    ExpectOneLine(printed);
    EXPECT_FALSE(fs::exists(dir / "out"));
    std::vector<std::string> agent = AgentArgv(0, 2, "broadcast", 7716, 1.0, dir / "agent.log");
    agent[static_cast<std::size_t>(std::find(agent.begin(), agent.end(), "--lcm") - agent.begin() + 1)] = url;
    const int status = WaitFor(Spawn(agent, dir / "agent.out"), std::chrono::seconds(240));
    const std::string said = Slurp(dir / "agent.out");
    ASSERT_TRUE(WIFEXITED(status)) << said;
    EXPECT_EQ(WEXITSTATUS(status), 2) << said;
    EXPECT_EQ(said.rfind("dvpr agent: --lcm: LCM URL '" + url + "': ", 0), 0u) << said;
    ExpectOneLine(said);
    EXPECT_FALSE(fs::exists(dir / "agent.log"));
  }
  EXPECT_EQ(Slurp(precious), "an LCM log someone keeps\n");
}

// A group that cannot be joined (here: a network namespace with loopback but no multicast
// route): the launcher finds it before it starts an agent (each would fail alike) and says so
// in one line, not LCM's page of advice. No agent, no folder.
TEST(LaunchFailureTest, AGroupThatCannotBeJoinedIsRefusedInOneLineBeforeAnyAgentStarts) {
  if (unshare(CLONE_NEWNET) != 0 || RunProgram({"ip", "link", "set", "lo", "up"}, "/dev/null") != 0) {
    GTEST_SKIP() << "cannot make a network namespace without a multicast route";
  }
  const fs::path dir = TestDir();
  const int status = WaitFor(Spawn(LaunchArgv(Url(7717), dir / "out"), dir / "launch.out"), std::chrono::seconds(240));
  const std::string printed = Slurp(dir / "launch.out");
  ASSERT_TRUE(WIFEXITED(status)) << printed;
  EXPECT_EQ(WEXITSTATUS(status), 1) << printed;
  EXPECT_EQ(printed.rfind("dvpr: error: LCM group 239.255.76.67:7717: cannot join the group (is there a multicast "
                          "route?", 0), 0u) << printed;
  ExpectOneLine(printed);
  EXPECT_FALSE(fs::exists(dir / "out"));
  EXPECT_TRUE(NamesStartingWith(dir, ".dvpr-run-").empty());
}

// `dvpr agent --out` into a folder that is not there: refused before the agent opens LCM or
// joins a team (it used to find out after the run, losing it).
TEST(LaunchFailureTest, AnAgentWhoseLogFolderIsMissingIsRefusedBeforeItStarts) {
  const fs::path dir = TestDir();
  const fs::path log = dir / "missing" / "robot0.log";
  // An URL that would fail if it were opened: the folder is checked first.
  std::vector<std::string> agent = AgentArgv(0, 2, "broadcast", 7718, 1.0, log);
  const int status = WaitFor(Spawn(agent, dir / "agent.out"), std::chrono::seconds(240));
  const std::string said = Slurp(dir / "agent.out");
  ASSERT_TRUE(WIFEXITED(status)) << said;
  EXPECT_EQ(WEXITSTATUS(status), 1) << said;
  EXPECT_EQ(said, "dvpr: error: --out " + log.string() + ": the folder " + (dir / "missing").string() +
                      " does not exist\n");
  EXPECT_FALSE(fs::exists(dir / "missing"));
}

// More robots than frames: refused by the launcher, before it starts any of them (it used to
// start them all, each of which failed alike: 100000 processes for --robots 100000).
TEST(LaunchFailureTest, AnImpossibleTeamSizeIsRefusedBeforeAnyAgentStarts) {
  const fs::path dir = TestDir();
  std::vector<std::string> argv = LaunchArgv(Url(7715), dir / "out");
  argv[std::find(argv.begin(), argv.end(), "--robots") - argv.begin() + 1] = "100000";
  const int status = WaitFor(Spawn(argv, dir / "launch.out"), std::chrono::seconds(240));
  const std::string printed = Slurp(dir / "launch.out");
  ASSERT_TRUE(WIFEXITED(status)) << printed;
  EXPECT_EQ(WEXITSTATUS(status), 1) << printed;
  EXPECT_NE(printed.find("dvpr: error: --robots: 100000 robots for "), std::string::npos) << printed;
  EXPECT_EQ(printed.find("agents started"), std::string::npos) << printed;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// Every team's agents fail (re-clustering, which `dvpr agent` refuses): each agent's cause is
// printed, then one error line; no result folder appears, not even a half-written one.
TEST(LaunchFailureTest, NoTeamRanPrintsEachCauseWritesNothingAndExits1) {
  const std::string why = IsolateNetwork();
  if (!why.empty()) GTEST_SKIP() << why;
  const fs::path dir = TestDir();
  const auto [status, printed] = LaunchWithRefusedReclustering(7714, "[recluster_c2_p50]", dir);
  ASSERT_TRUE(WIFEXITED(status)) << printed;
  EXPECT_EQ(WEXITSTATUS(status), 1) << printed;
  EXPECT_NE(printed.find("dvpr: error: " + (dir / "out").string() + ": no team ran"), std::string::npos) << printed;
  EXPECT_FALSE(fs::exists(dir / "out"));
  EXPECT_TRUE(NamesStartingWith(dir, ".dvpr-run-").empty());
}

// A strategy the agents refuse (re-clustering, which `dvpr agent` does not implement): all its
// agents fail, while broadcast's team runs. Rows for broadcast only, its agents and the refused
// ones in agents.csv, the causes printed, exit 1.
TEST(LaunchFailureTest, StrategyWhoseAgentsAllFailedHasNoRowsWhileTheOthersDo) {
  const std::string why = IsolateNetwork();
  if (!why.empty()) GTEST_SKIP() << why;
  const fs::path dir = TestDir();
  const auto [status, printed] = LaunchWithRefusedReclustering(7711, "[recluster_c2_p50, broadcast]", dir);
  ASSERT_TRUE(WIFEXITED(status)) << printed;
  EXPECT_EQ(WEXITSTATUS(status), 1) << printed;
  EXPECT_NE(printed.find("launch: broadcast: 100 queries, 0 with a reply missing"), std::string::npos) << printed;
  const std::string runs = Slurp(dir / "out" / "runs.csv");
  EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 2) << runs;  // header + broadcast
  EXPECT_NE(runs.find(",broadcast,"), std::string::npos) << runs;
  EXPECT_EQ(runs.find(",recluster_c2_p50,"), std::string::npos) << runs;  // no row (the header has recluster_* byte columns)
  const std::string agents = Slurp(dir / "out" / "agents.csv");
  // No log: every count after the exit is empty (12 of them, the last three the tags' and the
  // held channels').
  EXPECT_NE(agents.find("recluster_c2_p50,0,exit 1,,,,,,,,,,,,\n"), std::string::npos) << agents;
  EXPECT_NE(agents.find("recluster_c2_p50,1,exit 1,,,,,,,,,,,,\n"), std::string::npos) << agents;
  // Its counts of what the network brought follow (nothing malformed was sent).
  EXPECT_NE(agents.find("broadcast,0,exit 0,broadcast_robot0.log,50,0,0,0,"), std::string::npos) << agents;
}

}  // namespace
}  // namespace dvpr
