#pragma once
// Folders to remove when the process is told to stop (SIGINT, SIGTERM, SIGHUP), so an
// interrupted `dvpr run` leaves no temporary result folder behind. The signal handler only
// writes the signal number into a pipe (the one async-signal-safe step); a thread started for
// the purpose reads it, removes every registered folder, restores the default action and
// re-raises the signal, so the process still ends "killed by SIGTERM" for its parent.
// SIGKILL cannot be caught: what it leaves behind, the next run removes (result_folder.h).
#include <filesystem>
#include <functional>
#include <string_view>
#include <system_error>

namespace dvpr {

// Installs the handlers and the cleanup thread (once per process; again in a forked child),
// registers `dir` and makes it afresh (removing one of this pid's earlier life, after a SIGKILL
// and a reused pid), all with the cleanup held off: a signal's cleanup runs wholly before (the
// process ends and `dir` is never made) or wholly after (it removes `dir`). Its parent must
// exist. Returns false, with `ec` set, if `dir` could not be made; it stays registered then.
// Call before the threads that write into `dir` start.
bool CreateRemovedOnTermination(const std::filesystem::path& dir, std::error_code& ec);

// The cleanup renames a folder to its name + this suffix before removing it, so a SIGKILL during
// the removal leaves it under that name. The sweeps for dead processes' folders (result_folder.cpp,
// mpi_run_distributor.cpp) read the owner's pid from the name without it.
inline constexpr std::string_view kRemovingSuffix = ".removing";
inline std::string_view WithoutRemovingSuffix(std::string_view name) {
  return name.ends_with(kRemovingSuffix) ? name.substr(0, name.size() - kRemovingSuffix.size()) : name;
}

// Forgets `dir` (committed, or already removed).
void KeepOnTermination(const std::filesystem::path& dir);

// Runs `step` with the cleanup held off: a signal that arrives meanwhile is acted on after it,
// so a folder is never removed halfway through a sequence of renames.
void Uninterrupted(const std::function<void()>& step);

}  // namespace dvpr
