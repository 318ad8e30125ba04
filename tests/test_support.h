#pragma once
// Small helpers shared by the test files of every module: reading whole output files. Nothing
// here includes a project header, so a test of any layer can use it (descriptor_support.h has
// the helpers that need agents/).
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
