#pragma once
// Where a node is: metres in the frame its trajectory is given in (KITTI's: x right, y down,
// z forward). A plain value; net_models has no linear-algebra library.
#include <cmath>

namespace dvpr {

struct Position {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  bool operator==(const Position&) const = default;
};

inline double Distance(const Position& a, const Position& b) {
  return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z);
}

}  // namespace dvpr
