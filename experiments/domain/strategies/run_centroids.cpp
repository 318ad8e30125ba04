#include "experiments/domain/strategies/run_centroids.h"

#include <stdexcept>
#include <string>

#include "experiments/domain/data/loaders.h"
#include "experiments/domain/data/npy.h"
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

CentroidMatrix ReadCentroidFile(const std::filesystem::path& path, int robots, int clusters_per_robot,
                                Eigen::Index dim) {
  const auto fail = [&](const std::string& what) { throw std::invalid_argument(path.string() + ": " + what); };
  CentroidMatrix c = ReadNpyMatrix(path);
  const Eigen::Index k = static_cast<Eigen::Index>(robots) * clusters_per_robot;
  if (c.rows() != k) {
    fail(std::to_string(c.rows()) + " centroids, expected " + std::to_string(k) + " (" + std::to_string(robots) +
         " robots x " + std::to_string(clusters_per_robot) + " per robot)");
  }
  if (dim > 0 && c.cols() != dim) {
    fail(std::to_string(c.cols()) + " values per centroid, expected " + std::to_string(dim) +
         " (the descriptors' dataset.dim)");
  }
  for (Eigen::Index i = 0; i < c.rows(); ++i) {
    if (!c.row(i).allFinite()) fail("centroid " + std::to_string(i) + " (0-based row) holds NaN or Inf");
    if (c.cols() > 0 && c.row(i).cwiseAbs().maxCoeff() > kMaxDescriptorValue) {
      fail("centroid " + std::to_string(i) + " (0-based row) holds a value outside [-1e9, 1e9]");
    }
  }
  return c;
}

void CheckCentroidFiles(const RunCentroidParams& params, const std::vector<int>& robots, int runs, Eigen::Index dim) {
  for (const int n : robots) {
    for (int run = 0; run < runs; ++run) {
      ReadCentroidFile(ExpandCentroidPattern(params.centroids_pattern, n, run), n, params.clusters_per_robot, dim);
    }
  }
}

CentroidMatrix RunCentroids(const DescriptorMatrix& training, const RunCentroidParams& params, int robots, int run,
                            std::uint64_t* seed_used) {
  const int k = robots * params.clusters_per_robot;
  if (!params.centroids_pattern.empty()) {
    CentroidMatrix c = ReadCentroidFile(ExpandCentroidPattern(params.centroids_pattern, robots, run), robots,
                                        params.clusters_per_robot, training.cols());
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
