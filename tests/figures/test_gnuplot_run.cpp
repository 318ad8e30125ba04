// Starting gnuplot (gnuplot_run.h) with stand-ins for it: small scripts that fail, die, or write
// a PNG cut short; the earlier PNG must stay, nothing temporary may be left, the error must name
// the figure, what happened and the log.
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "experiments/figures/gnuplot_run.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;
using testing_support::Names;
using testing_support::Slurp;

// The smallest file the PNG check accepts: the signature and the IEND chunk.
const std::string kWholePng = std::string("\x89PNG\r\n\x1a\n", 8) + std::string("\0\0\0\0IEND\xae\x42\x60\x82", 12);

class GnuplotRun : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dvpr::testing_support::FreshTestDir("gnuplot_run");
    fs::create_directories(dir_ / "figures" / "data");
    fs::create_directories(dir_ / "bin");
    std::ofstream(data() / "f.gp") << "# stand-in script\n";
    std::ofstream(png()) << "earlier";
  }
  // An executable `name` in dir_/bin running `body` (a /bin/sh script).
  fs::path Program(const std::string& name, const std::string& body) {
    const fs::path p = dir_ / "bin" / name;
    std::ofstream(p) << "#!/bin/sh\n" << body << "\n";
    fs::permissions(p, fs::perms::owner_all);
    return p;
  }
  fs::path data() const { return dir_ / "figures" / "data"; }
  fs::path png() const { return dir_ / "figures" / "f.png"; }
  // Draws f.png with `program`; the error text, or "" when drawn.
  std::string Draw(const fs::path& program) {
    try {
      DrawWithGnuplot(program, data(), data() / "f.gp", png(), data() / "f.log");
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(GnuplotRun, AWholePngReplacesTheEarlierOne) {
  std::ofstream(dir_ / "good.png") << kWholePng;
  EXPECT_EQ(Draw(Program("ok", "cat " + (dir_ / "good.png").string())), "");
  EXPECT_EQ(Slurp(png()), kWholePng);
  EXPECT_EQ(Names(dir_ / "figures"), (std::vector<std::string>{"data", "f.png"}));
  EXPECT_FALSE(fs::exists(data() / "f.log"));  // removed once the figure is drawn
}

TEST_F(GnuplotRun, TheChildRunsInTheDataFolderWithTheScriptAndOutput) {
  EXPECT_NE(Draw(Program("args", "pwd >&2; echo \"$@\" >&2; exit 2")), "");
  EXPECT_EQ(Slurp(data() / "f.log"), fs::canonical(data()).string() + "\n-e dvpr_output='/dev/stdout' f.gp\n");
}

TEST_F(GnuplotRun, AFailureKeepsTheEarlierPngAndNamesFigureAndLog) {
  const std::string err = Draw(Program("fails", "echo 'line 3: undefined variable: x' >&2; echo '   ^' >&2; exit 1"));
  EXPECT_EQ(err, "figure f.png: gnuplot failed (exit status 1): line 3: undefined variable: x; its log: " +
                     (data() / "f.log").string());
  EXPECT_EQ(Slurp(png()), "earlier");
  EXPECT_EQ(Names(dir_ / "figures"), (std::vector<std::string>{"data", "f.png"}));  // no temporary left
  EXPECT_EQ(Slurp(data() / "f.log"), "line 3: undefined variable: x\n   ^\n");
}

TEST_F(GnuplotRun, AKilledGnuplotIsAFailure) {
  EXPECT_EQ(Draw(Program("killed", "kill -9 $$")),
            "figure f.png: gnuplot failed (killed by signal 9); its log: " + (data() / "f.log").string());
  EXPECT_EQ(Slurp(png()), "earlier");
}

TEST_F(GnuplotRun, APngCutShortOrEmptyIsAFailureEvenWithStatusZero) {
  // The signature alone (as a full disk leaves it), then nothing at all.
  // On a disk with room that is not the disk's doing: the bytes written, gnuplot's words, its log.
  for (const auto& [body, bytes] : {std::pair<std::string, int>{"printf '\\211PNG\\r\\n\\032\\n'", 8}, {"true", 0}}) {
    EXPECT_EQ(Draw(Program("short", body)), "figure f.png: gnuplot exited 0 but wrote no whole PNG (" +
                                                std::to_string(bytes) + " bytes); its log: " + (data() / "f.log").string());
    EXPECT_EQ(Slurp(png()), "earlier");
    EXPECT_EQ(Names(dir_ / "figures"), (std::vector<std::string>{"data", "f.png"}));
  }
}

// The PNG and the log go through the one writer: links planted at their names (a PNG drawn, a
// log written on failure) are replaced, their target untouched.
TEST_F(GnuplotRun, LinksAtThePngAndLogNamesAreReplacedNotFollowed) {
  fs::create_directories(dir_ / "elsewhere");
  const fs::path victim = dir_ / "elsewhere" / "victim.txt";
  std::ofstream(victim) << "precious";
  std::ofstream(dir_ / "good.png") << kWholePng;
  fs::remove(png());
  fs::create_symlink(victim, png());
  fs::create_symlink(victim, data() / "f.log");
  EXPECT_EQ(Draw(Program("ok", "echo drawn >&2; cat " + (dir_ / "good.png").string())), "");
  EXPECT_FALSE(fs::is_symlink(png()));
  EXPECT_EQ(Slurp(png()), kWholePng);
  EXPECT_FALSE(fs::exists(fs::symlink_status(data() / "f.log")));  // the link is removed, not its target
  fs::create_symlink(victim, data() / "f.log");
  EXPECT_NE(Draw(Program("fails", "echo oops >&2; exit 1")), "");
  EXPECT_FALSE(fs::is_symlink(data() / "f.log"));
  EXPECT_EQ(Slurp(data() / "f.log"), "oops\n");
  EXPECT_EQ(Slurp(victim), "precious");
  EXPECT_EQ(Names(data()), (std::vector<std::string>{"f.gp", "f.log"}));  // no temporary left
}

TEST_F(GnuplotRun, AProgramThatCannotStart) {
  EXPECT_EQ(Draw(dir_ / "bin" / "missing"), "figure f.png: gnuplot failed (cannot start it: No such file or directory); "
                                            "its log: " + (data() / "f.log").string());
}

// PATH search without a shell: the first executable regular file, skipping empty entries,
// folders of the name and files that are not executable.
TEST_F(GnuplotRun, FindProgramSearchesPath) {
  struct RestorePath {
    std::string saved = std::getenv("PATH") ? std::getenv("PATH") : "";
    ~RestorePath() { ::setenv("PATH", saved.c_str(), 1); }
  } restore;
  fs::create_directories(dir_ / "a" / "tool");     // a folder of the name
  fs::create_directories(dir_ / "b");
  std::ofstream(dir_ / "b" / "tool") << "not executable";
  fs::permissions(dir_ / "b" / "tool", fs::perms::owner_read | fs::perms::owner_write);
  const fs::path tool = Program("tool", "true");
  ::setenv("PATH", (":" + (dir_ / "a").string() + "::" + (dir_ / "b").string() + ":" + (dir_ / "bin").string()).c_str(), 1);
  EXPECT_EQ(FindProgram("tool"), tool);
  EXPECT_EQ(FindProgram("no_such_tool"), std::nullopt);
  ::setenv("PATH", (dir_ / "a").string().c_str(), 1);
  EXPECT_EQ(FindProgram("tool"), std::nullopt);
}

}  // namespace
}  // namespace dvpr
