#include "experiments/results/result_folder.h"

#include <signal.h>
#include <stdio.h>  // renameat2, RENAME_EXCHANGE (glibc >= 2.28)
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "experiments/results/result_writers.h"
#include "experiments/results/termination_cleanup.h"

namespace dvpr {

namespace fs = std::filesystem;

namespace {

// The absolute target without a trailing separator ("out/" names the folder "out").
fs::path Normalised(const fs::path& target) {
  fs::path p = fs::absolute(target).lexically_normal();
  if (p.filename().empty() && p.has_parent_path()) p = p.parent_path();
  return p;
}

std::string TemporaryPrefix(const fs::path& target) {
  return "." + target.filename().string() + ".tmp-";
}

bool IsEmptyFolder(const fs::path& dir) {
  return fs::directory_iterator(dir) == fs::directory_iterator();
}

// A temporary folder whose process is gone (killed by SIGKILL, a crash) is no one's: remove it,
// also when the kill came while the cleanup removed it (kRemovingSuffix).
void RemoveStaleTemporaries(const fs::path& target) {
  const std::string prefix = TemporaryPrefix(target);
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(target.parent_path(), ec)) {
    const std::string name(WithoutRemovingSuffix(entry.path().filename().string()));
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    if (digits.size() > 9) continue;  // not a pid this tool wrote
    const long pid = std::stol(digits);
    if (pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    std::error_code ignored;
    fs::remove_all(entry.path(), ignored);
  }
}

void CheckReplaceable(const fs::path& shown, const fs::path& target) {
  const std::string name = shown.string();
  const fs::file_status st = fs::symlink_status(target);
  if (!fs::exists(st)) return;
  if (fs::is_symlink(st)) {
    throw std::runtime_error(name + ": is a symbolic link; give the folder itself as --out");
  }
  if (!fs::is_directory(st)) {
    throw std::runtime_error(name + ": exists and is not a folder; give a folder as --out");
  }
  const fs::path here = fs::canonical(fs::current_path());
  const fs::path canon = fs::canonical(target);
  if (std::mismatch(canon.begin(), canon.end(), here.begin(), here.end()).first == canon.end()) {
    throw std::runtime_error(name + ": is the current folder or contains it; dvpr run replaces "
                             "its --out folder as a whole, so give a folder below it");
  }
  if (!IsEmptyFolder(target) && !IsResultFolder(target)) {
    throw std::runtime_error(name + ": exists, is not empty and is not a dvpr result folder (no "
                             "runs.csv written by dvpr); dvpr run replaces only its own result "
                             "folders: remove it or choose another --out");
  }
}

}  // namespace

void CheckOutputFolder(const fs::path& target) { CheckReplaceable(target, Normalised(target)); }

fs::path TemporaryFolderFor(const fs::path& target, long pid) {
  const fs::path t = Normalised(target);
  return t.parent_path() / (TemporaryPrefix(t) + std::to_string(pid));
}

bool IsResultFolder(const fs::path& dir) {
  std::ifstream in(dir / "runs.csv");
  std::string first;
  return in && std::getline(in, first) && first == kRunsHeader;
}

ResultFolder::ResultFolder(const fs::path& target)
    : shown_(target), target_(Normalised(target)), tmp_(TemporaryFolderFor(target_, ::getpid())) {
  CheckReplaceable(shown_, target_);
  for (fs::path p = target_.parent_path(); !p.empty() && !fs::exists(p); p = p.parent_path()) {
    created_parents_.push_back(p);  // deepest first
    if (p == p.parent_path()) break;
  }
  CreateOutputDir(target_.parent_path());
  RemoveStaleTemporaries(target_);
  std::error_code ec;
  if (!CreateRemovedOnTermination(tmp_, ec)) {
    const std::string why = ec ? " (" + ec.message() + ")" : std::string();
    KeepOnTermination(tmp_);
    for (const fs::path& p : created_parents_) fs::remove(p, ec);
    throw std::runtime_error(tmp_.string() + ": cannot create the temporary result folder" + why);
  }
}

ResultFolder::~ResultFolder() {
  std::error_code ec;
  fs::remove_all(tmp_, ec);  // after Commit() it holds the earlier result folder, if any
  KeepOnTermination(tmp_);
  if (committed_) return;
  for (const fs::path& p : created_parents_) fs::remove(p, ec);  // only while empty
}

void ResultFolder::Commit() {
  const std::string name = shown_.string();
  // Held off from the termination cleanup: a signal during the rename is acted on after it
  // (and then removes whatever tmp_ holds by then, the new or the earlier folder).
  int error = 0;
  Uninterrupted([&] {
    if (!fs::exists(fs::symlink_status(target_))) {
      if (std::rename(tmp_.c_str(), target_.c_str()) != 0) error = errno;
      return;
    }
    // One atomic step: the target becomes the new folder, tmp_ the earlier one (removed by the
    // destructor). There is no moment at which the target is missing or mixed.
    if (::renameat2(AT_FDCWD, tmp_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0) {
      error = errno;
    }
  });
  if (error != 0) {
    throw std::runtime_error(name + ": cannot move the results into place (" +
                             std::strerror(error) + "); an earlier folder there is left as it was");
  }
  committed_ = true;
}

}  // namespace dvpr
