#pragma once
// Runs the dvpr binary the way a user does (a shell command, stderr captured) for the tests of
// its command line and its errors; each test gets a fresh folder.
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

namespace dvpr::testing_support {

struct Result {
  int status = -1;
  std::string err;
};

class CliTest : public ::testing::Test {
 protected:
  using path = std::filesystem::path;

  void SetUp() override {
    dir_ = std::filesystem::absolute(path(DVPR_TEST_TMP) / "cli" /
                                     ::testing::UnitTest::GetInstance()->current_test_info()->name())
               .lexically_normal();
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  // Writes `yaml` to a config file and runs `dvpr run` on it (stderr captured).
  Result RunConfig(const std::string& yaml, const std::string& extra = "") {
    std::ofstream(Config()) << yaml;
    return Dvpr("run '" + Config().string() + "' --quiet --out '" + Out().string() + "' " + extra);
  }
  Result Dvpr(const std::string& args) {
    const path err = dir_ / "stderr.txt";
    const std::string cmd = std::string("'") + DVPR_BINARY_DIR + "/dvpr' " + args + " > '" +
                            (dir_ / "stdout.txt").string() + "' 2> '" + err.string() + "'";
    Result r;
    const int raw = std::system(cmd.c_str());
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    std::ifstream in(err);
    r.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return r;
  }
  std::string Stdout() const {
    std::ifstream in(dir_ / "stdout.txt");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  path Config() const { return dir_ / "bad.yaml"; }
  path Out() const { return dir_ / "out"; }
  // Exit 1, exactly one line on stderr that contains `expected`, no output folder.
  void ExpectConfigError(const Result& r, const std::string& expected) {
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_EQ(r.err.rfind("dvpr: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(Out()));
  }
  // Exactly this status and this one line on stderr, no output folder.
  void ExpectExactly(const Result& r, int status, const std::string& line) {
    EXPECT_EQ(r.status, status) << r.err;
    EXPECT_EQ(r.err, line + "\n");
    EXPECT_FALSE(std::filesystem::exists(Out()));
  }
  path dir_;
};

}  // namespace dvpr::testing_support
