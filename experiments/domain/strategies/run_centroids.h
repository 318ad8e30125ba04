#pragma once
// The centroids of one run (robots, run) of a sweep: k-means on the training descriptors with
// k = robots x clusters_per_robot, or the run's file when the config names centroid files.
// Every protocol (paper, sim, lcm) and every strategy's table starts from these, so the runs of
// one (robots, run) compare on identical centroids.
//
// Seeding: RunSeed(config seed, robots, run) = MixSeed(MixSeed(seed, robots), run)
// (sim/random_bits.h). A run's seed depends only on its own key: adding robot counts or runs, or
// changing the thread count or the protocol, changes nothing else.
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "agents/algorithms/descriptors.h"
#include "agents/algorithms/kmeans.h"

namespace dvpr {

struct RunCentroidParams {
  std::uint64_t seed = 1;               // the config seed
  int clusters_per_robot = 1;           // k = n x this
  // k-means settings; k and seed are set per run (k = n x clusters_per_robot, RunSeed).
  KMeansParams kmeans;
  // Non-empty: skip k-means and read each run's centroids (.npy, k x d) from this path, with
  // "{robots}" and "{run}" replaced (ExpandCentroidPattern).
  std::string centroids_pattern;
  bool operator==(const RunCentroidParams&) const = default;
};

std::uint64_t RunSeed(std::uint64_t config_seed, int robots, int run);

// `pattern` with every "{robots}" and "{run}" replaced by the numbers.
std::filesystem::path ExpandCentroidPattern(const std::string& pattern, int robots, int run);

// The centroid file of a run of `robots` robots: robots x clusters_per_robot rows of `dim`
// finite values within +-kMaxDescriptorValue (experiments/domain/data/loaders.h; dim <= 0: any width).
// Throws naming the file: std::invalid_argument for the row count, the width or the first bad
// row, std::runtime_error for the npy reader's errors.
CentroidMatrix ReadCentroidFile(const std::filesystem::path& path, int robots, int clusters_per_robot,
                                Eigen::Index dim);

// ReadCentroidFile for every (robots, run) of a sweep, params.centroids_pattern expanded: run
// before a sweep starts, so a bad file stops it before anything is written.
void CheckCentroidFiles(const RunCentroidParams& params, const std::vector<int>& robots, int runs, Eigen::Index dim);

// The centroids of run (robots, run). `seed_used` (if given) gets the k-means seed, 0 when the
// centroids were read from a file; a file must then be as wide as `training` (which holds no
// rows but the descriptors' width when centroid files replace k-means; width 0: unchecked).
CentroidMatrix RunCentroids(const DescriptorMatrix& training, const RunCentroidParams& params, int robots, int run,
                            std::uint64_t* seed_used = nullptr);

// RunCentroids computed once per (robots, run, clusters per robot) for a whole sweep: the
// strategies of one run that cluster the training set alike (decentralized, multi_probe_2, ...;
// lpt_c10 and bounded_c10_0.25) and the protocols that run the same (robots, run) (paper, and sim
// once per network variant) share one k-means. RunCentroids is deterministic, so sharing changes
// no result, only time: the default experiment clustered each (robots, run) three times before.
// Thread-safe (the sweep's runs call it from several threads; a second caller of a key being
// computed waits for it, and a k-means that throws is tried again by the next caller). Entries
// are kept for the sweep: one k x d float matrix per (robots, run), e.g. 190 matrices of at most
// 20 x 128 floats (2 MB) for the default experiment. For one config's RunCentroidParams (seed,
// k-means settings, centroid files; clusters per robot is part of the key): Get with other
// settings throws std::logic_error.
class RunCentroidCache {
 public:
  const CentroidMatrix& Get(const DescriptorMatrix& training, const RunCentroidParams& params, int robots, int run);

 private:
  struct Entry {
    std::once_flag once;
    CentroidMatrix centroids;
  };
  std::mutex mutex_;
  std::optional<RunCentroidParams> params_;  // the settings of the first Get, clusters per robot aside
  std::map<std::tuple<int, int, int>, std::shared_ptr<Entry>> computed_;
};

}  // namespace dvpr
