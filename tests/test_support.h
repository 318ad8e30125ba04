#pragma once
// Small helpers shared by the test files of every module: reading whole output files, starting a
// program without a shell, a folder of the test's own. Nothing
// here includes a project header, so a test of any layer can use it (descriptor_support.h has
// the helpers that need agents/).
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

extern char** environ;

namespace dvpr::testing_support {

// The whole file, byte for byte ("" if it cannot be opened).
inline std::string Slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A result CSV's rows by column name (a field the row lacks reads as empty; no quoting: dvpr's
// result files quote no field these tests read).
using Row = std::map<std::string, std::string>;
inline std::vector<Row> ReadCsv(const std::filesystem::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream hs(line);
  for (std::string c; std::getline(hs, c, ',');) header.push_back(c);
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    Row row;
    std::stringstream ls(line);
    std::size_t i = 0;
    for (std::string c; i < header.size(); ++i) {
      if (!std::getline(ls, c, ',')) c.clear();
      row[header[i]] = c;
    }
    rows.push_back(row);
  }
  return rows;
}

// Every entry below `root` (hidden ones too), relative path -> bytes; folders map to "<dir>".
// Two equal snapshots mean the folder is byte-identical, with nothing added or removed.
inline std::map<std::string, std::string> SnapshotFolder(const std::filesystem::path& root) {
  std::map<std::string, std::string> entries;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    const std::string rel = std::filesystem::relative(e.path(), root).string();
    entries[rel] = e.is_directory() ? std::string("<dir>") : Slurp(e.path());
  }
  return entries;
}

// An empty folder DVPR_TEST_TMP/<group>/<suite>.<test> for the running test alone. ctest runs
// each test as its own process, two at once, so a folder shared by the tests of a fixture would
// be emptied by one test's SetUp while another test writes into it.
inline std::filesystem::path FreshTestDir(const std::string& group) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::path(DVPR_TEST_TMP) / group /
                                    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// The names in `dir` (not below it), sorted.
inline std::vector<std::string> Names(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Runs argv[0] with an argument vector (posix_spawnp, no shell: quotes, `$(...)` and ';' in an
// argument reach the program as they are; a name without '/' is looked up in PATH), stdout and stderr into files (stderr into stdout's
// when `err` is empty), in folder `cwd` when not empty, with `env` ("NAME=value", replacing a
// variable of that name) added to this process's environment. Returns the exit status, -1 when
// the program could not start or did not exit.
inline int RunProgram(const std::vector<std::string>& argv, const std::filesystem::path& out,
                      const std::filesystem::path& err = {}, const std::filesystem::path& cwd = {},
                      const std::vector<std::string>& env = {}) {
  std::vector<std::string> env_strings;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry(*e);
    const bool replaced = std::any_of(env.begin(), env.end(), [&](const std::string& v) {
      return entry.compare(0, v.find('=') + 1, v, 0, v.find('=') + 1) == 0;
    });
    if (!replaced) env_strings.push_back(entry);
  }
  env_strings.insert(env_strings.end(), env.begin(), env.end());
  std::vector<char*> args, envp;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  for (const std::string& e : env_strings) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (err.empty()) {
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
  } else {
    posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  }
  if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int raw = 0;
  while (waitpid(pid, &raw, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

}  // namespace dvpr::testing_support
