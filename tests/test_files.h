#pragma once
// Reading output files in tests; no project library needed, so every test binary can use it.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace dvpr::testing_support {

// The whole file, byte for byte ("" if it cannot be opened).
inline std::string Slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace dvpr::testing_support
