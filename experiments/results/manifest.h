#pragma once
// The manifest of a result folder (README "Result folders"): `dvpr_manifest.txt` lists every
// entry dvpr wrote in the folder, so a later `dvpr run` can tell its own files from a user's and
// replaces the folder only while it holds nothing else. A text file, one entry a line after a
// header line: the path relative to the folder with '/' between components, a folder with a
// trailing '/', sorted by byte value. It holds names only (no sizes, times or owners), so the
// same config and seed give the same manifest, byte for byte.
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace dvpr {

class OutputDir;

inline constexpr const char* kManifestName = "dvpr_manifest.txt";
inline constexpr const char* kManifestHeader =
    "# dvpr result folder: the entries dvpr wrote here; dvpr run replaces this folder only while it holds nothing else";

// Every entry below the open folder `dir_fd` in manifest form (folders with a trailing '/'),
// sorted, never through a symbolic link (a link is listed by its own name, as a file). The
// manifest itself and temporaries of dvpr's writers (IsDvprTemporary) are left out.
std::vector<std::string> ListEntries(int dir_fd);

// The manifest's text for `entries` (as ListEntries gives them).
std::string ManifestText(const std::vector<std::string>& entries);

// The entries of the manifest in `dir_fd`; nullopt when there is none or it does not start with
// kManifestHeader.
std::optional<std::set<std::string>> ReadManifest(int dir_fd);

// The first entry below `dir_fd` (depth first, sorted by name) that is not dvpr's: not in the
// manifest, a symbolic link, or a file where the manifest has a folder (or the other way). A
// foreign folder is named with its trailing '/' and not entered. nullopt when there is none.
std::optional<std::string> FirstForeignEntry(int dir_fd, const std::set<std::string>& manifest);

// A name dvpr's writers give their temporaries (safe_output.h: ".dvpr-<16 hex>.tmp" and
// ".dvpr-<16 hex>.scratch"): left by a writer that was killed, dvpr's own.
bool IsDvprTemporary(const std::string& name);

// Adds `entries` to the manifest of `dir`, when it has one (a folder without one stays without:
// it is not dvpr's to claim). For the files `dvpr plot` and `dvpr replay` add to a result folder.
void AddToManifest(const OutputDir& dir, const std::vector<std::string>& entries);

}  // namespace dvpr
