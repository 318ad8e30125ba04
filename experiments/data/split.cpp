#include "experiments/data/split.h"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace dvpr {

SequenceSplit SplitSequence(int frames, int robots) {
  if (robots < 1) {
    throw std::invalid_argument("split: robots must be at least 1, got " + std::to_string(robots));
  }
  if (frames < robots) {
    throw std::invalid_argument("split: " + std::to_string(frames) + " frames cannot be split among " +
                                std::to_string(robots) + " robots (each needs at least one frame)");
  }
  // 64-bit products: r * N overflows int for long sequences and large teams.
  const auto boundary = [&](int r) {
    return static_cast<std::int32_t>(static_cast<std::int64_t>(r) * frames / robots);
  };
  SequenceSplit split;
  split.ranges.reserve(static_cast<std::size_t>(robots));
  split.owner.reserve(static_cast<std::size_t>(frames));
  for (int r = 0; r < robots; ++r) {
    const FrameRange range{FrameId(boundary(r)), FrameId(boundary(r + 1))};
    split.ranges.push_back(range);
    split.owner.insert(split.owner.end(), static_cast<std::size_t>(range.size()), RobotId(r));
  }
  return split;
}

}  // namespace dvpr
