#pragma once
// Runs the dvpr binary the way a user does (its arguments, stderr captured; no shell) for the
// tests of its command line and its errors; each test gets a fresh folder.
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

#include "tests/test_support.h"

namespace dvpr::testing_support {

struct Result {
  int status = -1;
  std::string err;
};

class CliTest : public ::testing::Test {
 protected:
  using path = std::filesystem::path;

  void SetUp() override {
    dir_ = std::filesystem::absolute(FreshTestDir("cli")).lexically_normal();
  }
  // Writes `yaml` to a config file and runs `dvpr run` on it (stderr captured).
  Result RunConfig(const std::string& yaml, const std::string& extra = "") {
    std::ofstream(Config()) << yaml;
    return Dvpr("run '" + Config().string() + "' --quiet --out '" + Out().string() + "' " + extra);
  }
  // A team secret for `dvpr agent` (docs/security.md): 64 hexadecimal digits, mode 0600.
  path Secret() {
    const path p = dir_ / "team.secret";
    std::ofstream(p) << std::string(64, 'a') << "\n";
    std::filesystem::permissions(p, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
    return p;
  }
  // Runs dvpr with `args` split into words as a shell would split them, but only at spaces and
  // with '...' quoting (nothing is expanded, nothing else is special): no shell runs.
  Result Dvpr(const std::string& args) {
    std::vector<std::string> words;
    std::string word;
    bool quoted = false, in_word = false;
    for (const char c : args) {
      if (c == '\'') {
        quoted = !quoted;
        in_word = true;
      } else if (c == ' ' && !quoted) {
        if (in_word) words.push_back(word);
        word.clear();
        in_word = false;
      } else {
        word += c;
        in_word = true;
      }
    }
    EXPECT_FALSE(quoted) << "unbalanced quote in: " << args;
    if (in_word) words.push_back(word);
    return Spawn(words, {}, {});
  }
  // Runs dvpr with an argument vector, without a shell, so paths and names with quotes,
  // backquotes, $(...), ';' or newlines reach it as they are; in folder dir_, stdout and stderr
  // captured as Dvpr() does. `search_path`, when not empty, replaces $PATH (a stand-in gnuplot).
  Result DvprArgv(const std::vector<std::string>& args, const std::string& search_path = "") {
    return Spawn(args, dir_, search_path.empty() ? std::vector<std::string>{}
                                                 : std::vector<std::string>{"PATH=" + search_path});
  }
  std::string Stdout() const {
    std::ifstream in(dir_ / "stdout.txt");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  // dvpr with `args` (stdout.txt and stderr.txt in dir_), in `cwd` when not empty.
  Result Spawn(const std::vector<std::string>& args, const path& cwd, const std::vector<std::string>& env) {
    std::vector<std::string> argv{std::string(DVPR_BINARY_DIR) + "/dvpr"};
    argv.insert(argv.end(), args.begin(), args.end());
    Result r;
    r.status = RunProgram(argv, dir_ / "stdout.txt", dir_ / "stderr.txt", cwd, env);
    std::ifstream in(dir_ / "stderr.txt");
    r.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return r;
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
