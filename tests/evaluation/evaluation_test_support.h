#pragma once
// What the evaluation tests share.
#include <cstddef>
#include <vector>

#include "experiments/domain/data/dataset.h"

namespace dvpr::testing_support {

// Frames on the x axis at the given coordinates.
inline Positions OnLine(const std::vector<double>& x) {
  Positions p = Positions::Zero(static_cast<Eigen::Index>(x.size()), 3);
  for (std::size_t i = 0; i < x.size(); ++i) p(static_cast<Eigen::Index>(i), 0) = x[i];
  return p;
}

}  // namespace dvpr::testing_support
