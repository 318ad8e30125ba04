#include "experiments/domain/data/split.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "experiments/domain/data/dataset.h"

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

SequenceSplit PlannedSplit(const std::vector<std::vector<SimTime>>& times) {
  if (times.empty()) throw std::invalid_argument("team plan: no robot");
  SequenceSplit split;
  std::int64_t total = 0;
  for (const auto& t : times) total += static_cast<std::int64_t>(t.size());
  if (total > std::numeric_limits<std::int32_t>::max()) {
    throw std::invalid_argument("team plan: " + std::to_string(total) + " frames, more than a frame id holds");
  }
  for (std::size_t r = 0; r < times.size(); ++r) {
    const std::vector<SimTime>& t = times[r];
    const std::string robot = "team plan: robot " + std::to_string(r);
    if (t.empty()) throw std::invalid_argument(robot + " takes no frame");
    if (t.front() < SimTime::Zero()) throw std::invalid_argument(robot + " starts before time 0");
    if (!std::is_sorted(t.begin(), t.end())) throw std::invalid_argument(robot + ": capture times not ascending");
    const FrameId begin(split.frames());
    split.ranges.push_back({begin, FrameId(begin.value + static_cast<std::int32_t>(t.size()))});
    split.owner.insert(split.owner.end(), t.size(), RobotId(static_cast<std::int32_t>(r)));
    split.capture.insert(split.capture.end(), t.begin(), t.end());
  }
  return split;
}

FrameStream SequenceSplit::StreamOf(int r, const DescriptorMatrix* descriptors, double fps) const {
  const FrameRange range = ranges.at(static_cast<std::size_t>(r));
  FrameStream stream{descriptors, range.begin, range.size(), fps};
  if (planned()) stream.times = std::span(capture).subspan(static_cast<std::size_t>(range.begin.value),
                                                           static_cast<std::size_t>(range.size()));
  return stream;
}

std::vector<FrameId> SequenceSplit::WindowStreams() const {
  std::vector<FrameId> starts;
  if (!planned()) return starts;
  for (std::size_t r = 1; r < ranges.size(); ++r) starts.push_back(ranges[r].begin);
  return starts;
}

SimTime SequenceSplit::LastCapture(double fps) const {
  SimTime last = SimTime::Zero();
  for (int r = 0; r < robots(); ++r) {  // a robot's times ascend: its last frame is its latest
    const FrameStream stream = StreamOf(r, nullptr, fps);
    if (stream.count > 0) last = std::max(last, stream.TimeOf(stream.count - 1));
  }
  return last;
}

std::vector<SimTime> SequenceSplit::CaptureTimes(double fps) const {
  if (planned()) return capture;
  std::vector<SimTime> times(owner.size());
  for (int r = 0; r < robots(); ++r) {
    const FrameStream stream = StreamOf(r, nullptr, fps);
    for (int k = 0; k < stream.count; ++k) times[static_cast<std::size_t>(stream.first.value + k)] = stream.TimeOf(k);
  }
  return times;
}

SequenceSplit SequenceSplit::First(int n) const {
  if (!planned()) throw std::invalid_argument("the paper's split has no first robots of a plan: split the sequence");
  if (n < 1 || n > robots()) {
    throw std::invalid_argument("a team of " + std::to_string(n) + " of a plan's " + std::to_string(robots()) +
                                " robots");
  }
  SequenceSplit first;
  first.ranges.assign(ranges.begin(), ranges.begin() + n);
  const auto rows = static_cast<std::size_t>(first.ranges.back().end.value);
  first.owner.assign(owner.begin(), owner.begin() + static_cast<std::ptrdiff_t>(rows));
  first.capture.assign(capture.begin(), capture.begin() + static_cast<std::ptrdiff_t>(rows));
  return first;
}

Dataset FirstRobots(const Dataset& team, int robots) {
  if (!team.plan) throw std::invalid_argument("FirstRobots: " + team.name + " is not a team plan");
  Dataset first;
  first.name = team.name;
  first.fps = team.fps;
  first.plan = team.plan->First(robots);
  const Eigen::Index rows = first.plan->frames();
  first.trajectory.positions = team.trajectory.positions.topRows(rows);
  first.trajectory.headings = team.trajectory.headings.topRows(rows);
  first.descriptors = team.descriptors.topRows(rows);
  return first;
}

SequenceSplit TeamSplit(const Dataset& data, int robots) {
  if (!data.plan) return SplitSequence(static_cast<int>(data.size()), robots);
  if (data.plan->robots() != robots || data.plan->frames() != data.size()) {
    throw std::invalid_argument("the team plan of " + data.name + " is for " + std::to_string(data.plan->robots()) +
                                " robots and " + std::to_string(data.plan->frames()) + " frames, not " +
                                std::to_string(robots) + " robots and " + std::to_string(data.size()));
  }
  return *data.plan;
}

}  // namespace dvpr
