#include "experiments/results/termination_cleanup.h"

#include <pthread.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

namespace dvpr {

namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

std::mutex& Mutex() {
  static std::mutex m;
  return m;
}
std::vector<std::filesystem::path>& Registered() {
  static std::vector<std::filesystem::path> dirs;
  return dirs;
}
int g_pipe_write = -1;   // written by the handler only
pid_t g_installed_for = 0;

extern "C" void ForwardSignal(int sig) {
  const int saved = errno;
  const unsigned char byte = static_cast<unsigned char>(sig);
  [[maybe_unused]] const ssize_t n = ::write(g_pipe_write, &byte, 1);
  errno = saved;
}

// Removes dir, trying until it is gone or `attempts` passes failed.
void RemoveAll(const std::filesystem::path& dir, int attempts) {
  for (int attempt = 0; attempt < attempts; ++attempt) {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
    if (!std::filesystem::exists(dir, ec)) return;
  }
}

// Workers may still be writing into the folder: removing it in place races with them (a file
// made after remove_all listed the folder keeps it from being removed, pass after pass). So it
// is first renamed away, in one step: from then on a new file under its old path cannot be made,
// and only writes already inside open() can land in the renamed folder, which a further pass
// removes. A folder made again under the old path meanwhile (create_directories) goes last.
void RemoveFolder(const std::filesystem::path& dir) {
  std::filesystem::path away = dir;
  away += kRemovingSuffix;
  std::error_code ec;
  std::filesystem::rename(dir, away, ec);
  if (!ec) RemoveAll(away, 100);
  RemoveAll(dir, 10);
}

void CleanUpThenDie(int read_fd) {
  unsigned char sig = 0;
  while (::read(read_fd, &sig, 1) != 1) {
    if (errno != EINTR) return;
  }
  std::lock_guard lock(Mutex());  // held until the process ends: nothing commits meanwhile
  for (const auto& dir : Registered()) RemoveFolder(dir);
  std::signal(sig, SIG_DFL);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, sig);
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
  std::raise(sig);
  _exit(128 + sig);  // not reached: the default action ends the process
}

// Called with Mutex() held.
void InstallOnce() {
  if (g_installed_for == ::getpid()) return;
  int fds[2];
  if (::pipe(fds) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
  g_pipe_write = fds[1];
  std::thread(CleanUpThenDie, fds[0]).detach();
  struct sigaction sa {};
  sa.sa_handler = ForwardSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  for (int sig : kSignals) ::sigaction(sig, &sa, nullptr);
  g_installed_for = ::getpid();
  Registered().clear();  // a forked child does not own its parent's folders
}

}  // namespace

bool CreateRemovedOnTermination(const std::filesystem::path& dir, std::error_code& ec) {
  std::lock_guard lock(Mutex());
  InstallOnce();
  Registered().push_back(dir);
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
  if (std::filesystem::create_directory(dir, ec)) return true;
  if (!ec) ec = std::make_error_code(std::errc::file_exists);  // made by another process meanwhile
  return false;
}

void KeepOnTermination(const std::filesystem::path& dir) {
  std::lock_guard lock(Mutex());
  auto& dirs = Registered();
  dirs.erase(std::remove(dirs.begin(), dirs.end(), dir), dirs.end());
}

}  // namespace dvpr

namespace dvpr {

void Uninterrupted(const std::function<void()>& step) {
  std::lock_guard lock(Mutex());
  step();
}

}  // namespace dvpr
