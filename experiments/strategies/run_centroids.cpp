#include "experiments/strategies/run_centroids.h"

#include <stdexcept>
#include <string>

#include "experiments/data/npy.h"
#include "sim/random_bits.h"

namespace dvpr {

std::uint64_t RunSeed(std::uint64_t config_seed, int robots, int run) {
  return MixSeed(MixSeed(config_seed, static_cast<std::uint64_t>(robots)), static_cast<std::uint64_t>(run));
}

std::filesystem::path ExpandCentroidPattern(const std::string& pattern, int robots, int run) {
  std::string path = pattern;
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"{robots}", std::to_string(robots)},
                                 std::pair<std::string, std::string>{"{run}", std::to_string(run)}}) {
    for (std::size_t at = path.find(from); at != std::string::npos; at = path.find(from, at + to.size())) {
      path.replace(at, from.size(), to);
    }
  }
  return path;
}

CentroidMatrix RunCentroids(const DescriptorMatrix& training, const RunCentroidParams& params, int robots, int run,
                            std::uint64_t* seed_used) {
  const int k = robots * params.clusters_per_robot;
  if (!params.centroids_pattern.empty()) {
    const auto path = ExpandCentroidPattern(params.centroids_pattern, robots, run);
    CentroidMatrix c = ReadNpyMatrix(path);
    if (c.rows() != k) {
      throw std::invalid_argument(path.string() + ": " + std::to_string(c.rows()) + " centroids, expected " +
                                  std::to_string(k) + " (" + std::to_string(robots) + " robots x " +
                                  std::to_string(params.clusters_per_robot) + " per robot)");
    }
    if (seed_used != nullptr) *seed_used = 0;
    return c;
  }
  KMeansParams kmeans = params.kmeans;
  kmeans.k = k;
  kmeans.seed = RunSeed(params.seed, robots, run);
  if (seed_used != nullptr) *seed_used = kmeans.seed;
  return KMeans(training, kmeans);
}

const CentroidMatrix& RunCentroidCache::Get(const DescriptorMatrix& training, const RunCentroidParams& params,
                                            int robots, int run) {
  const auto key = std::make_tuple(robots, run, params.clusters_per_robot);
  auto it = computed_.find(key);
  if (it == computed_.end()) it = computed_.emplace(key, RunCentroids(training, params, robots, run)).first;
  return it->second;
}

}  // namespace dvpr
