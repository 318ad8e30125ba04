#pragma once
// A result folder written as one transaction (README "Result folders"). `dvpr run` writes every
// file into a private temporary folder next to the target (same file system, a short random name:
// `.dvpr-run-<tag>-<pid>-<random>`, made exclusively and never followed through a link), and
// Commit() records what it holds in its manifest (manifest.h) and puts it in the target's place
// in one rename; an earlier result folder there is replaced as a whole. Until then the earlier
// folder stays exactly as it was: an error unwinds through the destructor, a
// SIGINT/SIGTERM/SIGHUP is handled by termination_cleanup.h, both remove the temporary folder;
// one left by a killed (SIGKILL) process is removed by the next run that writes next to it.
//
// Only what dvpr itself wrote is ever replaced: the target must be absent, an empty folder or a
// dvpr result folder holding only what its manifest lists; anything else is refused, naming the
// first foreign entry, before any file is written.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/results/safe_output.h"

namespace dvpr {

// Throws std::runtime_error naming `target` when a run may not write it (see ResultFolder): a
// file, a symbolic link, the current folder or one above it, a mount point (the final rename
// cannot replace it), or a non-empty folder holding an entry its manifest does not list (or
// without a manifest). Cheap, so `dvpr run` calls it before loading its inputs. Creates nothing.
void CheckOutputFolder(const std::filesystem::path& target);

class ResultFolder {
 public:
  // Checks that `target` may be written (CheckOutputFolder), removes temporary folders of dead
  // processes next to it and creates the temporary folder (and the target's parents): a parent
  // where nothing can be created fails here, before any run.
  explicit ResultFolder(const std::filesystem::path& target);
  // Removes the temporary folder; unless committed, also the target's parents it created.
  ~ResultFolder();
  ResultFolder(const ResultFolder&) = delete;
  ResultFolder& operator=(const ResultFolder&) = delete;

  // Where the run writes its files: the path, and the folder open (for safe_output.h).
  const std::filesystem::path& dir() const { return tmp_; }
  const OutputDir& output() const { return *output_; }
  // Writes the manifest, checks the target again (a file a user put there meanwhile is refused,
  // not deleted), puts dir() in the target's place and removes the earlier folder. Throws on
  // failure (the earlier folder then stays as it was).
  void Commit();

  // An error of the run before Commit(), for the user: the paths inside dir() (gone when the
  // folder unwinds) as their places in the target, and what became of the target.
  std::string Explain(std::string_view error) const;

 private:
  std::filesystem::path shown_;   // the target as the user spelled it, for messages
  std::filesystem::path target_;  // absolute
  int parent_fd_ = -1;            // the target's folder, open
  std::string tmp_name_;
  std::filesystem::path tmp_;
  std::optional<OutputDir> output_;
  std::vector<std::filesystem::path> created_parents_;  // removed again if never committed
  bool committed_ = false;
  bool existed_ = false;  // an earlier result folder was there
};

// The temporary folder a process `pid` writes for `target`, with `random` (RandomSuffix) as its
// unpredictable part: `.dvpr-run-<8 hex digits of the target's name>-<pid>-<random>` beside it,
// at most 52 bytes whatever the target's name.
std::filesystem::path TemporaryFolderFor(const std::filesystem::path& target, long pid,
                                         const std::string& random);

}  // namespace dvpr
