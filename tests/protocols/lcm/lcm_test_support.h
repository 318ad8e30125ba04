#pragma once
// Shared by the LCM tests: an isolated network namespace per test (loopback
// only, multicast routed to it), `dvpr agent` processes, the small config.
#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agents/auth/team_secret.h"
#include "agents/lcm/lcm_transport.h"
#include "tests/test_support.h"

namespace dvpr::lcm_test {

namespace fs = std::filesystem;

// Moves this test process (and the agents it starts) into a fresh network
// namespace with only loopback, multicast-capable: nothing reaches real
// interfaces and tests running in parallel do not hear each other. Returns
// the reason when that is impossible (then the test skips).
inline std::string IsolateNetwork() {
  if (unshare(CLONE_NEWNET) != 0) return std::string("unshare(CLONE_NEWNET) failed: ") + std::strerror(errno);
  for (const std::vector<std::string>& ip : {std::vector<std::string>{"ip", "link", "set", "lo", "up"},
                                             std::vector<std::string>{"ip", "link", "set", "lo", "multicast", "on"},
                                             std::vector<std::string>{"ip", "route", "add", "224.0.0.0/4", "dev", "lo"}}) {
    if (testing_support::RunProgram(ip, "/dev/null") != 0) {
      return "could not set up loopback multicast in the new namespace (ip failed)";
    }
  }
  return "";
}

// recv_buf_size: every agent receives every datagram of the group (LCM's udpm filters channels
// after receipt), 25 kB verification requests among them. With the kernel's default 208 KiB
// socket buffer, an agent process starved for a moment on a loaded machine overflowed it and the
// kernel dropped datagrams (seen as dropped_messages > 0 and a verification that never ended).
// 4 MiB is what LCM's documentation advises for udpm (the kernel caps it at net.core.rmem_max).
// A result CSV's rows by column name (tests/test_support.h).
using testing_support::ReadCsv;
using testing_support::Row;

inline std::string Url(int port) {
  return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0&recv_buf_size=4194304";
}

// The small team every test runs: KITTI 00's first 300 frames, a short
// suppression window so matches exist, a small training set for a quick
// k-means, queries written, and 1 kB verification requests: every agent receives every datagram
// of the multicast group, and with 25 kB requests (about 3.5 MB/s for the team at speedup 5) a
// process starved for a second on a loaded machine overflowed its receive buffers and LCM lost
// datagrams (seen: 9 messages to one robot, 7 replies missing, under load average 8-13). The
// exchange is the same with 1 kB; only the volume a starved process must catch up on shrinks.
inline std::vector<std::string> SmallConfigSets() {
  return {"dataset.frames=300", "evaluation.suppression_frames=20", "training.synthetic.samples=2000",
          "outputs.queries=true", "outputs.figures=false", "verification.request_bytes=1000"};
}

inline std::string ConfigPath() { return std::string(DVPR_SOURCE_DIR) + "/experiments/configs/paper_kitti00.yaml"; }
inline std::string Dvpr() { return std::string(DVPR_BINARY_DIR) + "/dvpr"; }

inline fs::path TestDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(DVPR_TEST_TMP) / "lcm" / (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// fork/exec with stdout and stderr to `log`.
inline pid_t Spawn(const std::vector<std::string>& argv, const fs::path& log) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const std::string out = log.string();
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
    }
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

// The secret of a team a test starts itself (dvpr launch makes its own): one file per folder,
// readable by its owner only, made once and shared by every agent whose log goes there.
inline fs::path TeamSecret(fs::path dir) {
  while (!dir.empty() && dir != dir.parent_path() && !fs::is_directory(dir)) dir = dir.parent_path();  // a test of a missing folder
  const fs::path path = dir / "team.secret";
  if (!fs::exists(path)) auth::WriteSecretFile(path, auth::DrawSecret());
  return path;
}

// grace_s: wall seconds a robot waits after the team's last frame (dvpr agent --grace).
// The team's secret is TeamSecret(the log's folder).
inline std::vector<std::string> AgentArgv(int robot, int robots, const std::string& strategy, int port,
                                          double speedup, const fs::path& log, double grace_s = 2.0) {
  std::vector<std::string> a{Dvpr(), "agent", "--config", ConfigPath()};
  for (const auto& s : SmallConfigSets()) {
    a.push_back("--set");
    a.push_back(s);
  }
  for (const std::string& s : {std::string("--robot"), std::to_string(robot), std::string("--robots"),
                               std::to_string(robots), std::string("--strategy"), strategy, std::string("--lcm"),
                               Url(port), std::string("--speedup"), std::to_string(speedup),
                               std::string("--out"), log.string(), std::string("--grace"),
                               std::to_string(grace_s), std::string("--team-secret"),
                               TeamSecret(log.parent_path()).string()}) {
    a.push_back(s);
  }
  return a;
}

// Waits for `pid` up to `timeout`, handling `transport`'s messages meanwhile
// (the wait is the transport's poll, not a sleep). Kills it at the timeout.
// Returns the wait status, or -1 when it had to be killed.
inline int WaitFor(pid_t pid, std::chrono::seconds timeout, LcmTransport* transport = nullptr) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  int status = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (waitpid(pid, &status, WNOHANG) == pid) return status;
    if (transport != nullptr) {
      transport->RunUntilWall(std::chrono::steady_clock::now() + std::chrono::milliseconds(20));
    } else {
      // No transport to wait on: block in waitpid with a timer signal would be
      // overkill for a test helper; poll at 20 ms via ppoll on nothing.
      timespec ts{0, 20000000};
      ppoll(nullptr, 0, &ts, nullptr);
    }
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return -1;
}

}  // namespace dvpr::lcm_test
