#pragma once
// Where each robot is over time, recomputed from a result folder's config.yaml
// (the fully resolved config: absolute pose path, dataset.frames, fps) exactly
// as the simulation placed the robots: the sequence split into n contiguous
// parts (SplitSequence), robot r's k-th frame taken at k / fps.
#include <filesystem>
#include <string>
#include <vector>

#include "experiments/config/config.h"

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

// A result folder's config.yaml, its files resolved by name only (ConfigFiles::kNamesOnly).
// Throws std::runtime_error naming it when it is missing, ConfigError when it does not read.
ExperimentConfig LoadFolderConfig(const std::filesystem::path& config_yaml);

// The tracks of a team of `robots` in `config` (read from `config_yaml`, which errors name).
// Throws std::runtime_error naming config.yaml (and the key) when its pose file cannot be read.
Tracks TracksOf(const ExperimentConfig& config, const std::filesystem::path& config_yaml, int robots);

// LoadFolderConfig, then TracksOf.
Tracks LoadTracks(const std::filesystem::path& config_yaml, int robots);

}  // namespace dvpr::replay
