#pragma once
// Folders to remove when the process is told to stop (SIGINT, SIGTERM, SIGHUP), so an
// interrupted `dvpr run` leaves no temporary result folder behind. The signal handler only
// writes the signal number into a pipe (the one async-signal-safe step); a thread started for
// the purpose reads it, removes every registered folder, restores the default action and
// re-raises the signal, so the process still ends "killed by SIGTERM" for its parent.
// SIGKILL cannot be caught: what it leaves behind, the next run removes (result_folder.h).
#include <filesystem>
#include <functional>

namespace dvpr {

// Installs the handlers and the cleanup thread (once per process; again in a forked child) and
// registers `dir`. Call before the threads that write into `dir` start, and before `dir` is
// made; make it inside Uninterrupted(), so a signal's cleanup cannot run between a removal
// that found nothing and the mkdir that follows it.
void RemoveOnTermination(const std::filesystem::path& dir);

// Forgets `dir` (committed, or already removed).
void KeepOnTermination(const std::filesystem::path& dir);

// Runs `step` with the cleanup held off: a signal that arrives meanwhile is acted on after it,
// so a folder is never removed halfway through a sequence of renames.
void Uninterrupted(const std::function<void()>& step);

}  // namespace dvpr
