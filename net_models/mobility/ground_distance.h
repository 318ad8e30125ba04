#pragma once
// Distance on the ground plane, what a radio's range is measured in (docs/network_model.md, "The
// radio"). KITTI's frame has y pointing down, so the ground plane is x and z; the height of a
// robot (a few metres over a drive) does not change who hears whom.
#include <cmath>

#include "net_models/core/position.h"

namespace dvpr {

inline double GroundDistance(const Position& a, const Position& b) { return std::hypot(a.x - b.x, a.z - b.z); }

}  // namespace dvpr
