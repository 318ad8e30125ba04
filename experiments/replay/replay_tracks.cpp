#include "experiments/replay/replay_tracks.h"

#include <stdexcept>

#include "experiments/config/config.h"
#include "experiments/domain/data/loaders.h"
#include "experiments/domain/data/split.h"

namespace dvpr::replay {

ExperimentConfig LoadFolderConfig(const std::filesystem::path& config_yaml) {
  if (!std::filesystem::is_regular_file(config_yaml)) {
    throw std::runtime_error(config_yaml.string() + ": not found (a replay needs the result folder's config.yaml)");
  }
  // Only the poses are read (TracksOf, with their own error): descriptor and BoW files the run
  // read may have moved since.
  return LoadConfig(config_yaml, {}, ConfigFiles::kNamesOnly);
}

Tracks LoadTracks(const std::filesystem::path& config_yaml, int robots) {
  return TracksOf(LoadFolderConfig(config_yaml), config_yaml, robots);
}

Tracks TracksOf(const ExperimentConfig& config, const std::filesystem::path& config_yaml, int robots) {
  if (config.dataset.Planned()) {
    throw std::runtime_error(config_yaml.string() + ": dataset: the replay draws the paper's split of one drive; "
                             "a team of its own trajectories (dataset.trajectories or a scenario other than split) "
                             "cannot be replayed yet");
  }
  Trajectory trajectory;
  try {
    trajectory = LoadKittiPoses(config.dataset.poses);
    KeepFirstFrames(trajectory, config.dataset.frames.value_or(-1), config.dataset.poses);
  } catch (const std::exception& e) {
    throw std::runtime_error(config_yaml.string() + ": dataset.poses: " + e.what());
  }
  const int frames = static_cast<int>(trajectory.size());
  if (robots < 1 || robots > frames) {
    throw std::runtime_error(config_yaml.string() + ": " + std::to_string(robots) + " robots, but dataset.frames gives " +
                             std::to_string(frames) + " frames");
  }
  Tracks tracks{config.name, config.dataset.fps, {}};
  for (const FrameRange& range : SplitSequence(frames, robots).ranges) {
    RobotTrack& t = tracks.robots.emplace_back();
    t.first_frame = range.begin.value;
    for (int f = range.begin.value; f < range.end.value; ++f) {
      t.x.push_back(trajectory.positions(f, 0));
      t.z.push_back(trajectory.positions(f, 2));
    }
  }
  return tracks;
}

}  // namespace dvpr::replay
