#pragma once
// A result folder written as one transaction (README "Result folders"). `dvpr run` writes every
// file into a temporary folder next to the target (same file system), `.<name>.tmp-<pid>`, and
// Commit() puts it in the target's place in one rename; an earlier result folder there is
// replaced as a whole. Until then the earlier folder stays exactly as it was: an error unwinds
// through the destructor, a SIGINT/SIGTERM/SIGHUP is handled by termination_cleanup.h, both
// remove the temporary folder; one left by a killed (SIGKILL) process is removed by the next
// run that writes next to it.
//
// Only what dvpr itself wrote is ever replaced: the target must be absent, an empty folder or a
// dvpr result folder (IsResultFolder); anything else is refused before any file is written.
#include <filesystem>
#include <vector>

namespace dvpr {

// A folder whose runs.csv starts with dvpr's runs.csv header (every finished `dvpr run` writes
// one). An empty folder is not one (but may still be written into).
bool IsResultFolder(const std::filesystem::path& dir);

// Throws std::runtime_error naming `target` when a run may not write it (see ResultFolder);
// cheap, so `dvpr run` calls it before loading its inputs. Creates nothing.
void CheckOutputFolder(const std::filesystem::path& target);

class ResultFolder {
 public:
  // Checks that `target` may be written (CheckOutputFolder), removes temporary folders of dead
  // processes next to it and creates the temporary folder (and the target's parents). Throws
  // std::runtime_error naming `target` when it is a file, a symbolic link, the current folder or
  // one above it, or a non-empty folder that is not a dvpr result folder.
  explicit ResultFolder(const std::filesystem::path& target);
  // Removes the temporary folder; unless committed, also the target's parents it created.
  ~ResultFolder();
  ResultFolder(const ResultFolder&) = delete;
  ResultFolder& operator=(const ResultFolder&) = delete;

  // Where the run writes its files.
  const std::filesystem::path& dir() const { return tmp_; }
  // Puts dir() in the target's place and removes the earlier folder. Throws on failure (the
  // earlier folder then stays as it was).
  void Commit();

 private:
  std::filesystem::path shown_;   // the target as the user spelled it, for messages
  std::filesystem::path target_;  // absolute
  std::filesystem::path tmp_;
  std::vector<std::filesystem::path> created_parents_;  // removed again if never committed
  bool committed_ = false;
};

// The temporary folder a process `pid` writes for `target`: `.<name>.tmp-<pid>` beside it.
std::filesystem::path TemporaryFolderFor(const std::filesystem::path& target, long pid);

}  // namespace dvpr
