#pragma once
// Splitting the deployment sequence among the robots (docs/design.md §2): robot r drives the
// contiguous frames [floor(r N / n), floor((r + 1) N / n)), so lengths differ by at most one.
#include <vector>

#include "agents/algorithms/ids.h"

namespace dvpr {

// Frames [begin, end) of the full sequence.
struct FrameRange {
  FrameId begin;
  FrameId end;
  int size() const { return end.value - begin.value; }
  bool Contains(FrameId f) const { return begin <= f && f < end; }
  bool operator==(const FrameRange&) const = default;
};

struct SequenceSplit {
  std::vector<FrameRange> ranges;  // ranges[r]: robot r's frames
  std::vector<RobotId> owner;      // owner[f]: the robot that took frame f
  int robots() const { return static_cast<int>(ranges.size()); }
  int frames() const { return static_cast<int>(owner.size()); }
  RobotId OwnerOf(FrameId f) const { return owner.at(static_cast<std::size_t>(f.value)); }
};

// Throws std::invalid_argument unless 1 <= robots <= frames (every robot gets a frame).
SequenceSplit SplitSequence(int frames, int robots);

}  // namespace dvpr
