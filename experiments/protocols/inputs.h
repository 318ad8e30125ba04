#pragma once
// Loads what every run of an experiment reads (the deployment data, the training descriptors)
// from a validated config, once. Errors that need the data (dim larger than the descriptors,
// frame counts of poses and descriptors differing, NaN values) are ConfigErrors naming the key.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "experiments/config/config.h"
#include "experiments/domain/data/synthetic_bow.h"
#include "experiments/protocols/run.h"

namespace dvpr {

// Told what starts, "inputs: generating the deployment's descriptors": the progress's words for
// a step that may take seconds.
using PhaseNotice = std::function<void(const std::string& what)>;

// `origin` names the config file in error messages. `bow_progress` hears of each frame the
// synthetic BoW world makes (only when a bow_ strategy runs without dataset.bow); `phase`, if
// set, of making the deployment's and the training set's descriptors as each starts.
SharedInputs LoadSharedInputs(const ExperimentConfig& config, const std::string& origin,
                              const FrameProgress& bow_progress = {}, const PhaseNotice& phase = {});

// Throws a ConfigError naming dataset.dim when the deployment's descriptors are longer than a
// message can carry. LoadSharedInputs checks it for a config with a protocol that sends messages
// (the paper protocol sends none and takes any length); dvpr agent and launch call it.
void CheckDescriptorsFitTheWire(const Dataset& deployment, const std::string& origin);

// Writes each robot's rows of a team plan's descriptors to dir/robot<r>.npy (float32, one row per
// frame of the robot in its poses' order: what dataset.trajectories[r].descriptors reads back) and
// returns the files. Throws std::invalid_argument for a deployment without a plan.
std::vector<std::filesystem::path> WriteRobotDescriptors(const Dataset& team, const std::filesystem::path& dir);

}  // namespace dvpr
