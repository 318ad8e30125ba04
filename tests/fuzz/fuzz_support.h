#pragma once
// What the fuzz targets share. The data loaders read files, not buffers, so each input is
// written to one file per process (in a fresh temporary folder, removed at exit) and the loader
// reads it; tmpfs or page cache keeps this cheap. A broken property calls Violated(), which
// aborts: libFuzzer then saves the input and scripts/fuzz.sh fails.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <system_error>

namespace dvpr::fuzz {

[[noreturn]] inline void Violated(const std::string& what) {
  std::fprintf(stderr, "dvpr fuzz: property violated: %s\n", what.c_str());
  std::abort();
}

// A folder of this process's own under the system's temporary folder.
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "dvpr_fuzz_XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) Violated("cannot create a temporary folder");
    dir_ = pattern;
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  // Writes `bytes` as the file `name` in the folder and returns its path.
  std::filesystem::path Write(const std::string& name, std::span<const std::uint8_t> bytes) const {
    const std::filesystem::path path = dir_ / name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) Violated("cannot write " + path.string());
    return path;
  }
  const std::filesystem::path& path() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

// One scratch folder for the whole process (a fuzz target runs inputs one after another).
inline const ScratchDir& Scratch() {
  static const ScratchDir dir;
  return dir;
}

}  // namespace dvpr::fuzz
