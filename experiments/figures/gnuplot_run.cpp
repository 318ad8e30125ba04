#include "experiments/figures/gnuplot_run.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <cstdint>
#include <sstream>
#include <stdexcept>

#include "experiments/figures/gnuplot_text.h"
#include "experiments/results/safe_output.h"

extern char** environ;

namespace dvpr {

namespace {

namespace fs = std::filesystem;

// posix_spawn's file actions and attributes, destroyed with the object.
struct SpawnSetup {
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attr;
  SpawnSetup() {
    posix_spawn_file_actions_init(&actions);
    posix_spawnattr_init(&attr);
  }
  ~SpawnSetup() {
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
  }
  SpawnSetup(const SpawnSetup&) = delete;
  SpawnSetup& operator=(const SpawnSetup&) = delete;
};

std::string Errno(int e) { return std::strerror(e); }

// Less than this free beside a PNG gnuplot could not finish: the disk was full (the largest
// figure, confusion_matrix.png, is about 320 kB).
constexpr std::uint64_t kRoomForAFigure = 1 << 20;

// A whole PNG: the 8-byte signature first, the 12-byte IEND chunk last (a full disk or a killed
// gnuplot leaves a file cut short or empty).
bool WholePng(int fd) {
  static constexpr std::array<unsigned char, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  static constexpr std::array<unsigned char, 12> kIend = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
  struct stat st {};
  if (::fstat(fd, &st) != 0 || st.st_size < 8 + 12) return false;
  std::array<unsigned char, 8> head{};
  std::array<unsigned char, 12> tail{};
  return ::pread(fd, head.data(), head.size(), 0) == 8 && head == kSignature &&
         ::pread(fd, tail.data(), tail.size(), st.st_size - 12) == 12 && tail == kIend;
}

// gnuplot's first lines that say something, as one line (its errors quote the script line
// and point at it with a caret on the next), read from the open log.
std::string FirstWords(int fd) {
  std::string text(4096, '\0');
  const ssize_t n = ::pread(fd, text.data(), text.size(), 0);
  text.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  std::istringstream in(text);
  std::string words;
  for (std::string line; std::getline(in, line) && words.size() < 200;) {
    if (line.find_first_not_of(" \t^") == std::string::npos) continue;
    words += (words.empty() ? "" : " / ") + line.substr(line.find_first_not_of(" \t"));
  }
  if (words.size() > 200) words = words.substr(0, 200) + "...";
  return OneLineText(words);
}

std::int64_t FileBytes(int fd) {
  struct stat st {};
  return ::fstat(fd, &st) == 0 ? static_cast<std::int64_t>(st.st_size) : 0;
}

// "the file system holding DIR is full (N bytes free; ...)" when less than a PNG's worth is left
// where `fd` was written, else "" (a cut-short PNG on a file system with room has another cause).
std::string FullFileSystem(int fd, const fs::path& dir) {
  struct statvfs v {};
  if (::fstatvfs(fd, &v) != 0) return "";
  const auto free_bytes = static_cast<std::uint64_t>(v.f_bavail) * v.f_frsize;
  if (free_bytes >= kRoomForAFigure) return "";
  return "the file system holding " + dir.string() + " is full (" + std::to_string(free_bytes) +
         " bytes free; gnuplot could write " + std::to_string(FileBytes(fd)) + " bytes of the PNG)";
}

}  // namespace

std::optional<fs::path> FindProgram(std::string_view name) {
  const char* env = std::getenv("PATH");
  const std::string path = env != nullptr ? env : "/usr/bin:/bin";
  for (std::size_t start = 0; start <= path.size();) {
    std::size_t end = path.find(':', start);
    if (end == std::string::npos) end = path.size();
    const std::string folder = path.substr(start, end - start);
    start = end + 1;
    if (folder.empty()) continue;
    std::error_code ec;
    const fs::path candidate = fs::absolute(fs::path(folder) / name, ec);
    if (!ec && fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

std::string RunProgram(const fs::path& program, const std::vector<std::string>& argv, const fs::path& dir, int out_fd,
                       int err_fd) {
  SpawnSetup s;
  // The child starts with default signal handling and no blocked signals, whatever the caller set.
  sigset_t none, all;
  sigemptyset(&none);
  sigfillset(&all);
  posix_spawnattr_setsigmask(&s.attr, &none);
  posix_spawnattr_setsigdefault(&s.attr, &all);
  posix_spawnattr_setflags(&s.attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawn_file_actions_addchdir_np(&s.actions, dir.c_str());
  posix_spawn_file_actions_addopen(&s.actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&s.actions, out_fd, 1);
  posix_spawn_file_actions_adddup2(&s.actions, err_fd, 2);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  if (const int e = posix_spawn(&pid, program.c_str(), &s.actions, &s.attr, args.data(), environ); e != 0) {
    return "cannot start it: " + Errno(e);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return "cannot wait for it: " + Errno(errno);
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status) == 0 ? "" : "exit status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  return "status " + std::to_string(status);
}

void DrawWithGnuplot(const fs::path& gnuplot, const fs::path& data_dir, const fs::path& gp, const fs::path& png,
                     const fs::path& log, FigureLog kept) {
  // Both files go through the one writer (safe_output.h): private temporaries created O_EXCL and
  // O_NOFOLLOW relative to their open folders, renamed into place, so a link planted at a final
  // or a temporary name is never followed. The log reaches its name only when the figure failed.
  AtomicFile err(OutputDir::Open(log.parent_path()), log.filename().string());
  AtomicFile out(OutputDir::Open(png.parent_path()), png.filename().string());
  // The PNG goes to gnuplot's standard output, the private file opened above: gnuplot never opens
  // an output path itself. The script's own `set output` (its PNG by name, for a rerun by hand)
  // yields to dvpr_output; the value is a fixed string, single-quoted.
  const std::string failure = RunProgram(gnuplot, {"gnuplot", "-e", "dvpr_output='/dev/stdout'", gp.filename().string()},
                                         data_dir, out.fd(), err.fd());
  if (failure.empty() && WholePng(out.fd())) {
    if (::fsync(out.fd()) != 0) throw std::runtime_error(png.string() + ": cannot write it: " + Errno(errno));
    out.Commit();
    std::error_code ec;
    fs::remove(log, ec);  // an earlier failure's log (a link there is removed, not followed)
    return;
  }
  std::string what;
  if (const std::string full = FullFileSystem(out.fd(), png.parent_path()); failure.empty() && !full.empty()) {
    what = full;  // gnuplot's warnings are those of a good draw: not the cause
  } else {
    const std::string words = FirstWords(err.fd());
    what = (failure.empty() ? "gnuplot exited 0 but wrote no whole PNG (" + std::to_string(FileBytes(out.fd())) + " bytes)"
                            : "gnuplot failed (" + failure + ")") +
           (words.empty() ? "" : ": " + words);
  }
  // The PNG's temporary goes with `out`: a half-drawn PNG never replaces the earlier one.
  bool logged = false;
  if (kept == FigureLog::kKept) {
    try {
      err.Commit();
      logged = true;
    } catch (const std::runtime_error&) {  // the disk that refused the PNG may refuse its log too
    }
  }
  throw std::runtime_error("figure " + png.filename().string() + ": " + what + (logged ? "; its log: " + log.string() : ""));
}

}  // namespace dvpr
