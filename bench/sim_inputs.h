#pragma once
// What the simulation benchmarks run on: KITTI 00 with synthetic descriptors, that trajectory
// tiled to any length (copies 3 km apart, so each copy is new ground), the decentralized
// centroid table, point-to-point links, and the process's peak memory.
#include <sys/resource.h>

#include <memory>
#include <string>

#include "agents/algorithms/centroid_table.h"
#include "agents/algorithms/kmeans.h"
#include "experiments/domain/data/loaders.h"
#include "experiments/domain/data/synthetic.h"
#include "experiments/protocols/sim/simulation.h"

namespace dvpr::bench {

inline Trajectory Kitti00Poses() {
  return LoadKittiPoses(std::string(DVPR_SOURCE_DIR) + "/data/kitti/00_poses.txt");
}

inline Dataset Kitti00() {
  Dataset d;
  d.name = "kitti00";
  d.trajectory = Kitti00Poses();
  d.descriptors = SyntheticDeployment(d.trajectory, SyntheticParams{}, 1);
  return d;
}

// The first `frames` frames of KITTI 00 repeated, copy c shifted 3000 c metres along x.
inline Dataset Tiled(Eigen::Index frames) {
  const Trajectory base = Kitti00Poses();
  const Eigen::Index n = base.size();
  Dataset d;
  d.name = "tiled";
  d.trajectory.positions.resize(frames, 3);
  d.trajectory.headings.resize(frames, 3);
  for (Eigen::Index first = 0; first < frames; first += n) {
    const Eigen::Index rows = std::min(n, frames - first);
    d.trajectory.positions.middleRows(first, rows) = base.positions.topRows(rows);
    d.trajectory.positions.middleRows(first, rows).col(0).array() += 3000.0 * static_cast<double>(first / n);
    d.trajectory.headings.middleRows(first, rows) = base.headings.topRows(rows);
  }
  d.descriptors = SyntheticDeployment(d.trajectory, SyntheticParams{}, 1);
  return d;
}

// Where the routing centroids are learnt: kDiverse, many other environments (the paper's setting:
// the deployment, one environment, falls into a few clusters, a few robots store most frames);
// kDeployment, the deployment's own environment at other places (stores of similar size).
enum class Training { kDiverse, kDeployment };

inline std::shared_ptr<const CentroidTable> Table(int robots, int iterations, Training training = Training::kDiverse) {
  KMeansParams p;
  p.k = robots;
  p.seed = 3;
  p.max_iterations = iterations;
  const SyntheticTrainingParams samples{.samples = 20000};
  const DescriptorMatrix descriptors = training == Training::kDiverse
                                           ? SyntheticTrainingDiverse(SyntheticParams{}, samples, 2)
                                           : SyntheticTrainingDeploymentLike(SyntheticParams{}, samples, 1);
  return std::make_shared<CentroidTable>(CentroidTable::RoundRobin(KMeans(descriptors, p), robots));
}

inline SimRunParams PointToPoint(int robots) {
  SimRunParams p;
  p.scenario.robots = robots;
  p.scenario.network.model = LinkModelKind::kPointToPoint;
  p.scenario.network.bandwidth = DataRate::Mbps(10);
  p.scenario.network.latency = SimTime::Millis(2);
  return p;
}

// The same team on 10 Mbit/s radios of `range_m` on the ground plane, relayed along shortest paths
// (docs/network_model.md, "The radio").
inline SimRunParams Radio(int robots, double range_m) {
  SimRunParams p = PointToPoint(robots);
  p.scenario.network.model = LinkModelKind::kRadio;
  p.scenario.network.propagation = PropagationParams{.kind = PropagationKind::kRange, .range_m = range_m};
  p.scenario.network.routing = NextHopKind::kShortestPath;
  return p;
}

// The same team on one contending medium (docs/network_model.md, "Contending media"): ns-3's CSMA
// at 10 Mbit/s with a 2 ms channel delay, or 802.11a DCF at `wifi_mbps` with every robot in range.
inline SimRunParams Csma(int robots) {
  SimRunParams p = PointToPoint(robots);
  p.scenario.network.model = LinkModelKind::kCsma;
  return p;
}
inline SimRunParams Wifi(int robots, std::int64_t wifi_mbps) {
  SimRunParams p = PointToPoint(robots);
  p.scenario.network.model = LinkModelKind::kWifi;
  p.scenario.network.wifi.rate = DataRate::Mbps(wifi_mbps);
  return p;
}

inline double PeakRssMiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

}  // namespace dvpr::bench
