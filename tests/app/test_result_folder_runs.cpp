// `dvpr run` into an existing result folder (RunExperiment with a stand-in protocol whose runs
// fail or are interrupted on purpose, halfway through the sweep): the earlier folder stays
// byte-identical, no temporary folder is left, and a finished run replaces the folder as a
// whole (a run with queries off leaves no queries.csv of an earlier run).
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/app/experiment.h"
#include "experiments/config/config.h"
#include "experiments/results/result_writers.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

using testing_support::Names;
using testing_support::Slurp;
using testing_support::SnapshotFolder;

using Strings = std::vector<std::string>;

// Names the folder SigtermChildProcess runs in (set for the child process only).
constexpr char kChildRootVariable[] = "DVPR_TEST_SIGTERM_CHILD_ROOT";

enum class Fault { kNone, kThrowInSecondRun, kSigtermInSecondRun };

// A protocol "paper" that writes one row per run with auc = `auc`, one query row, and fails
// (or signals itself) in the sweep's second run, after the first run's rows were written.
ProtocolRegistry StandIn(double auc, Fault fault, std::atomic<bool>* started_writing) {
  ProtocolRegistry registry;
  registry.Add("paper", [=](const SharedInputs& inputs) -> RunFunction {
    const fs::path dir = inputs.out_dir;
    return [=](const RunSpec& spec) {
      if (spec.index == 1 && fault != Fault::kNone) {
        if (started_writing) *started_writing = fs::exists(dir / "config.yaml");
        if (fault == Fault::kThrowInSecondRun) throw std::runtime_error("stand-in failure");
        ::kill(::getpid(), SIGTERM);
        for (;;) ::pause();  // the cleanup thread ends the process
      }
      RunOutput out;
      RunResult r;
      r.key = spec.Key("decentralized");
      r.auc = auc;
      out.runs.push_back(r);
      QueryRow q;
      q.key = r.key;
      out.queries.push_back(q);
      return out;
    };
  });
  return registry;
}

class ResultFolderRunTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = dvpr::testing_support::FreshTestDir("result_folder_runs");
  }
  // 2 robot counts x 1 run of a small synthetic dataset; only the stand-in protocol runs.
  static ExperimentConfig Config(bool queries) {
    return ParseConfig(
        "name: folder\nseed: 3\n"
        "dataset: {source: synthetic, poses: data/kitti/00_poses.txt, dim: 8, frames: 60}\n"
        "training: {source: synthetic_diverse, synthetic: {samples: 50}}\n"
        "robots: [2, 3]\nruns: 1\nprotocols: [paper]\nstrategies: [decentralized]\n"
        "evaluation: {suppression_frames: 5}\n"
        "outputs: {figures: false, queries: " + std::string(queries ? "true" : "false") + "}\n",
        DVPR_SOURCE_DIR);
  }
  void Run(bool queries, double auc, Fault fault = Fault::kNone,
           std::atomic<bool>* started_writing = nullptr) {
    std::ostringstream summary;
    RunExperiment(Config(queries), "folder.yaml", root_ / "out",
                  StandIn(auc, fault, started_writing), {.threads = 1, .progress = false}, summary);
  }
  fs::path root_;
};

TEST_F(ResultFolderRunTest, ALaterRunReplacesTheFolderAsAWhole) {
  Run(true, 0.25);
  EXPECT_EQ(Names(root_ / "out"), (Strings{"config.yaml", "dvpr_manifest.txt", "links.csv", "per_robot.csv",
                                           "queries.csv", "runs.csv", "summary.json"}));
  Run(false, 0.75);  // queries off: the earlier queries.csv must not stay beside the new rows
  EXPECT_EQ(Names(root_), Strings{"out"});
  EXPECT_EQ(Names(root_ / "out"),
            (Strings{"config.yaml", "dvpr_manifest.txt", "links.csv", "per_robot.csv", "runs.csv", "summary.json"}));
  const std::vector<RunResult> rows = ReadRunsCsv(root_ / "out" / "runs.csv");
  ASSERT_EQ(rows.size(), 2u);  // n = 2 and 3, one run each
  for (const RunResult& r : rows) EXPECT_EQ(r.auc, 0.75);  // the later run's rows only
  EXPECT_NE(Slurp(root_ / "out" / "config.yaml").find("queries: false"), std::string::npos);
}

TEST_F(ResultFolderRunTest, AFailureHalfwayLeavesTheEarlierFolderByteIdentical) {
  Run(true, 0.25);
  const auto before = SnapshotFolder(root_ / "out");
  std::atomic<bool> started_writing = false;
  try {
    Run(false, 0.75, Fault::kThrowInSecondRun, &started_writing);
    FAIL() << "the stand-in failure did not propagate";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("stand-in failure"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(started_writing) << "the failure came before the run wrote anything";
  EXPECT_EQ(SnapshotFolder(root_ / "out"), before);
  EXPECT_EQ(Names(root_), Strings{"out"});
}

TEST_F(ResultFolderRunTest, AFailedFirstRunLeavesNoFolder) {
  try {
    Run(true, 0.25, Fault::kThrowInSecondRun);
    FAIL() << "the stand-in failure did not propagate";
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(Names(root_), Strings{});
}

// Refused before the sweep: the protocol is never even built, and the folder stays as it was.
TEST_F(ResultFolderRunTest, AFolderDvprDidNotWriteIsRefusedBeforeTheSweepAndLeftAsItWas) {
  for (const bool earlier_run : {false, true}) {
    SCOPED_TRACE(earlier_run ? "a dvpr result folder with a user's file" : "a folder of the user's");
    fs::remove_all(root_);
    fs::create_directories(root_ / "out");
    if (earlier_run) Run(true, 0.25);
    std::ofstream(root_ / "out" / "notes.txt") << "my notes\n";
    const auto before = SnapshotFolder(root_);
    bool swept = false;
    ProtocolRegistry registry;
    registry.Add("paper", [&swept](const SharedInputs&) -> RunFunction {
      swept = true;
      return [](const RunSpec&) { return RunOutput{}; };
    });
    try {
      std::ostringstream summary;
      RunExperiment(Config(true), "folder.yaml", root_ / "out", registry, {.threads = 1, .progress = false}, summary);
      FAIL() << "a folder with other files was replaced";
    } catch (const std::runtime_error& e) {
      const std::string why = earlier_run ? "(not in its dvpr_manifest.txt)" : "(it has no dvpr_manifest.txt)";
      EXPECT_EQ(std::string(e.what()).rfind((root_ / "out").string() + ": holds notes.txt, which dvpr did not "
                                            "write " + why, 0), 0u) << e.what();
    }
    EXPECT_FALSE(swept);
    EXPECT_EQ(SnapshotFolder(root_), before);
  }
}

// SIGTERM in the middle of the sweep, in a child process that signals itself (no timing). The
// child is this test binary started again for SigtermChildProcess alone, not a fork: this process
// has threads by then (the first run started the cleanup thread), and a forked copy can inherit a
// lock one of them held - once in three CI runs the child hung in ASan's allocator.
TEST_F(ResultFolderRunTest, SigtermHalfwayLeavesTheEarlierFolderByteIdentical) {
  Run(true, 0.25);
  const auto before = SnapshotFolder(root_ / "out");
  std::string filter = "--gtest_filter=ResultFolderRunTest.SigtermChildProcess";
  std::string exe = "/proc/self/exe";
  char* argv[] = {exe.data(), filter.data(), nullptr};
  std::vector<std::string> env_strings;
  for (char** e = environ; *e != nullptr; ++e) env_strings.emplace_back(*e);
  env_strings.push_back(std::string(kChildRootVariable) + "=" + root_.string());
  std::vector<char*> envp;
  for (std::string& e : env_strings) envp.push_back(e.data());
  envp.push_back(nullptr);
  pid_t child = 0;
  ASSERT_EQ(::posix_spawn(&child, exe.c_str(), nullptr, nullptr, argv, envp.data()), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_EQ(SnapshotFolder(root_ / "out"), before);
  EXPECT_EQ(Names(root_), Strings{"out"});
}

// The interrupted run of the test above, in its process; skipped when not started by it.
TEST_F(ResultFolderRunTest, SigtermChildProcess) {
  const char* root = std::getenv(kChildRootVariable);
  if (root == nullptr) GTEST_SKIP() << "started by SigtermHalfwayLeavesTheEarlierFolderByteIdentical only";
  root_ = root;
  try {
    Run(false, 0.75, Fault::kSigtermInSecondRun);
  } catch (...) {
  }
  _exit(3);  // not reached when the signal ends the process as it should
}

}  // namespace
}  // namespace dvpr
