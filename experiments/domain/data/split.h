#pragma once
// Splitting the deployment sequence among the robots (docs/design.md §2): robot r drives the
// contiguous frames [floor(r N / n), floor((r + 1) N / n)), so lengths differ by at most one.
// A planned team (docs/design.md §3, "Team plans") lays its robots' own trajectories end to end
// instead: robot r drives its range and takes each frame at its own capture time.
#include <vector>

#include "agents/algorithms/descriptors.h"
#include "agents/algorithms/frame_stream.h"
#include "agents/algorithms/frame_window.h"
#include "agents/algorithms/ids.h"
#include "sim/sim_time.h"

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
  // A planned team: capture[f], when frame f is taken on the team's clock (ascending within each
  // robot's range). Empty for the paper's split: robot r's k-th frame at k / fps.
  std::vector<SimTime> capture;
  int robots() const { return static_cast<int>(ranges.size()); }
  int frames() const { return static_cast<int>(owner.size()); }
  RobotId OwnerOf(FrameId f) const { return owner.at(static_cast<std::size_t>(f.value)); }
  bool planned() const { return !capture.empty(); }
  // Robot r's frames as its agent takes them (descriptors may be null where only times matter).
  FrameStream StreamOf(int r, const DescriptorMatrix* descriptors, double fps) const;
  // FrameWindow's stream starts: every robot's first frame but robot 0's for a planned team (a
  // robot never matches its own last seconds, and nothing else is suppressed); none for the split.
  std::vector<FrameId> WindowStreams() const;
  FrameWindow Window(int frames) const { return FrameWindow(frames, WindowStreams()); }
  // Per frame of the sequence, when its robot takes it.
  std::vector<SimTime> CaptureTimes(double fps) const;
  // When the team takes its last frame (0 for no frame): no robot sends a query after it.
  SimTime LastCapture(double fps) const;
  // A planned team of the first `robots` robots of this one (a team plan swept over team sizes,
  // docs/config.md "Team plans"): their ranges, owners and capture times, a prefix of the rows.
  // Throws std::invalid_argument for the split or a count outside [1, robots()].
  SequenceSplit First(int robots) const;
};

// Throws std::invalid_argument unless 1 <= robots <= frames (every robot gets a frame).
SequenceSplit SplitSequence(int frames, int robots);

// A planned team: robot r takes times[r].size() frames, the robots' rows laid end to end in robot
// order, the k-th at times[r][k]. Throws std::invalid_argument when a robot has no frame or its
// times are negative or not ascending.
SequenceSplit PlannedSplit(const std::vector<std::vector<SimTime>>& times);

}  // namespace dvpr
