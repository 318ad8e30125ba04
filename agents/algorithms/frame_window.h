#pragma once
// The suppression window (docs/design.md section 2): a query never matches a frame within
// `frames` of it in the sequence, the robot's own frames of the seconds just before and after.
// When the team's frames are several streams laid end to end (a planned team: every robot its own
// trajectory, dataset.trajectories or a scenario other than split), the window stays inside the
// query's own stream: the last frame of one robot and the first of the next are neighbours in the
// sequence, not in time. Without streams the whole sequence is one (the paper's split).
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "agents/algorithms/ids.h"

namespace dvpr {

// Frames lo..hi of the sequence, both included; empty when hi < lo.
struct FrameInterval {
  std::int64_t lo = 0;
  std::int64_t hi = -1;
  bool Contains(std::int64_t frame) const { return lo <= frame && frame <= hi; }
};

class FrameWindow {
 public:
  // One stream: |query - j| <= frames is suppressed. Implicit: a count of frames is the window of
  // the paper's split.
  FrameWindow(int frames) : frames_(frames) {}  // NOLINT(google-explicit-constructor)
  // Streams beginning at `stream_starts` (ascending; the first stream begins at frame 0 and is
  // not listed): the window is cut at the query's stream's ends.
  FrameWindow(int frames, std::vector<FrameId> stream_starts)
      : frames_(frames), starts_(std::move(stream_starts)) {}

  int frames() const { return frames_; }
  const std::vector<FrameId>& stream_starts() const { return starts_; }

  // The frames a query of frame `query` may not match.
  FrameInterval Around(std::int64_t query) const {
    FrameInterval w{query - frames_, query + frames_};
    if (starts_.empty()) return w;
    const auto next = std::upper_bound(starts_.begin(), starts_.end(), query,
                                       [](std::int64_t q, FrameId s) { return q < s.value; });
    if (next != starts_.end()) w.hi = std::min<std::int64_t>(w.hi, next->value - 1);
    if (next != starts_.begin()) w.lo = std::max<std::int64_t>(w.lo, std::prev(next)->value);
    return w;
  }
  bool Suppresses(std::int64_t query, std::int64_t frame) const { return Around(query).Contains(frame); }

 private:
  int frames_ = 0;
  std::vector<FrameId> starts_;
};

}  // namespace dvpr
