#include "experiments/results/manifest.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <string_view>

#include "experiments/results/safe_output.h"

namespace dvpr {

namespace {

struct Entry {
  std::string name;
  bool folder = false;  // a real folder, not a link to one
  bool link = false;
};

// The entries of the open folder `fd` (not below it), sorted by name; `fd` stays open.
std::vector<Entry> EntriesOf(int fd) {
  std::vector<Entry> out;
  const int copy = ::fcntl(fd, F_DUPFD_CLOEXEC, 0);
  if (copy < 0) return out;
  DIR* d = ::fdopendir(copy);
  if (d == nullptr) {
    ::close(copy);
    return out;
  }
  while (const dirent* e = ::readdir(d)) {
    const std::string name = e->d_name;
    if (name == "." || name == "..") continue;
    struct stat st {};
    const bool known = ::fstatat(fd, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0;
    out.push_back({name, known && S_ISDIR(st.st_mode), known && S_ISLNK(st.st_mode)});
  }
  ::closedir(d);
  std::sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) { return a.name < b.name; });
  return out;
}

void ListInto(int fd, const std::string& prefix, std::vector<std::string>& out) {
  for (const Entry& e : EntriesOf(fd)) {
    if (IsDvprTemporary(e.name) || (prefix.empty() && e.name == kManifestName)) continue;
    if (!e.folder) {
      out.push_back(prefix + e.name);
      continue;
    }
    out.push_back(prefix + e.name + "/");
    const int sub = ::openat(fd, e.name.c_str(), kDirFlags);
    if (sub < 0) continue;
    ListInto(sub, prefix + e.name + "/", out);
    ::close(sub);
  }
}

std::optional<std::string> ForeignIn(int fd, const std::string& prefix, const std::set<std::string>& manifest) {
  for (const Entry& e : EntriesOf(fd)) {
    if (IsDvprTemporary(e.name) || (prefix.empty() && e.name == kManifestName)) continue;
    const std::string listed = prefix + e.name + (e.folder ? "/" : "");
    if (e.link || !manifest.contains(listed)) return listed;  // dvpr makes no links
    if (!e.folder) continue;
    const int sub = ::openat(fd, e.name.c_str(), kDirFlags);
    if (sub < 0) return listed;  // a folder dvpr cannot read is not one it can vouch for
    const std::optional<std::string> found = ForeignIn(sub, listed, manifest);
    ::close(sub);
    if (found) return found;
  }
  return std::nullopt;
}

bool IsHex(std::string_view s) { return s.find_first_not_of("0123456789abcdef") == std::string_view::npos; }

}  // namespace

bool IsDvprTemporary(const std::string& name) {
  const std::string_view n = name;
  constexpr std::string_view kPrefix = ".dvpr-";
  if (!n.starts_with(kPrefix)) return false;
  const std::string_view rest = n.substr(kPrefix.size());
  if (rest.size() < 16 || !IsHex(rest.substr(0, 16))) return false;
  const std::string_view tail = rest.substr(16);
  return tail == ".tmp" || tail == ".scratch";
}

std::vector<std::string> ListEntries(int dir_fd) {
  std::vector<std::string> out;
  ListInto(dir_fd, "", out);
  std::sort(out.begin(), out.end());
  return out;
}

std::string ManifestText(const std::vector<std::string>& entries) {
  std::string text = std::string(kManifestHeader) + "\n";
  for (const std::string& e : entries) text += e + "\n";
  return text;
}

std::optional<std::set<std::string>> ReadManifest(int dir_fd) {
  const int fd = ::openat(dir_fd, kManifestName, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  std::string text;
  char buf[1 << 14];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    text.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fd);
  const std::string header = std::string(kManifestHeader) + "\n";
  if (!text.starts_with(header)) return std::nullopt;
  std::set<std::string> entries;
  std::size_t pos = header.size();
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    const std::size_t stop = end == std::string::npos ? text.size() : end;
    if (stop > pos) entries.insert(text.substr(pos, stop - pos));
    pos = stop + 1;
  }
  return entries;
}

std::optional<std::string> FirstForeignEntry(int dir_fd, const std::set<std::string>& manifest) {
  return ForeignIn(dir_fd, "", manifest);
}

void AddToManifest(const OutputDir& dir, const std::vector<std::string>& entries) {
  std::optional<std::set<std::string>> manifest = ReadManifest(dir.fd());
  if (!manifest) return;
  manifest->insert(entries.begin(), entries.end());
  WriteFileAt(dir, kManifestName, ManifestText({manifest->begin(), manifest->end()}));
}

}  // namespace dvpr
