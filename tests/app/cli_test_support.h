#pragma once
// Runs the dvpr binary the way a user does (a shell command, stderr captured) for the tests of
// its command line and its errors; each test gets a fresh folder.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

extern char** environ;

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
  // Runs dvpr with an argument vector, without a shell, so paths and names with quotes,
  // backquotes, $(...), ';' or newlines reach it as they are; in folder dir_, stdout and stderr
  // captured as Dvpr() does. `search_path`, when not empty, replaces $PATH (a stand-in gnuplot).
  Result DvprArgv(const std::vector<std::string>& args, const std::string& search_path = "") {
    const std::string binary = std::string(DVPR_BINARY_DIR) + "/dvpr";
    std::vector<std::string> env_strings;
    for (char** e = environ; *e != nullptr; ++e) {
      if (search_path.empty() || std::string(*e).rfind("PATH=", 0) != 0) env_strings.emplace_back(*e);
    }
    if (!search_path.empty()) env_strings.push_back("PATH=" + search_path);
    std::vector<char*> argv = {const_cast<char*>(binary.c_str())}, envp;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    for (const std::string& e : env_strings) envp.push_back(const_cast<char*>(e.c_str()));
    envp.push_back(nullptr);
    const path err = dir_ / "stderr.txt", out = dir_ / "stdout.txt";
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addchdir_np(&actions, dir_.c_str());
    pid_t pid = 0;
    Result r;
    const int spawned = posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) {
      ADD_FAILURE() << "cannot start " << binary;
      return r;
    }
    int raw = 0;
    while (waitpid(pid, &raw, 0) < 0 && errno == EINTR) {
    }
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
