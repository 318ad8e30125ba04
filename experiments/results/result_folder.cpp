#include "experiments/results/result_folder.h"

#include <signal.h>
#include <stdio.h>  // renameat2, RENAME_EXCHANGE, RENAME_NOREPLACE (glibc >= 2.28)
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

#include "experiments/results/manifest.h"
#include "experiments/results/mount_point.h"
#include "experiments/results/result_writers.h"
#include "experiments/results/safe_output.h"
#include "experiments/results/termination_cleanup.h"

namespace dvpr {

namespace fs = std::filesystem;

namespace {

constexpr const char* kTemporaryPrefix = ".dvpr-run-";

// The absolute target without a trailing separator ("out/" names the folder "out").
fs::path Normalised(const fs::path& target) {
  fs::path p = fs::absolute(target).lexically_normal();
  if (p.filename().empty() && p.has_parent_path()) p = p.parent_path();
  return p;
}

// 8 hex digits of the target's name (FNV-1a): temporaries of one target are told from those of
// its neighbours without the name itself, which may be 255 bytes long.
std::string NameTag(const fs::path& target) {
  std::uint32_t h = 2166136261u;
  for (const unsigned char c : target.filename().string()) h = (h ^ c) * 16777619u;
  char buf[9];
  std::snprintf(buf, sizeof buf, "%08x", h);
  return buf;
}

std::string TemporaryPrefix(const fs::path& target) { return kTemporaryPrefix + NameTag(target) + "-"; }

// A temporary folder whose process is gone (killed by SIGKILL, a crash) is no one's: remove it,
// also when the kill came while the cleanup removed it (kRemovingSuffix).
void RemoveStaleTemporaries(int parent_fd, const fs::path& target) {
  const std::string prefix = TemporaryPrefix(target);
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(target.parent_path(), ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string rest(WithoutRemovingSuffix(name.substr(prefix.size())));  // <pid>-<16 hex>
    const std::size_t dash = rest.find('-');
    if (dash == std::string::npos || dash == 0 || dash > 9) continue;
    const std::string digits = rest.substr(0, dash);
    if (digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const long pid = std::stol(digits);
    if (pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    RemoveTreeAt(parent_fd, name);
  }
}

struct Foreign {
  std::string entry;
  bool has_manifest = false;
};

// The first entry of the existing folder `target` that dvpr did not write; nullopt when it holds
// only what its manifest lists (or nothing).
std::optional<Foreign> ForeignEntry(const fs::path& shown, const fs::path& target) {
  const int fd = ::open(target.c_str(), kDirFlags);
  if (fd < 0) throw std::runtime_error(shown.string() + ": cannot read the folder (" + std::strerror(errno) + ")");
  const std::optional<std::set<std::string>> manifest = ReadManifest(fd);
  std::optional<std::string> found = FirstForeignEntry(fd, manifest.value_or(std::set<std::string>{}));
  struct stat st {};
  if (!found && !manifest && ::fstatat(fd, kManifestName, &st, AT_SYMLINK_NOFOLLOW) == 0) {
    found = kManifestName;  // a file of that name that is not a manifest
  }
  ::close(fd);
  if (!found) return std::nullopt;
  return Foreign{*found, manifest.has_value()};
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
  if (IsMountPoint(target)) {
    throw std::runtime_error(name + ": is a mount point, which dvpr run cannot replace (it puts "
                             "its result folder in place by a rename); give a folder inside it, "
                             "e.g. --out " + (shown / "results").string());
  }
  const std::optional<Foreign> foreign = ForeignEntry(shown, target);
  if (!foreign) return;
  const std::string why = foreign->has_manifest ? std::string("not in its ") + kManifestName
                                                : std::string("it has no ") + kManifestName;
  throw std::runtime_error(name + ": holds " + foreign->entry + ", which dvpr did not write (" + why +
                           "); dvpr run replaces only its own result folders, as a whole: move it "
                           "out, remove the folder or choose another --out");
}

int OpenParent(const fs::path& parent, const fs::path& shown) {
  const int fd = ::open(parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) {
    throw std::runtime_error(shown.string() + ": cannot open its folder " + parent.string() + " (" +
                             std::strerror(errno) + ")");
  }
  return fd;
}

}  // namespace

void CheckOutputFolder(const fs::path& target) { CheckReplaceable(target, Normalised(target)); }

fs::path TemporaryFolderFor(const fs::path& target, long pid, const std::string& random) {
  const fs::path t = Normalised(target);
  return t.parent_path() / (TemporaryPrefix(t) + std::to_string(pid) + "-" + random);
}

ResultFolder::ResultFolder(const fs::path& target) : shown_(target), target_(Normalised(target)) {
  CheckReplaceable(shown_, target_);
  std::error_code exists_ec;
  existed_ = fs::exists(target_, exists_ec);
  for (fs::path p = target_.parent_path(); !p.empty() && !fs::exists(p); p = p.parent_path()) {
    created_parents_.push_back(p);  // deepest first
    if (p == p.parent_path()) break;
  }
  std::error_code ec;
  try {
    CreateOutputDir(target_.parent_path());
    parent_fd_ = OpenParent(target_.parent_path(), shown_);
    RemoveStaleTemporaries(parent_fd_, target_);
    // A fresh random name each attempt: one that exists already was not made for this run.
    for (int attempt = 0; attempt < 100 && !output_; ++attempt) {
      tmp_ = TemporaryFolderFor(target_, ::getpid(), RandomSuffix());
      tmp_name_ = tmp_.filename().string();
      if (CreateRemovedOnTermination(tmp_, ec)) {
        output_.emplace(OutputDir::Open(tmp_));
      } else {
        KeepOnTermination(tmp_);
        if (ec != std::errc::file_exists) break;
      }
    }
    if (!output_) {
      throw std::runtime_error(shown_.string() + ": cannot create a folder in " +
                               target_.parent_path().string() + " (" + ec.message() +
                               "); choose an --out where you can write");
    }
  } catch (...) {
    if (parent_fd_ >= 0) ::close(parent_fd_);
    for (const fs::path& p : created_parents_) fs::remove(p, ec);
    throw;
  }
}

ResultFolder::~ResultFolder() {
  output_.reset();
  RemoveTreeAt(parent_fd_, tmp_name_);  // after Commit() it holds the earlier result folder, if any
  KeepOnTermination(tmp_);
  ::close(parent_fd_);
  if (committed_) return;
  std::error_code ec;
  for (const fs::path& p : created_parents_) fs::remove(p, ec);  // only while empty
}

void ResultFolder::Commit() {
  WriteFileAt(*output_, kManifestName, ManifestText(ListEntries(output_->fd())));
  CheckReplaceable(shown_, target_);  // a file put there during the sweep is refused, not deleted
  const std::string name = target_.filename().string();
  // Held off from the termination cleanup: a signal during the rename is acted on after it
  // (and then removes whatever tmp_ holds by then, the new or the earlier folder).
  int error = 0;
  Uninterrupted([&] {
    struct stat st {};
    if (::fstatat(parent_fd_, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) {
      if (::renameat2(parent_fd_, tmp_name_.c_str(), parent_fd_, name.c_str(), RENAME_NOREPLACE) != 0) {
        error = errno;
      }
      return;
    }
    // One atomic step: the target becomes the new folder, tmp_ the earlier one (removed by the
    // destructor). There is no moment at which the target is missing or mixed.
    if (::renameat2(parent_fd_, tmp_name_.c_str(), parent_fd_, name.c_str(), RENAME_EXCHANGE) != 0) {
      error = errno;
    }
  });
  if (error != 0) {
    throw std::runtime_error(shown_.string() + ": cannot move the results into place (" +
                             std::strerror(error) + "); an earlier folder there is left as it was");
  }
  committed_ = true;
}

std::string ResultFolder::Explain(std::string_view error) const {
  const std::string tmp = tmp_.string();
  std::string shown = shown_.string();
  while (shown.size() > 1 && shown.back() == '/') shown.pop_back();
  std::string out;
  for (std::size_t at = 0;;) {
    const std::size_t hit = tmp.empty() ? std::string_view::npos : error.find(tmp, at);
    out.append(error.substr(at, hit == std::string_view::npos ? std::string_view::npos : hit - at));
    if (hit == std::string_view::npos) break;
    out += shown;
    at = hit + tmp.size();
  }
  return out + "; nothing was written to " + shown + (existed_ ? " (its earlier results are as they were)" : "");
}

}  // namespace dvpr
