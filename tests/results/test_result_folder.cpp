// Result folders as transactions (experiments/results/result_folder.h): nothing appears at the
// target before Commit(), an earlier result folder is replaced as a whole, an error or a
// SIGTERM leaves it byte-identical, nothing that dvpr did not write is ever replaced, and no
// temporary folder is left behind. A folder is dvpr's when it holds only what its manifest lists.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/results/manifest.h"
#include "experiments/results/mount_point.h"
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
    root_ = dvpr::testing_support::FreshTestDir("result_folder");
  }
  // What an earlier `dvpr run` left: runs.csv, queries.csv, config.yaml and a centroid file,
  // committed through a ResultFolder (so with its manifest).
  fs::path EarlierResult() const {
    const fs::path out = root_ / "out";
    ResultFolder folder(out);
    const fs::path d = folder.dir();
    fs::create_directories(d / "centroids");
    std::ofstream(d / "runs.csv") << kRunsHeader << "\nold row\n";
    std::ofstream(d / "queries.csv") << "old queries\n";
    std::ofstream(d / "config.yaml") << "name: old\n";
    std::ofstream(d / "centroids" / "centroids_n2_r0.npy") << "old centroids";
    folder.Commit();
    return out;
  }
  // The message of the std::runtime_error ResultFolder(target) throws ("" if none).
  static std::string Refusal(const fs::path& target) {
    try {
      ResultFolder folder(target);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }
  static void Write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }
  fs::path root_;
};

TEST_F(ResultFolderTest, NothingAtTheTargetBeforeCommit) {
  const fs::path out = root_ / "out";
  {
    ResultFolder folder(out);
    EXPECT_EQ(folder.dir().parent_path(), root_);
    EXPECT_EQ(folder.output().path(), folder.dir());
    EXPECT_FALSE(fs::exists(out));
    Write(folder.dir() / "runs.csv", "new");
    folder.Commit();
  }
  EXPECT_EQ(Names(root_), Strings{"out"});
  EXPECT_EQ(Names(out), (Strings{"dvpr_manifest.txt", "runs.csv"}));
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
  EXPECT_EQ(Names(out), (Strings{"config.yaml", "dvpr_manifest.txt", "runs.csv"}));
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

// An error of the run names its files where the user looks for them: the temporary folder's
// path (every occurrence) becomes the target's as the user spelled it, and the line says what
// became of the target (an earlier result folder stays as it was).
TEST_F(ResultFolderTest, AnErrorIsExplainedWithTheTargetsPathsNotTheTemporaryOnes) {
  const fs::path fresh = root_ / "fresh";
  {
    ResultFolder folder(fresh);
    const std::string tmp = folder.dir().string();
    EXPECT_EQ(folder.Explain(tmp + "/runs.csv: write failed (No space left on device)"),
              fresh.string() + "/runs.csv: write failed (No space left on device); nothing was written to " +
                  fresh.string());
  }
  const fs::path out = EarlierResult();
  ResultFolder folder(out.string() + "/");
  const std::string tmp = folder.dir().string();
  EXPECT_EQ(folder.Explain("figure a.png: " + tmp + "/figures/a.gp and " + tmp + "/figures/b.gp"),
            "figure a.png: " + out.string() + "/figures/a.gp and " + out.string() +
                "/figures/b.gp; nothing was written to " + out.string() + " (its earlier results are as they were)");
  EXPECT_EQ(folder.Explain("no path here"),
            "no path here; nothing was written to " + out.string() + " (its earlier results are as they were)");
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
           {mine, ": holds config.yaml, which dvpr did not write (it has no dvpr_manifest.txt)"},
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
    EXPECT_EQ(folder.dir().parent_path(), root_);
    Write(folder.dir() / "runs.csv", "new");
    folder.Commit();
  }
  EXPECT_EQ(Names(root_ / "empty"), (Strings{"dvpr_manifest.txt", "runs.csv"}));
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
  const std::string random = "0123456789abcdef";
  const fs::path dead = TemporaryFolderFor(root_ / "out", DeadPid(), random);
  const fs::path live = TemporaryFolderFor(root_ / "out", ::getppid(), random);
  const fs::path other = dead.parent_path() / (dead.filename().string().substr(0, 19) + "notapid-" + random);
  const fs::path unrelated = TemporaryFolderFor(root_ / "other", DeadPid(), random);
  // Killed while its termination cleanup removed the folder (renamed first, then removed).
  const fs::path dead_removing = TemporaryFolderFor(root_ / "out", DeadPid(), random).string() + ".removing";
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

// A user's file or folder in a result folder: refused before anything is written, naming the
// first foreign entry (sorted by byte value, so NOTES.txt before analysis/), the folder left
// byte-identical and no temporary folder made.
TEST_F(ResultFolderTest, AUsersFileIsRefusedNamingItAndEverythingIsLeftByteIdentical) {
  const fs::path out = EarlierResult();
  fs::create_directories(out / "analysis");
  Write(out / "analysis" / "plot.py", "print(1)\n");
  Write(out / "NOTES.txt", "my notes\n");
  EXPECT_EQ(Refusal(out), out.string() + ": holds NOTES.txt, which dvpr did not write (not in its "
                          "dvpr_manifest.txt); dvpr run replaces only its own result folders, as a "
                          "whole: move it out, remove the folder or choose another --out");
  fs::remove(out / "NOTES.txt");
  EXPECT_EQ(Refusal(out).rfind(out.string() + ": holds analysis/, which", 0), 0u);
  fs::remove_all(out / "analysis");
  Write(out / "centroids" / "mine.npy", "x");
  EXPECT_EQ(Refusal(out).rfind(out.string() + ": holds centroids/mine.npy, which", 0), 0u);
  fs::remove(out / "centroids" / "mine.npy");
  fs::remove(out / "runs.csv");
  fs::create_symlink(root_ / "elsewhere.csv", out / "runs.csv");  // listed, but dvpr makes no links
  EXPECT_EQ(Refusal(out).rfind(out.string() + ": holds runs.csv, which", 0), 0u);
  EXPECT_TRUE(fs::is_symlink(out / "runs.csv"));
  EXPECT_EQ(Names(root_), Strings{"out"});
}

TEST_F(ResultFolderTest, AFolderWithoutAManifestIsRefusedNamingItsFirstEntry) {
  const fs::path out = root_ / "legacy";
  fs::create_directories(out / "centroids");
  Write(out / "runs.csv", std::string(kRunsHeader) + "\n");  // a result folder of an older dvpr
  EXPECT_EQ(Refusal(out).rfind(out.string() + ": holds centroids/, which dvpr did not write (it has no "
                                              "dvpr_manifest.txt)", 0), 0u) << Refusal(out);
  fs::remove_all(out / "centroids");
  fs::remove(out / "runs.csv");
  Write(out / "dvpr_manifest.txt", "not dvpr's\n");  // a lone file of that name is not a manifest
  EXPECT_EQ(Refusal(out).rfind(out.string() + ": holds dvpr_manifest.txt, which", 0), 0u) << Refusal(out);
  EXPECT_EQ(SnapshotFolder(out), (std::map<std::string, std::string>{{"dvpr_manifest.txt", "not dvpr's\n"}}));
}

TEST_F(ResultFolderTest, AUsersFileIsNeverDeletedByTheRerunThatWasRefused) {
  const fs::path out = EarlierResult();
  Write(out / "NOTES.txt", "my notes\n");
  const auto before = SnapshotFolder(root_);
  EXPECT_NE(Refusal(out), "");
  EXPECT_EQ(SnapshotFolder(root_), before);
  EXPECT_EQ(Names(root_), Strings{"out"});
}

// A file put into the target while the sweep ran is found when the folder is committed: the run
// fails naming it and the file stays.
TEST_F(ResultFolderTest, AFileAddedDuringTheSweepIsRefusedAtCommitNotDeleted) {
  const fs::path out = EarlierResult();
  ResultFolder folder(out);
  Write(folder.dir() / "runs.csv", "new");
  Write(out / "NOTES.txt", "written meanwhile\n");
  const auto before = SnapshotFolder(out);
  try {
    folder.Commit();
    ADD_FAILURE() << "committed over NOTES.txt";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(out.string() + ": holds NOTES.txt, which", 0), 0u) << e.what();
  }
  EXPECT_EQ(SnapshotFolder(out), before);
}

TEST_F(ResultFolderTest, TheManifestListsWhatTheRunWroteSortedAndIsAcceptedByTheNextRun) {
  const fs::path out = root_ / "out";
  {
    ResultFolder folder(out);
    fs::create_directories(folder.dir() / "figures" / "data");
    Write(folder.dir() / "runs.csv", "r");
    Write(folder.dir() / "config.yaml", "c");
    Write(folder.dir() / "figures" / "a.png", "p");
    Write(folder.dir() / "figures" / "data" / "a.dat", "d");
    folder.Commit();
  }
  EXPECT_EQ(Slurp(out / "dvpr_manifest.txt"),
            std::string(kManifestHeader) + "\nconfig.yaml\nfigures/\nfigures/a.png\nfigures/data/\nfigures/data/a.dat\nruns.csv\n");
  // A temporary of a writer that was killed (a `dvpr plot` stopped by SIGKILL) is dvpr's too.
  Write(out / "figures" / ".dvpr-0123456789abcdef.tmp", "half");
  {
    ResultFolder folder(out);
    Write(folder.dir() / "runs.csv", "r2");
    folder.Commit();
  }
  EXPECT_EQ(Names(out), (Strings{"dvpr_manifest.txt", "runs.csv"}));
  EXPECT_EQ(Slurp(out / "dvpr_manifest.txt"), std::string(kManifestHeader) + "\nruns.csv\n");
}

TEST_F(ResultFolderTest, ATargetNameOf250CharactersWorks) {
  const fs::path out = root_ / std::string(250, 'r');
  {
    ResultFolder folder(out);
    EXPECT_LE(folder.dir().filename().string().size(), 52u);
    Write(folder.dir() / "runs.csv", "new");
    folder.Commit();
  }
  {
    ResultFolder again(out);  // and replacing it
    Write(again.dir() / "runs.csv", "newer");
    again.Commit();
  }
  EXPECT_EQ(Names(root_), Strings{std::string(250, 'r')});
  EXPECT_EQ(Slurp(out / "runs.csv"), "newer");
}

TEST_F(ResultFolderTest, TemporaryNamesAreUnpredictable) {
  const fs::path a = ResultFolder(root_ / "out").dir();
  const fs::path b = ResultFolder(root_ / "out").dir();
  EXPECT_NE(a, b);
  const std::string prefix = ".dvpr-run-";
  EXPECT_EQ(a.filename().string().rfind(prefix, 0), 0u);
  EXPECT_EQ(Names(root_), Strings{});
}

TEST_F(ResultFolderTest, AParentWhereNothingCanBeMadeFailsAtOnceNamingIt) {
  Write(root_ / "file", "x");
  const std::string error = Refusal(root_ / "file" / "out");
  EXPECT_EQ(error, (root_ / "file").string() + ": cannot create the output folder (Not a directory)");
  const std::string proc = Refusal("/proc/dvpr_out");  // a file system that makes no folders
  EXPECT_EQ(proc.rfind("/proc/dvpr_out: cannot create a folder in /proc (", 0), 0u) << proc;
  EXPECT_EQ(Names(root_), Strings{"file"});
}

TEST(MountPointTest, MountInfoLinesAreReadByTheirFifthField) {
  const std::string mountinfo =
      "22 1 8:1 / / rw,relatime shared:1 - ext4 /dev/sda1 rw\n"
      "35 22 0:31 / /srv/my\\040data rw - ext4 /dev/sdb1 rw\n"
      "36 22 8:1 /home/u/results /work/out rw - ext4 /dev/sda1 rw\n";
  EXPECT_TRUE(MountInfoListsMountPoint(mountinfo, "/work/out"));  // a bind mount of a folder
  EXPECT_TRUE(MountInfoListsMountPoint(mountinfo, "/srv/my data"));
  EXPECT_TRUE(MountInfoListsMountPoint(mountinfo, "/"));
  EXPECT_FALSE(MountInfoListsMountPoint(mountinfo, "/work"));
  EXPECT_FALSE(MountInfoListsMountPoint(mountinfo, "/home/u/results"));  // the mount's source
  EXPECT_FALSE(MountInfoListsMountPoint(mountinfo, "/srv/my\\040data"));
  EXPECT_FALSE(MountInfoListsMountPoint("", "/"));
}

TEST(MountPointTest, ProcIsAMountPointAndAFolderInTheTestTreeIsNot) {
  EXPECT_TRUE(IsMountPoint("/proc"));
  const fs::path dir = fs::path(DVPR_TEST_TMP) / "mount_point";
  fs::create_directories(dir);
  EXPECT_FALSE(IsMountPoint(dir));
  try {
    ResultFolder folder("/proc");
    ADD_FAILURE() << "/proc accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "/proc: is a mount point, which dvpr run cannot replace (it puts its "
                                     "result folder in place by a rename); give a folder inside it, e.g. "
                                     "--out /proc/results");
  }
}

}  // namespace
}  // namespace dvpr
