#pragma once
// Small helpers shared by the test files: hand-made inputs and reading whole output files.
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <string>
#include <vector>

#include "agents/descriptors.h"
#include "agents/ids.h"

namespace dvpr::testing_support {

// A d = 1 descriptor matrix with one row per value.
inline DescriptorMatrix Column(std::initializer_list<float> values) {
  DescriptorMatrix m(static_cast<Eigen::Index>(values.size()), 1);
  Eigen::Index i = 0;
  for (float v : values) m(i++, 0) = v;
  return m;
}

inline std::vector<RobotId> Robots(std::initializer_list<int> ids) {
  std::vector<RobotId> out;
  for (int id : ids) out.push_back(RobotId(id));
  return out;
}

// The whole file, byte for byte ("" if it cannot be opened).
inline std::string Slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace dvpr::testing_support
