// Result folders as transactions (experiments/results/result_folder.h): nothing appears at the
// target before Commit(), an earlier result folder is replaced as a whole, an error or a
// SIGTERM leaves it byte-identical, nothing that dvpr did not write is ever replaced, and no
// temporary folder is left behind.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/results/result_folder.h"
#include "experiments/results/result_writers.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

using testing_support::Names;
using testing_support::Slurp;
using testing_support::SnapshotFolder;

using Strings = std::vector<std::string>;

class ResultFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::path(DVPR_TEST_TMP) / "result_folder" /
            ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  // What an earlier `dvpr run` left: runs.csv with dvpr's header, queries.csv, a centroid file,
  // and a temporary file of an aborted writer from before this change.
  fs::path EarlierResult() const {
    const fs::path out = root_ / "out";
    fs::create_directories(out / "centroids");
    std::ofstream(out / "runs.csv") << kRunsHeader << "\nold row\n";
    std::ofstream(out / "queries.csv") << "old queries\n";
    std::ofstream(out / "config.yaml") << "name: old\n";
    std::ofstream(out / "centroids" / "centroids_n2_r0.npy") << "old centroids";
    std::ofstream(out / ".runs.csv.tmp4242") << "half";
    return out;
  }
  static void Write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }
  fs::path root_;
};

TEST_F(ResultFolderTest, NothingAtTheTargetBeforeCommit) {
  const fs::path out = root_ / "out";
  {
    ResultFolder folder(out);
    EXPECT_EQ(folder.dir(), root_ / (".out.tmp-" + std::to_string(::getpid())));
    EXPECT_FALSE(fs::exists(out));
    Write(folder.dir() / "runs.csv", "new");
    folder.Commit();
  }
  EXPECT_EQ(Names(root_), Strings{"out"});
  EXPECT_EQ(Names(out), Strings{"runs.csv"});
  EXPECT_EQ(Slurp(out / "runs.csv"), "new");
}

TEST_F(ResultFolderTest, ReplacesAnEarlierResultFolderAsAWhole) {
  const fs::path out = EarlierResult();
  {
    ResultFolder folder(out);
    Write(folder.dir() / "runs.csv", "new");  // queries off this time: no queries.csv
    Write(folder.dir() / "config.yaml", "name: new\n");
    folder.Commit();
  }
  EXPECT_EQ(Names(root_), Strings{"out"});  // the earlier folder is gone, no temporary left
  EXPECT_EQ(Names(out), (Strings{"config.yaml", "runs.csv"}));
  EXPECT_EQ(Slurp(out / "config.yaml"), "name: new\n");
}

TEST_F(ResultFolderTest, AnErrorBeforeCommitLeavesTheEarlierFolderByteIdentical) {
  const fs::path out = EarlierResult();
  const auto before = SnapshotFolder(out);
  try {
    ResultFolder folder(out);
    Write(folder.dir() / "config.yaml", "name: new\n");
    fs::create_directories(folder.dir() / "centroids");
    Write(folder.dir() / "centroids" / "centroids_n2_r0.npy", "new centroids");
    throw std::runtime_error("run paper n=3 run 0: failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(SnapshotFolder(out), before);
  EXPECT_EQ(Names(root_), Strings{"out"});
}

TEST_F(ResultFolderTest, RefusesWhatDvprDidNotWrite) {
  const fs::path mine = root_ / "mine";
  fs::create_directories(mine);
  Write(mine / "config.yaml", "my own config\n");  // a config.yaml alone is not a result
  Write(mine / "runs.csv", "a,b,c\n1,2,3\n");      // nor a runs.csv of another tool
  const fs::path file = root_ / "file.txt";
  Write(file, "x");
  const fs::path link = root_ / "link";
  fs::create_directory_symlink(mine, link);
  const auto before = SnapshotFolder(root_);
  for (const auto& [target, expected] : std::vector<std::pair<fs::path, std::string>>{
           {mine, ": exists, is not empty and is not a dvpr result folder"},
           {file, ": exists and is not a folder"},
           {link, ": is a symbolic link"},
           {root_ / "mine" / "..", ": is the current folder or contains it"}}) {
    const fs::path here = fs::current_path();
    if (target.filename() == "..") fs::current_path(mine);
    try {
      ResultFolder folder(target);
      ADD_FAILURE() << target << " accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(target.string() + expected, 0), 0u) << e.what();
    }
    fs::current_path(here);
  }
  EXPECT_EQ(SnapshotFolder(root_), before);
}

TEST_F(ResultFolderTest, AnEmptyFolderAndATrailingSeparatorAreAccepted) {
  fs::create_directories(root_ / "empty");
  {
    ResultFolder folder(root_ / "empty/");
    EXPECT_EQ(folder.dir().filename(), ".empty.tmp-" + std::to_string(::getpid()));
    Write(folder.dir() / "runs.csv", "new");
    folder.Commit();
  }
  EXPECT_EQ(Names(root_ / "empty"), Strings{"runs.csv"});
  EXPECT_EQ(Names(root_), Strings{"empty"});
}

TEST_F(ResultFolderTest, ParentsCreatedForAFailedRunAreRemovedAgain) {
  { ResultFolder folder(root_ / "a" / "b" / "out"); }
  EXPECT_EQ(Names(root_), Strings{});
  {
    ResultFolder folder(root_ / "a" / "b" / "out");
    folder.Commit();
  }
  EXPECT_EQ(Names(root_ / "a" / "b"), Strings{"out"});
}

// The pid of a process that has ended (forked, exited, reaped).
pid_t DeadPid() {
  const pid_t pid = ::fork();
  if (pid == 0) _exit(0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return pid;
}

TEST_F(ResultFolderTest, TemporaryFoldersOfDeadProcessesAreRemovedLiveOnesKept) {
  const fs::path dead = TemporaryFolderFor(root_ / "out", DeadPid());
  const fs::path live = TemporaryFolderFor(root_ / "out", ::getppid());
  const fs::path other = root_ / ".out.tmp-notapid";
  const fs::path unrelated = TemporaryFolderFor(root_ / "other", DeadPid());
  // Killed while its termination cleanup removed the folder (renamed first, then removed).
  const fs::path dead_removing = TemporaryFolderFor(root_ / "out", DeadPid()).string() + ".removing";
  const fs::path live_removing = live.string() + ".removing";
  for (const fs::path& p : {dead, live, other, unrelated, dead_removing, live_removing}) {
    fs::create_directories(p);
    Write(p / "runs.csv", "partial");
  }
  {
    ResultFolder folder(root_ / "out");
    EXPECT_FALSE(fs::exists(dead));
    EXPECT_FALSE(fs::exists(dead_removing));
    folder.Commit();
  }
  std::vector<std::string> want = {"out", live.filename().string(), other.filename().string(),
                                   unrelated.filename().string(), live_removing.filename().string()};
  std::sort(want.begin(), want.end());
  EXPECT_EQ(Names(root_), want);
}

// A SIGTERM while the run writes: the process still ends by SIGTERM, the temporary folder is
// removed, the earlier folder is untouched. In a forked child, which signals itself and then
// keeps writing until the cleanup thread ends it (no timing involved).
TEST_F(ResultFolderTest, SigtermRemovesTheTemporaryFolderAndKeepsTheEarlierOne) {
  const fs::path out = EarlierResult();
  const auto before = SnapshotFolder(out);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    try {
      ResultFolder folder(out);
      Write(folder.dir() / "config.yaml", "name: new\n");
      ::kill(::getpid(), SIGTERM);
      for (int i = 0;; ++i) Write(folder.dir() / ("part" + std::to_string(i % 100)), "x");
    } catch (...) {
    }
    _exit(3);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_EQ(SnapshotFolder(out), before);
  EXPECT_EQ(Names(root_), Strings{"out"});
}

}  // namespace
}  // namespace dvpr
