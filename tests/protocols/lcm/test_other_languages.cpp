// The LCM types as LCM users in other languages get them (lcmtypes/CMakeLists.txt): every event
// of a simulated run's event log and of a live team's `lcm-logger` recording decodes with the
// Java types of dvpr_lcmtypes.jar (read by LCM's Java log reader, tests/tools/lcm_types/
// DecodeDvprLog.java) and with the Python types of lcmtypes/python (read by a pure-Python log
// reader, decode_dvpr_log.py), and encodes back to the same bytes; in the live recording every
// utime is within a second of the wall clock at which lcm-logger received the message.
#include <iostream>

#include "lcm_test_support.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

using namespace lcm_test;
using testing_support::Slurp;

// Sets for a quick team: 2 robots of 60 frames each.
std::vector<std::string> WithSets(std::vector<std::string> argv) {
  std::vector<std::string> sets = SmallConfigSets();
  sets.push_back("dataset.frames=120");
  for (const auto& s : sets) {
    argv.push_back("--set");
    argv.push_back(s);
  }
  return argv;
}

// Runs `argv` to completion; its stdout and stderr go to `out`. Returns its exit status (-1: killed).
int RunTool(const std::vector<std::string>& argv, const fs::path& out) {
  const int status = WaitFor(Spawn(argv, out), std::chrono::seconds(240));
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Decodes `log` with both languages' types; returns what the decoders printed.
std::string DecodeBoth(const fs::path& log, bool live, const fs::path& dir) {
  std::vector<std::string> java{"/usr/bin/java",
                                "-cp",
                                std::string("/usr/share/java/lcm.jar:") + DVPR_LCMTYPES_JAR,
                                std::string(DVPR_SOURCE_DIR) + "/tests/tools/lcm_types/DecodeDvprLog.java",
                                DVPR_LCMTYPES_JAR,
                                log.string()};
  std::vector<std::string> python{"/usr/bin/python3",
                                  std::string(DVPR_SOURCE_DIR) + "/tests/tools/lcm_types/decode_dvpr_log.py",
                                  std::string(DVPR_BINARY_DIR) + "/lcmtypes/python", log.string()};
  if (live) {
    java.push_back("--live");
    python.push_back("--live");
  }
  const fs::path java_out = dir / (log.stem().string() + ".java.out");
  const fs::path python_out = dir / (log.stem().string() + ".python.out");
  EXPECT_EQ(RunTool(java, java_out), 0) << Slurp(java_out);
  EXPECT_EQ(RunTool(python, python_out), 0) << Slurp(python_out);
  return Slurp(java_out) + Slurp(python_out);
}

TEST(OtherLanguagesTest, SimulatedAndLiveLogsDecodeWithTheJavaAndPythonTypes) {
  const std::string why = IsolateNetwork();
  if (!why.empty()) GTEST_SKIP() << why;
  if (std::string(DVPR_LCMTYPES_JAR).empty()) GTEST_SKIP() << "no Java types: javac or lcm.jar (liblcm-java) missing";
  const fs::path dir = TestDir();

  // A simulated run's event log (broadcast: every message type of a stateless team).
  const std::vector<std::string> sim =
      WithSets({Dvpr(), "run", ConfigPath(), "--quiet", "--out", (dir / "sim").string(), "--set", "protocols=[sim]",
                "--set", "robots=[2]", "--set", "runs=1", "--set", "strategies=[broadcast]", "--set",
                "outputs.lcm_log=true"});
  ASSERT_EQ(RunTool(sim, dir / "sim.out"), 0) << Slurp(dir / "sim.out");
  std::vector<fs::path> sim_logs;
  for (const auto& e : fs::recursive_directory_iterator(dir / "sim")) {
    if (e.path().extension() == ".lcmlog") sim_logs.push_back(e.path());
  }
  ASSERT_FALSE(sim_logs.empty());  // one per network variant of the config

  // A live team recorded by lcm-logger, as an LCM user would (--lcm-url=: `-l` is rejected).
  const std::string url = Url(7721);
  const pid_t logger = Spawn({"/usr/bin/lcm-logger", "--lcm-url=" + url, "--quiet", (dir / "live.lcmlog").string()},
                             dir / "logger.out");
  const std::vector<std::string> launch =
      WithSets({Dvpr(), "launch", "--config", ConfigPath(), "--robots", "2", "--speedup", "5", "--lcm", url, "--out",
                (dir / "lcm").string(), "--set", "strategies=[broadcast]", "--grace", "30"});
  const int launched = RunTool(launch, dir / "launch.out");
  kill(logger, SIGINT);  // lcm-logger closes its file on SIGINT
  const int logged = WaitFor(logger, std::chrono::seconds(30));
  ASSERT_EQ(launched, 0) << Slurp(dir / "launch.out");
  ASSERT_TRUE(WIFEXITED(logged)) << Slurp(dir / "logger.out");

  std::vector<std::pair<fs::path, bool>> logs{{dir / "live.lcmlog", true}};
  for (const fs::path& log : sim_logs) logs.emplace_back(log, false);
  for (const auto& [log, live] : logs) {
    SCOPED_TRACE(log.string());
    const std::string printed = DecodeBoth(log, live, dir);
    std::cout << printed;
    for (const std::string type : {"query_t", "match_t", "verify_request_t", "verify_result_t"}) {
      // Twice: once in the Java decoder's counts ("query_t=120"), once in Python's ('query_t': 120).
      EXPECT_NE(printed.find(type + "="), std::string::npos) << printed;
      EXPECT_NE(printed.find("'" + type + "': "), std::string::npos) << printed;
    }
    if (live) {
      EXPECT_NE(printed.find("agent_status_t="), std::string::npos) << printed;  // heartbeats too
    }
  }
}

}  // namespace
}  // namespace dvpr
