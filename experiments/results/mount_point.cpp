#include "experiments/results/mount_point.h"

#include <fcntl.h>
#include <sys/stat.h>

#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>

namespace dvpr {

namespace {

// mountinfo escapes space, tab, newline and backslash as \ooo.
std::string Unescape(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 3 < s.size()) {
      const std::string_view d = s.substr(i + 1, 3);
      if (d.find_first_not_of("01234567") == std::string_view::npos) {
        out.push_back(static_cast<char>((d[0] - '0') * 64 + (d[1] - '0') * 8 + (d[2] - '0')));
        i += 3;
        continue;
      }
    }
    out.push_back(s[i]);
  }
  return out;
}

}  // namespace

bool MountInfoListsMountPoint(std::string_view mountinfo, const std::filesystem::path& canonical) {
  const std::string want = canonical.string();
  std::size_t pos = 0;
  while (pos < mountinfo.size()) {
    std::size_t end = mountinfo.find('\n', pos);
    if (end == std::string_view::npos) end = mountinfo.size();
    std::istringstream fields{std::string(mountinfo.substr(pos, end - pos))};
    std::string id, parent, dev, root, point;
    if (fields >> id >> parent >> dev >> root >> point && Unescape(point) == want) return true;
    pos = end + 1;
  }
  return false;
}

bool IsMountPoint(const std::filesystem::path& path) {
#ifdef STATX_ATTR_MOUNT_ROOT
  struct statx sx {};
  if (::statx(AT_FDCWD, path.c_str(), AT_SYMLINK_NOFOLLOW, STATX_BASIC_STATS, &sx) == 0 &&
      (sx.stx_attributes_mask & STATX_ATTR_MOUNT_ROOT) != 0) {
    return (sx.stx_attributes & STATX_ATTR_MOUNT_ROOT) != 0;
  }
#endif
  struct stat self {}, up {};
  const std::filesystem::path parent = path / "..";
  if (::stat(path.c_str(), &self) == 0 && ::stat(parent.c_str(), &up) == 0 && self.st_dev != up.st_dev) {
    return true;
  }
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::canonical(path, ec);
  if (ec) return false;
  std::ifstream in("/proc/self/mountinfo");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return MountInfoListsMountPoint(text, canonical);
}

}  // namespace dvpr
