#pragma once
// Where each robot is over time, recomputed from a result folder's config.yaml
// (the fully resolved config: absolute pose path, dataset.frames, fps) exactly
// as the simulation placed the robots: the sequence split into n contiguous
// parts (SplitSequence), robot r's k-th frame taken at k / fps.
#include <filesystem>
#include <string>
#include <vector>

namespace dvpr::replay {

struct RobotTrack {
  int first_frame = 0;    // index of its first frame in the full sequence
  std::vector<double> x;  // KITTI x (right) of each of its frames, metres
  std::vector<double> z;  // KITTI z (forward): the map's second axis
};

struct Tracks {
  std::string name;  // the config's name
  double fps = 10;
  std::vector<RobotTrack> robots;
};

// Throws std::runtime_error naming config.yaml (and the key) when it or its pose file cannot be read.
Tracks LoadTracks(const std::filesystem::path& config_yaml, int robots);

}  // namespace dvpr::replay
