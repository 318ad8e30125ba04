#include "experiments/domain/strategies/run_centroids.h"

#include <memory>
#include <mutex>
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
  std::shared_ptr<Entry> entry;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    RunCentroidParams settings = params;
    settings.clusters_per_robot = 0;  // part of the key
    if (!params_) params_ = settings;
    if (!(*params_ == settings)) {
      throw std::logic_error("RunCentroidCache: one cache serves one config's k-means settings and centroid files");
    }
    std::shared_ptr<Entry>& slot = computed_[std::make_tuple(robots, run, params.clusters_per_robot)];
    if (!slot) slot = std::make_shared<Entry>();
    entry = slot;
  }
  // Outside the lock: other keys are computed meanwhile; callers of this key wait here.
  std::call_once(entry->once, [&] { entry->centroids = RunCentroids(training, params, robots, run); });
  return entry->centroids;
}

}  // namespace dvpr
