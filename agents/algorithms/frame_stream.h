#pragma once
// The frames a robot takes (docs/design.md section 3): rows [first, first + count) of the full
// sequence, the k-th at k / fps from the start of the run, or, for a planned team (its robots
// driving their own trajectories from their own start times), at times[k] on the team's clock.
#include <cmath>
#include <span>

#include "agents/algorithms/descriptors.h"
#include "agents/algorithms/ids.h"
#include "sim/sim_time.h"

namespace dvpr {

struct FrameStream {
  const DescriptorMatrix* descriptors = nullptr;
  FrameId first{0};
  int count = 0;
  double fps = 10.0;
  std::span<const SimTime> times = {};  // empty, or count ascending capture times (not owned)
  SimTime TimeOf(int k) const {
    if (!times.empty()) return times[static_cast<std::size_t>(k)];
    return SimTime::Nanos(std::llround(static_cast<double>(k) * 1e9 / fps));
  }
};

}  // namespace dvpr
