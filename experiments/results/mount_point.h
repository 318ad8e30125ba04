#pragma once
// Whether a folder is a mount point (a container volume, a bind mount). `dvpr run --out` cannot
// put its result folder there: the final rename cannot replace a mount point (EBUSY/EXDEV), so it
// is refused before the sweep (result_folder.h), not after it.
#include <filesystem>
#include <string_view>

namespace dvpr {

// `path` (an existing folder) is the root of a mount: statx's STATX_ATTR_MOUNT_ROOT where the
// kernel reports it, else a device differing from its parent's or a line of
// /proc/self/mountinfo naming it.
bool IsMountPoint(const std::filesystem::path& path);

// Whether `mountinfo` (the text of /proc/self/mountinfo) has a mount whose mount point (field
// 5, octal escapes such as \040 decoded) is `canonical` (an absolute path without links).
bool MountInfoListsMountPoint(std::string_view mountinfo, const std::filesystem::path& canonical);

}  // namespace dvpr
