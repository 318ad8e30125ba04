#include "agents/recluster/recluster.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "agents/algorithms/load_balanced_table.h"
#include "sim/random_bits.h"

namespace dvpr {

void ReclusterParams::Validate() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument("re-clustering: " + what); };
  if (clusters_per_robot < 1) fail("clusters_per_robot must be >= 1, got " + std::to_string(clusters_per_robot));
  if (period < 1) fail("period must be >= 1 frame, got " + std::to_string(period));
  if (sample_stride < 1) fail("sample_stride must be >= 1, got " + std::to_string(sample_stride));
}

int ReclusterEpochOf(int step, const ReclusterParams& params) { return step / params.period; }

bool InReclusterSample(int step, int epoch, const ReclusterParams& params) {
  return step >= 0 && step < epoch * params.period && step % params.sample_stride == 0;
}

int ReclusterEpochs(int longest_stream, const ReclusterParams& params) {
  return longest_stream > 0 ? (longest_stream - 1) / params.period : 0;
}

CentroidTable ReclusterTable(const DescriptorMatrix& sample, const std::vector<RobotId>& live, int num_robots,
                             const ReclusterParams& params, int epoch) {
  params.Validate();
  if (sample.rows() == 0) throw std::invalid_argument("ReclusterTable: empty sample");
  if (live.empty()) throw std::invalid_argument("ReclusterTable: no robot to own the clusters");
  KMeansParams kmeans = params.kmeans;
  kmeans.k = static_cast<int>(std::min<Eigen::Index>(
      static_cast<Eigen::Index>(params.clusters_per_robot) * num_robots, sample.rows()));
  kmeans.seed = MixSeed(params.seed, static_cast<std::uint64_t>(epoch));
  CentroidMatrix centroids = KMeans(sample, kmeans);
  // LPT over the live robots only (slot s is live[s]): a robot that sent no sample may be gone.
  const std::vector<RobotId> slots =
      AssignByLoad(ExpectedLoads(centroids, sample, 1.0), static_cast<int>(live.size()), LoadBalanceParams{});
  std::vector<RobotId> owners;
  owners.reserve(slots.size());
  for (RobotId s : slots) owners.push_back(live[static_cast<std::size_t>(s.value)]);
  return CentroidTable(std::move(centroids), std::move(owners), num_robots);
}

}  // namespace dvpr
