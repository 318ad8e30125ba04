#include "experiments/protocols/inputs.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "agents/algorithms/ids.h"
#include "experiments/domain/data/bow_file.h"
#include "experiments/domain/data/loaders.h"
#include "experiments/domain/data/npy.h"
#include "experiments/domain/data/synthetic_bow.h"
#include "experiments/domain/data/team_plan.h"
#include "experiments/results/protocol_traits.h"

namespace dvpr {

namespace {

// Runs `load`, turning any loader error into a ConfigError naming the config key.
template <typename Fn>
auto WithKey(const std::string& origin, const std::string& key, Fn&& load) {
  try {
    return load();
  } catch (const ConfigError&) {
    throw;
  } catch (const std::exception& e) {
    throw ConfigError(origin + ": " + key + ": " + e.what());
  }
}

// A team of dataset.trajectories with dataset.source files: each robot's own descriptor file, one
// row per pose of its trajectory, laid end to end in robot order as its poses are (team_plan.h).
// A file whose rows differ from its robot's poses, or whose width differs from robot 0's (another
// kind of descriptor), is an error naming the robot's entry and the file.
DescriptorMatrix LoadTeamDescriptors(const ExperimentConfig& c, const Dataset& team, const std::string& origin) {
  const DatasetConfig& d = c.dataset;
  std::vector<DescriptorFile> files;
  Eigen::Index rows = 0;
  for (std::size_t r = 0; r < d.trajectories.size(); ++r) {
    const TrajectorySource& source = d.trajectories[r];
    const std::string key = "dataset.trajectories[" + std::to_string(r) + "].descriptors";
    if (!source.descriptors) throw ConfigError(origin + ": " + key + ": required when dataset.source is files");
    DescriptorFile& file = files.emplace_back(
        WithKey(origin, key, [&] { return LoadDescriptorFile(*source.descriptors, d.dim, d.bin_width); }));
    const FrameRange range = team.plan->ranges[r];
    if (file.rows.rows() != range.size()) {
      throw ConfigError(origin + ": " + key + ": " + source.descriptors->string() + " has " +
                        std::to_string(file.rows.rows()) + " descriptors (rows), but the robot's poses " +
                        source.poses.string() + " have " + std::to_string(range.size()) +
                        ": one row per pose, in the poses' order");
    }
    if (file.width != files.front().width) {
      throw ConfigError(origin + ": " + key + ": " + source.descriptors->string() + " has " +
                        std::to_string(file.width) + " values per frame, dataset.trajectories[0].descriptors (" +
                        d.trajectories.front().descriptors->string() + ") " + std::to_string(files.front().width) +
                        ": every robot's descriptors must be of one kind and width");
    }
    rows += file.rows.rows();
  }
  DescriptorMatrix all(rows, d.dim);
  Eigen::Index at = 0;
  for (const DescriptorFile& file : files) {
    all.middleRows(at, file.rows.rows()) = file.rows;
    at += file.rows.rows();
  }
  return all;
}

// The pose file and the descriptor file are loaded apart, so an error names the key of the file
// at fault; dataset.frames is checked against the pose file whatever the source (a synthetic
// deployment longer than its poses would silently run fewer frames than config.yaml says).
// A planned team's poses (experiments/domain/data/team_plan.h), its descriptors rendered along every
// robot's own poses at their times on the common clock.
Dataset LoadTeamPlan(const ExperimentConfig& c, const Trajectory& poses, const std::string& origin) {
  const DatasetConfig& d = c.dataset;
  Dataset team;
  if (!d.trajectories.empty()) {
    std::vector<TimedTrajectory> trajectories;
    for (std::size_t r = 0; r < d.trajectories.size(); ++r) {
      trajectories.push_back(WithKey(origin, "dataset.trajectories[" + std::to_string(r) + "]",
                                     [&] { return LoadRobotTrajectory(d.trajectories[r]); }));
    }
    team = WithKey(origin, "dataset.trajectories", [&] { return TeamOfTrajectories(d.trajectories, trajectories, d.fps); });
  } else {
    team = WithKey(origin, "dataset.scenario", [&] {
      // The largest team of the sweep: a smaller one is its first robots (SharedInputs::smaller_teams),
      // as a plan for that many would drive (robot r's drive depends on r alone, random_routes' on
      // the draws of robots 0 to r).
      const int robots = *std::max_element(c.sweep.robots.begin(), c.sweep.robots.end());
      return DriveTeam(poses, PlanDrives(d.scenario, static_cast<int>(poses.size()), robots, d.fps), d.fps);
    });
  }
  team.name = c.name;
  if (d.source == DatasetSource::kFiles) {
    team.descriptors = LoadTeamDescriptors(c, team, origin);
    return team;
  }
  team.descriptors = WithKey(origin, "dataset.synthetic", [&] {
    return SyntheticDeployment(team.trajectory, TimesInFrames(*team.plan, d.fps), d.synthetic, c.seed);
  });
  return team;
}

Dataset LoadDeployment(const ExperimentConfig& c, const std::string& origin) {
  const DatasetConfig& d = c.dataset;
  if (!d.trajectories.empty()) return LoadTeamPlan(c, Trajectory{}, origin);
  Dataset ds;
  ds.name = c.name.empty() && d.descriptors ? d.descriptors->stem().string() : c.name;
  ds.fps = d.fps;
  ds.trajectory = WithKey(origin, "dataset.poses", [&] { return LoadKittiPoses(d.poses); });
  if (d.source == DatasetSource::kFiles) {
    ds.descriptors = WithKey(origin, "dataset.descriptors",
                             [&] { return LoadDescriptors(*d.descriptors, d.dim, d.bin_width); });
    WithKey(origin, "dataset.descriptors",
            [&] { CheckSameFrameCount(ds.trajectory, d.poses, ds.descriptors, *d.descriptors); });
  }
  WithKey(origin, "dataset.frames", [&] { KeepFirstFrames(ds.trajectory, d.frames.value_or(-1), d.poses); });
  if (d.source == DatasetSource::kFiles) {
    ds.descriptors.conservativeResize(ds.trajectory.size(), Eigen::NoChange);
    return ds;
  }
  if (d.Planned()) return LoadTeamPlan(c, ds.trajectory, origin);
  ds.descriptors = WithKey(origin, "dataset.synthetic",
                           [&] { return SyntheticDeployment(ds.trajectory, d.synthetic, c.seed); });
  return ds;
}

DescriptorMatrix LoadTraining(const ExperimentConfig& c, const Dataset& deployment,
                              const std::string& origin) {
  const TrainingConfig& t = c.training;
  // k-means is skipped; no rows, but the width the centroid files must have.
  if (!t.run_centroids.centroids_pattern.empty()) return DescriptorMatrix(0, deployment.dim());
  const SyntheticParams& model = c.dataset.synthetic;
  switch (t.source) {
    case TrainingSource::kSyntheticDiverse:
      return WithKey(origin, "training.synthetic",
                     [&] { return SyntheticTrainingDiverse(model, t.synthetic, c.seed); });
    case TrainingSource::kSyntheticDeploymentLike:
      return WithKey(origin, "training.synthetic",
                     [&] { return SyntheticTrainingDeploymentLike(model, t.synthetic, c.seed); });
    case TrainingSource::kFiles:
      return WithKey(origin, "training.descriptors", [&] {
        return LoadDescriptors(*t.descriptors, c.dataset.dim, c.dataset.bin_width);
      });
    case TrainingSource::kDeployment:
      return deployment.descriptors;
  }
  return {};
}

// The BoW vectors, only when a bow_ strategy runs (the default experiment's outputs and time do
// not change): the user's file, cut to dataset.frames like the poses, or the synthetic model.
BowData LoadBow(const ExperimentConfig& c, const std::string& origin, const Dataset& ds, const FrameProgress& progress) {
  const bool wanted = std::any_of(c.sweep.strategies.begin(), c.sweep.strategies.end(),
                                  [](const StrategySpec& s) { return s.bag_of_words(); });
  if (!wanted) return {};
  const DatasetConfig& d = c.dataset;
  if (!d.bow) {
    return WithKey(origin, "dataset.synthetic_bow", [&] {
      return SyntheticBow(ds.trajectory, d.synthetic, d.synthetic_bow.value_or(SyntheticBowParams{}), c.seed, progress);
    });
  }
  BowData bow = WithKey(origin, "dataset.bow", [&] { return LoadBowFile(*d.bow); });
  const auto lines = static_cast<Eigen::Index>(bow.frames.size());
  if (lines < ds.size() || (!d.frames && lines != ds.size())) {
    throw ConfigError(origin + ": dataset.bow: " + d.bow->string() + " has " + std::to_string(lines) +
                      " frames, the dataset " + std::to_string(ds.size()));
  }
  bow.frames.resize(static_cast<std::size_t>(ds.size()));
  return bow;
}

// "generating" a synthetic set, "reading" one from files.
std::string Making(bool files) { return files ? "reading" : "generating"; }

}  // namespace

SharedInputs LoadSharedInputs(const ExperimentConfig& config, const std::string& origin,
                              const FrameProgress& bow_progress, const PhaseNotice& phase) {
  const auto tell = [&phase](const std::string& what) {
    if (phase) phase("inputs: " + what);
  };
  SharedInputs in;
  in.config = &config;
  const DatasetConfig& d = config.dataset;
  const bool read = d.source == DatasetSource::kFiles;  // as LoadDeployment
  tell(Making(read) + " the deployment's descriptors" +
       (read && !d.trajectories.empty() ? " (every robot's own file)"
                                        : !read && d.Planned() ? " (every robot's frames of its plan)" : ""));
  in.deployment = LoadDeployment(config, origin);
  if (const auto& plan = in.deployment.plan) {
    for (const int n : config.sweep.robots) {
      if (n < plan->robots()) in.smaller_teams.emplace(n, FirstRobots(in.deployment, n));
    }
  }
  in.bow = LoadBow(config, origin, in.deployment, bow_progress);
  const int largest = *std::max_element(config.sweep.robots.begin(), config.sweep.robots.end());
  if (in.deployment.size() < largest) {
    throw ConfigError(origin + ": robots: " + std::to_string(largest) + " robots but only " +
                      std::to_string(in.deployment.size()) + " frames (dataset.frames)");
  }
  if (AnyProtocol(config.sweep.protocols, &ProtocolTraits::sends_messages)) CheckDescriptorsFitTheWire(in.deployment, origin);
  const TrainingConfig& t = config.training;
  if (t.run_centroids.centroids_pattern.empty() && t.source != TrainingSource::kDeployment) {
    tell(Making(t.source == TrainingSource::kFiles) + " the training descriptors");
  }
  in.training = LoadTraining(config, in.deployment, origin);
  const RunCentroidParams& centroids = config.training.run_centroids;
  const auto k = static_cast<Eigen::Index>(largest) * centroids.clusters_per_robot;
  if (centroids.centroids_pattern.empty() && in.training.rows() < k) {
    throw ConfigError(origin + ": training: " + std::to_string(in.training.rows()) +
                      " training descriptors, k-means needs at least " + std::to_string(k));
  }
  return in;
}

std::vector<std::filesystem::path> WriteRobotDescriptors(const Dataset& team, const std::filesystem::path& dir) {
  if (!team.plan) throw std::invalid_argument("the config's dataset is no team plan (dataset.trajectories or dataset.scenario)");
  std::vector<std::filesystem::path> files;
  for (int r = 0; r < team.plan->robots(); ++r) {
    const FrameRange range = team.plan->ranges[static_cast<std::size_t>(r)];
    files.push_back(dir / ("robot" + std::to_string(r) + ".npy"));
    WriteNpy(files.back(), team.descriptors.middleRows(range.begin.value, range.size()));
  }
  return files;
}

void CheckDescriptorsFitTheWire(const Dataset& deployment, const std::string& origin) {
  if (deployment.dim() > kMaxWireInt16) {
    throw ConfigError(origin + ": dataset.dim: " + std::to_string(deployment.dim()) +
                      " values per descriptor, but a query_t carries at most " + std::to_string(kMaxWireInt16) +
                      " (its dim is an int16 on the wire); only the paper protocol, which sends no messages, "
                      "takes longer descriptors");
  }
}

}  // namespace dvpr
