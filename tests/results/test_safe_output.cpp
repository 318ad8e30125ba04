// The one output writer (experiments/results/safe_output.h): files appear whole under their final
// name and nowhere else, a symbolic link planted at a temporary or a final name is never
// followed, a failed write is an error and leaves nothing, and a file another program wrote into
// a scratch folder is committed only when it is a non-empty regular file.
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/results/safe_output.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

using testing_support::Names;
using testing_support::Slurp;
using Strings = std::vector<std::string>;

class SafeOutputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = dvpr::testing_support::FreshTestDir("safe_output");
    fs::create_directories(root_ / "out");
    fs::create_directories(root_ / "elsewhere");
    victim_ = root_ / "elsewhere" / "victim.txt";
    std::ofstream(victim_) << "precious";
  }
  // The message of the std::runtime_error `f` throws ("" if it throws none).
  template <typename F>
  static std::string ErrorOf(F f) {
    try {
      f();
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }
  fs::path root_;
  fs::path victim_;
};

TEST_F(SafeOutputTest, AFileAppearsWholeUnderItsNameAndNothingElseIsLeft) {
  const OutputDir dir = OutputDir::Open(root_ / "out");
  {
    AtomicFile f(dir, "runs.csv");
    f.stream() << "a,b\n1,2\n";
    EXPECT_EQ(Names(root_ / "out").size(), 1u);  // the temporary only
    EXPECT_FALSE(fs::exists(root_ / "out" / "runs.csv"));
    f.Commit();
  }
  WriteFileAt(dir, "summary.json", "{}\n");
  WriteFileAtomic(root_ / "out" / "config.yaml", "name: x\n");
  EXPECT_EQ(Names(root_ / "out"), (Strings{"config.yaml", "runs.csv", "summary.json"}));
  EXPECT_EQ(Slurp(root_ / "out" / "runs.csv"), "a,b\n1,2\n");
  EXPECT_EQ(Slurp(root_ / "out" / "summary.json"), "{}\n");
}

TEST_F(SafeOutputTest, AnUncommittedFileIsRemovedAndTheEarlierOneKept) {
  WriteFileAtomic(root_ / "out" / "runs.csv", "earlier");
  {
    AtomicFile f(OutputDir::Open(root_ / "out"), "runs.csv");
    f.stream() << "half";
  }
  EXPECT_EQ(Names(root_ / "out"), Strings{"runs.csv"});
  EXPECT_EQ(Slurp(root_ / "out" / "runs.csv"), "earlier");
}

// The names the writers used before (".<name>.tmp<pid>", "<name>.tmp.<pid>.0") were predictable:
// a link planted there made dvpr overwrite its target.
TEST_F(SafeOutputTest, LinksAtTheOldPredictableTemporaryNamesAreNotFollowed) {
  const std::string pid = std::to_string(::getpid());
  for (const std::string& name : {".page.html.tmp" + pid, "page.html.tmp." + pid + ".0"}) {
    fs::create_symlink(victim_, root_ / "out" / name);
  }
  WriteFileAtomic(root_ / "out" / "page.html", "<html>");
  EXPECT_EQ(Slurp(victim_), "precious");
  EXPECT_EQ(Slurp(root_ / "out" / "page.html"), "<html>");
}

// Whatever sits at the temporary's name once it is made, the writes go to the file that was
// created: a link put in its place meanwhile does not receive them.
TEST_F(SafeOutputTest, ALinkSwappedInAtTheTemporaryNameDoesNotReceiveTheWrites) {
  const OutputDir dir = OutputDir::Open(root_ / "out");
  AtomicFile f(dir, "page.html");
  const Strings names = Names(root_ / "out");
  ASSERT_EQ(names.size(), 1u);
  const fs::path tmp = root_ / "out" / names[0];
  EXPECT_EQ(names[0].rfind(".dvpr-", 0), 0u);
  fs::remove(tmp);
  fs::create_symlink(victim_, tmp);
  f.stream() << std::string(1 << 17, 'x');  // more than the buffer: written before Commit
  f.Write("<html>");
  EXPECT_EQ(Slurp(victim_), "precious");
}

TEST_F(SafeOutputTest, ALinkAtTheFinalNameIsReplacedNotFollowed) {
  fs::create_symlink(victim_, root_ / "out" / "runs.csv");
  WriteFileAtomic(root_ / "out" / "runs.csv", "new");
  EXPECT_EQ(Slurp(victim_), "precious");
  EXPECT_FALSE(fs::is_symlink(root_ / "out" / "runs.csv"));
  EXPECT_EQ(Slurp(root_ / "out" / "runs.csv"), "new");
}

TEST_F(SafeOutputTest, TwoWritersOfOneNameUseTheirOwnTemporaries) {
  const OutputDir dir = OutputDir::Open(root_ / "out");
  AtomicFile a(dir, "runs.csv");
  AtomicFile b(dir, "runs.csv");
  a.Write("from a");
  b.Write("from b");
  a.Commit();
  EXPECT_EQ(Slurp(root_ / "out" / "runs.csv"), "from a");
  b.Commit();
  EXPECT_EQ(Slurp(root_ / "out" / "runs.csv"), "from b");
  EXPECT_EQ(Names(root_ / "out"), Strings{"runs.csv"});
}

TEST_F(SafeOutputTest, FoldersThatAreLinksAreRefusedNamingThem) {
  fs::create_directory_symlink(root_ / "elsewhere", root_ / "out" / "figures");
  const OutputDir dir = OutputDir::Open(root_ / "out");
  const std::string sub = ErrorOf([&] { dir.Sub("figures"); });
  EXPECT_EQ(sub, (root_ / "out" / "figures").string() +
                     ": is a symbolic link (dvpr does not write through links it did not make)");
  const std::string open = ErrorOf([&] { OutputDir::Open(root_ / "out" / "figures"); });
  EXPECT_EQ(open.rfind((root_ / "out" / "figures").string() + ": is a symbolic link", 0), 0u) << open;
  const std::string path = ErrorOf([&] { WriteFileAtomic(root_ / "out" / "figures" / "x.dat", "1"); });
  EXPECT_EQ(path.rfind((root_ / "out" / "figures").string() + ": is a symbolic link", 0), 0u) << path;
  EXPECT_EQ(Names(root_ / "elsewhere"), Strings{"victim.txt"});
}

TEST_F(SafeOutputTest, SubMakesAFolderOnceAndOpensAnExistingOne) {
  const OutputDir dir = OutputDir::Open(root_ / "out");
  {
    const OutputDir figures = dir.Sub("figures");
    WriteFileAt(figures.Sub("data"), "a.dat", "1\n");
  }
  const OutputDir again = dir.Sub("figures", OutputDir::Create::kNo);
  EXPECT_EQ(again.path(), root_ / "out" / "figures");
  EXPECT_EQ(Slurp(root_ / "out" / "figures" / "data" / "a.dat"), "1\n");
  EXPECT_NE(ErrorOf([&] { dir.Sub("absent", OutputDir::Create::kNo); }), "");
  WriteFileAt(dir, "file", "x");
  EXPECT_EQ(ErrorOf([&] { dir.Sub("file"); }), (root_ / "out" / "file").string() + ": exists and is not a folder");
}

// A file that cannot be written whole is an error, not a short file: in a child whose file size
// limit is 100 bytes (write() then fails with EFBIG, as it fails with ENOSPC on a full disk).
TEST_F(SafeOutputTest, AFailedWriteIsAnErrorAndLeavesNoFile) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{100, 100};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    int code = 1;
    try {
      AtomicFile f(OutputDir::Open(root_ / "out"), "big.csv");
      f.stream() << std::string(1000, 'x');
      f.Commit();
    } catch (const std::runtime_error& e) {
      const std::string want = (root_ / "out" / "big.csv").string() + ": write failed (File too large)";
      code = std::string(e.what()) == want ? 0 : 2;
    }
    _exit(code);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: no error, 2: another message";
  EXPECT_EQ(Names(root_ / "out"), Strings{});
}

TEST_F(SafeOutputTest, ANameOf255BytesWorks) {
  const std::string name(255, 'n');
  WriteFileAtomic(root_ / "out" / name, "x");
  EXPECT_EQ(Names(root_ / "out"), Strings{name});
}

TEST_F(SafeOutputTest, AScratchFolderIsPrivateAndCommitsOnlyANonEmptyRegularFile) {
  const OutputDir dir = OutputDir::Open(root_ / "out");
  fs::path scratch_path;
  {
    ScratchDir scratch(dir);
    scratch_path = scratch.path();
    EXPECT_EQ(scratch_path.parent_path(), root_ / "out");
    struct stat st {};
    ASSERT_EQ(::stat(scratch_path.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0700u);
    std::ofstream(scratch_path / "a.png") << "PNG";
    std::ofstream(scratch_path / "empty.png");
    fs::create_symlink(victim_, scratch_path / "link.png");
    scratch.CommitFile("a.png", "figure.png");
    const std::string shown = (root_ / "out" / "figure.png").string();
    EXPECT_EQ(ErrorOf([&] { scratch.CommitFile("empty.png", "figure.png"); }),
              shown + ": was written empty (a full disk?)");
    EXPECT_EQ(ErrorOf([&] { scratch.CommitFile("link.png", "figure.png"); }),
              shown + ": was not written as a regular file");
    EXPECT_EQ(ErrorOf([&] { scratch.CommitFile("none.png", "figure.png"); }),
              shown + ": was not written (No such file or directory)");
  }
  EXPECT_FALSE(fs::exists(scratch_path));
  EXPECT_EQ(Names(root_ / "out"), Strings{"figure.png"});
  EXPECT_EQ(Slurp(root_ / "out" / "figure.png"), "PNG");
  EXPECT_EQ(Slurp(victim_), "precious");
}

TEST_F(SafeOutputTest, RemoveTreeDoesNotFollowLinks) {
  fs::create_directories(root_ / "out" / "tree" / "sub");
  std::ofstream(root_ / "out" / "tree" / "sub" / "f") << "x";
  fs::create_directory_symlink(root_ / "elsewhere", root_ / "out" / "tree" / "sub" / "link");
  const OutputDir dir = OutputDir::Open(root_ / "out");
  RemoveTreeAt(dir.fd(), "tree");
  EXPECT_EQ(Names(root_ / "out"), Strings{});
  EXPECT_EQ(Names(root_ / "elsewhere"), Strings{"victim.txt"});
}

TEST_F(SafeOutputTest, RandomSuffixesDiffer) {
  const std::string a = RandomSuffix();
  EXPECT_EQ(a.size(), 16u);
  EXPECT_EQ(a.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_NE(a, RandomSuffix());
}

}  // namespace
}  // namespace dvpr
