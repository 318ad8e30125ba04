// Where `dvpr run`, `dvpr plot` and `dvpr replay` may write, as a user runs them: a result
// folder holding a user's file is refused before the sweep and left byte-identical, a mount
// point as --out is refused up front naming it, a 250-character --out works, `plot` does not
// follow a `figures` link out of its folder, `replay --out` writes only a new file or over an
// earlier replay page.
#include <fcntl.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <algorithm>
#include <map>
#include <optional>
#include <utility>
#include <string>

#include <gtest/gtest.h>

#include "experiments/replay/replay.h"
#include "tests/app/cli_test_support.h"
#include "tests/test_support.h"

namespace dvpr::testing_support {
namespace {

namespace fs = std::filesystem;

class OutputPlaceTest : public CliTest {
 protected:
  // A short simulated run that records its messages: 3 robots, 60 frames, no figures.
  static std::string Yaml(const std::string& extra = "") {
    return "name: tiny\nseed: 2\ndataset: {dim: 16, frames: 60}\ntraining: {synthetic: {samples: 300}}\n"
           "robots: [3]\nruns: 1\nprotocols: [sim]\nevaluation: {suppression_frames: 10}\n"
           "outputs: {figures: false, messages: true}\n" + extra;
  }
  Result RunTo(const fs::path& out, const std::string& yaml = Yaml()) {
    std::ofstream(Config()) << yaml;
    return Dvpr("run '" + Config().string() + "' --quiet --out '" + out.string() + "'");
  }
  static void Write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }
  // Exit 1 and exactly this one line on stderr.
  static void ExpectError(const Result& r, const std::string& line) {
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_EQ(r.err, "dvpr: error: " + line + "\n");
  }
};

TEST_F(OutputPlaceTest, ARerunIntoAFolderWithAUsersFilesIsRefusedAndLeftByteIdentical) {
  ASSERT_EQ(RunTo(Out()).status, 0);
  EXPECT_TRUE(fs::exists(Out() / "dvpr_manifest.txt"));
  ASSERT_EQ(RunTo(Out()).status, 0) << "a folder holding only what dvpr wrote is replaced";
  Write(Out() / "NOTES.txt", "my notes\n");
  fs::create_directories(Out() / "analysis");
  Write(Out() / "analysis" / "fit.py", "print(1)\n");
  const auto before = SnapshotFolder(Out());  // every file's bytes
  ExpectError(RunTo(Out()), Out().string() + ": holds NOTES.txt, which dvpr did not write (not in its "
                            "dvpr_manifest.txt); dvpr run replaces only its own result folders, as a whole: "
                            "move it out, remove the folder or choose another --out");
  EXPECT_EQ(SnapshotFolder(Out()), before);
  EXPECT_EQ(Names(dir_), (std::vector<std::string>{"bad.yaml", "out", "stderr.txt", "stdout.txt"}));  // no temporary
  fs::remove(Out() / "NOTES.txt");
  const auto without_notes = SnapshotFolder(Out());
  EXPECT_NE(RunTo(Out()).err.find(Out().string() + ": holds analysis/, which dvpr did not write"), std::string::npos);
  EXPECT_EQ(SnapshotFolder(Out()), without_notes);
}

TEST_F(OutputPlaceTest, AMountPointAsOutIsRefusedUpFrontNamingIt) {
  ExpectError(RunTo("/proc"), "/proc: is a mount point, which dvpr run cannot replace (it puts its result "
                              "folder in place by a rename); give a folder inside it, e.g. --out /proc/results");
}

// A bind mount in a private mount namespace (a container volume's situation), made by a child
// that then becomes `dvpr run --out VOLUME`: the mount is gone with it. Everything the child
// needs is prepared before fork (it only makes system calls, then execs). Skipped where a mount
// namespace cannot be made (not root).
TEST_F(OutputPlaceTest, ABindMountedEmptyFolderAsOutIsRefusedBeforeTheSweep) {
  const fs::path volume = dir_ / "volume";
  const fs::path source = dir_ / "source";
  fs::create_directories(volume);
  fs::create_directories(source);
  std::ofstream(Config()) << Yaml();
  const std::string err_file = (dir_ / "stderr.txt").string();
  std::string exe = std::string(DVPR_BINARY_DIR) + "/dvpr", run = "run", config = Config().string(),
              quiet = "--quiet", out = "--out", where = volume.string();
  char* argv[] = {exe.data(), run.data(), config.data(), quiet.data(), out.data(), where.data(), nullptr};
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (::unshare(CLONE_NEWNS) != 0 || ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0 ||
        ::mount(source.c_str(), volume.c_str(), nullptr, MS_BIND, nullptr) != 0) {
      _exit(77);
    }
    const int fd = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0 || ::dup2(fd, 2) < 0) _exit(78);
    ::execv(argv[0], argv);
    _exit(79);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 77) GTEST_SKIP() << "no private mount namespace here";
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_EQ(Slurp(err_file), "dvpr: error: " + volume.string() + ": is a mount point, which dvpr run cannot "
                             "replace (it puts its result folder in place by a rename); give a folder inside "
                             "it, e.g. --out " + (volume / "results").string() + "\n");
  EXPECT_EQ(Names(source), std::vector<std::string>{});
  EXPECT_EQ(Names(dir_), (std::vector<std::string>{"bad.yaml", "source", "stderr.txt", "volume"}));
}

// `dvpr run --out FULL/r` in a private mount namespace where FULL is a tmpfs of `bytes` (a
// child makes the mount, then execs dvpr with `path` as PATH): exit status and stderr, or
// nullopt where no mount namespace can be made (not root). The mount goes with the child.
std::optional<std::pair<int, std::string>> RunOnATinyDisk(const fs::path& dir, const fs::path& config,
                                                           std::size_t bytes, const std::string& path) {
  const fs::path full = dir / "full";
  fs::create_directories(full);
  const std::string err_file = (dir / "stderr.txt").string();
  const std::string size = "size=" + std::to_string(bytes);
  std::string exe = std::string(DVPR_BINARY_DIR) + "/dvpr", run = "run", cfg = config.string(), quiet = "--quiet",
              out = "--out", where = (full / "r").string(), env_path = "PATH=" + path;
  char* argv[] = {exe.data(), run.data(), cfg.data(), quiet.data(), out.data(), where.data(), nullptr};
  char* envp[] = {env_path.data(), nullptr};
  const pid_t child = ::fork();
  if (child < 0) return std::nullopt;
  if (child == 0) {
    if (::unshare(CLONE_NEWNS) != 0 || ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0 ||
        ::mount("tmpfs", full.c_str(), "tmpfs", 0, size.c_str()) != 0) {
      _exit(77);
    }
    const int fd = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0 || ::dup2(fd, 2) < 0) _exit(78);
    ::execve(argv[0], argv, envp);
    _exit(79);
  }
  int status = 0;
  if (::waitpid(child, &status, 0) != child || !WIFEXITED(status) || WEXITSTATUS(status) == 77) return std::nullopt;
  return std::make_pair(WEXITSTATUS(status), Slurp(err_file));
}

// A full disk while the rows are written: the error names the file where the user asked for it
// (not inside the temporary folder, which is gone by then) and says nothing was written.
TEST_F(OutputPlaceTest, AFullDiskNamesTheFileInTheTargetNotTheGoneTemporaryFolder) {
  std::ofstream(Config()) << Yaml();
  const auto r = RunOnATinyDisk(dir_, Config(), 16 * 1024, "/usr/bin:/bin");
  if (!r) GTEST_SKIP() << "no private mount namespace here";
  const std::string target = (dir_ / "full" / "r").string();
  EXPECT_EQ(r->first, 1) << r->second;
  EXPECT_EQ(r->second.rfind("dvpr: error: " + target + "/", 0), 0u) << r->second;
  EXPECT_NE(r->second.find(": write failed (No space left on device); nothing was written to " + target + "\n"),
            std::string::npos) << r->second;
  EXPECT_EQ(r->second.find(".dvpr-run"), std::string::npos) << r->second;
  EXPECT_EQ(std::count(r->second.begin(), r->second.end(), '\n'), 1) << r->second;
}

// A figure that fails because the disk is full says so, with the bytes free: no guess, no quote of
// gnuplot's warnings (a good draw prints them too), no log (the run's folder is removed with it),
// no "skipped" notes before it. The stand-in gnuplot prints a warning, writes the PNG's signature,
// then fills the disk from inside the run's folder, and exits 0.
TEST_F(OutputPlaceTest, AFigureOnAFullDiskSaysTheDiskIsFull) {
  const fs::path bin = dir_ / "bin";
  fs::create_directories(bin);
  Write(bin / "gnuplot", "#!/bin/sh\necho 'warning: a harmless warning' >&2\nprintf '\\211PNG\\r\\n\\032\\n'\n"
                         "cat /dev/zero > filler 2>/dev/null\nexit 0\n");
  fs::permissions(bin / "gnuplot", fs::perms::owner_all);
  std::string yaml = Yaml();
  std::ofstream(Config()) << yaml.replace(yaml.find("figures: false"), 14, "figures: true");
  const auto r = RunOnATinyDisk(dir_, Config(), 8 << 20, bin.string() + ":/usr/bin:/bin");
  if (!r) GTEST_SKIP() << "no private mount namespace here";
  const std::string target = (dir_ / "full" / "r").string();
  EXPECT_EQ(r->first, 1) << r->second;
  EXPECT_EQ(r->second.rfind("dvpr: error: figure confusion_matrix.png: the file system holding " + target +
                                "/figures is full (0 bytes free; gnuplot could write 8 bytes of the PNG) (and ",
                            0),
            0u)
      << r->second;
  EXPECT_NE(r->second.find(" more figures); nothing was written to " + target + "\n"), std::string::npos) << r->second;
  EXPECT_EQ(r->second.find("warning"), std::string::npos) << r->second;
  EXPECT_EQ(r->second.find("log"), std::string::npos) << r->second;
  EXPECT_EQ(std::count(r->second.begin(), r->second.end(), '\n'), 1) << r->second;  // no "skipped" notes
}

TEST_F(OutputPlaceTest, AnOutOf250CharactersWorks) {
  const fs::path out = dir_ / std::string(250, 'o');
  const Result r = RunTo(out);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "runs.csv"));
  EXPECT_EQ(RunTo(out).status, 0);  // and replacing it
}

TEST_F(OutputPlaceTest, PlotDoesNotFollowAFiguresLinkOutOfTheFolder) {
  ASSERT_EQ(RunTo(Out()).status, 0);
  const fs::path outside = dir_ / "outside";
  fs::create_directories(outside);
  fs::create_directory_symlink(outside, Out() / "figures");
  ExpectError(Dvpr("plot '" + Out().string() + "'"),
              (Out() / "figures").string() + ": is a symbolic link (dvpr does not write through links it did not make)");
  fs::remove(Out() / "figures");
  fs::create_directories(Out() / "figures");
  fs::create_directory_symlink(outside, Out() / "figures" / "data");
  ExpectError(Dvpr("plot '" + Out().string() + "'"), (Out() / "figures" / "data").string() +
                                                         ": is a symbolic link (dvpr does not write through links it did not make)");
  EXPECT_EQ(Names(outside), std::vector<std::string>{});
}

TEST_F(OutputPlaceTest, ReplayWritesOnlyANewFileOrOverAnEarlierPage) {
  ASSERT_EQ(RunTo(Out()).status, 0);
  const std::string runs = Slurp(Out() / "runs.csv");
  const std::string refused = "; dvpr replay writes only a new file or over an earlier replay page: choose another --out";
  ExpectError(Dvpr("replay '" + Out().string() + "' --out '" + (Out() / "runs.csv").string() + "'"),
              (Out() / "runs.csv").string() + ": exists and is not a replay page" + refused);
  EXPECT_EQ(Slurp(Out() / "runs.csv"), runs);
  const fs::path victim = dir_ / "victim.txt";
  Write(victim, "precious");
  fs::create_symlink(victim, dir_ / "page.html");
  ExpectError(Dvpr("replay '" + Out().string() + "' --out '" + (dir_ / "page.html").string() + "'"),
              (dir_ / "page.html").string() + ": is a symbolic link" + refused);
  EXPECT_EQ(Slurp(victim), "precious");
  // A new file, then over that earlier page.
  const fs::path page = dir_ / "new.html";
  EXPECT_EQ(Dvpr("replay '" + Out().string() + "' --out '" + page.string() + "'").status, 0);
  EXPECT_EQ(Slurp(page).rfind(replay::kReplayPageMarker, 0), 0u) << "the page no longer starts with its marker";
  const Result again = Dvpr("replay '" + Out().string() + "' --strategy broadcast --out '" + page.string() + "'");
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_NE(Slurp(page).find("\"strategies\":[{\"name\":\"broadcast\""), std::string::npos);
}

// What plot and replay add to a result folder is recorded in its manifest: a later run replaces
// the folder (the page is dvpr's), where a user's file would be refused.
TEST_F(OutputPlaceTest, APageReplayWroteIntoTheFolderIsDvprsForTheNextRun) {
  ASSERT_EQ(RunTo(Out()).status, 0);
  ASSERT_EQ(Dvpr("replay '" + Out().string() + "'").status, 0);
  EXPECT_NE(Slurp(Out() / "dvpr_manifest.txt").find("\nreplay_n3_run0_net0.html\n"), std::string::npos);
  const Result r = RunTo(Out());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(Out() / "replay_n3_run0_net0.html"));  // replaced as a whole
}

}  // namespace
}  // namespace dvpr::testing_support
