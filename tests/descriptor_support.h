#pragma once
// Hand-made inputs for the tests of agents/ and the modules above it.
#include <initializer_list>
#include <vector>

#include "agents/algorithms/descriptors.h"
#include "agents/algorithms/ids.h"

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

}  // namespace dvpr::testing_support
