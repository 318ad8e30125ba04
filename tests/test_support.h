#pragma once
// Small helpers shared by the test files of every module: reading whole output files. Nothing
// here includes a project header, so a test of any layer can use it (descriptor_support.h has
// the helpers that need agents/).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace dvpr::testing_support {

// The whole file, byte for byte ("" if it cannot be opened).
inline std::string Slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every entry below `root` (hidden ones too), relative path -> bytes; folders map to "<dir>".
// Two equal snapshots mean the folder is byte-identical, with nothing added or removed.
inline std::map<std::string, std::string> SnapshotFolder(const std::filesystem::path& root) {
  std::map<std::string, std::string> entries;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    const std::string rel = std::filesystem::relative(e.path(), root).string();
    entries[rel] = e.is_directory() ? std::string("<dir>") : Slurp(e.path());
  }
  return entries;
}

// The names in `dir` (not below it), sorted.
inline std::vector<std::string> Names(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace dvpr::testing_support
