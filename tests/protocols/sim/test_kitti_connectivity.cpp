// Connectivity of the KITTI 00 split (issue 33): the simulation's positions (RobotTracks over
// SplitSequence, a TrackMobility) under the range model, summarised by ConnectivityOver, against
// a second computation written here from the pose file alone: its own reading of the poses, its
// own split arithmetic and interpolation, Floyd-Warshall instead of breadth-first searches.
// Sampled every 50 ms (half the frame period, so every other sample lies between two frames).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "experiments/domain/data/loaders.h"
#include "experiments/domain/data/split.h"
#include "experiments/domain/scenario/scenario.h"
#include "net_models/propagation/connectivity.h"
#include "net_models/propagation/range_propagation.h"

namespace dvpr {
namespace {

const std::string kPoses = std::string(DVPR_SOURCE_DIR) + "/data/kitti/00_poses.txt";
constexpr std::int64_t kFramePeriodNs = 100'000'000;  // 10 fps
constexpr std::int64_t kSampleNs = 50'000'000;

struct Summary {
  double share_connected = 0.0;  // of the samples
  double pair_share = 0.0;       // mean over samples of pairs in range / (n (n - 1) / 2)
  double mean_hops = 0.0;        // mean over samples with a connected pair of their mean hops
  std::vector<int> pairs;        // per sample
  std::vector<int> components;   // per sample
};

// --- The second computation: nothing from dvpr but the file's name. ---
struct Xz {
  double x, z;
};

std::vector<Xz> ReadGroundTrack(const std::string& path) {
  std::ifstream in(path);
  std::vector<Xz> track;
  double m[12];
  while (in >> m[0]) {
    for (int i = 1; i < 12; ++i) in >> m[i];
    track.push_back(Xz{m[3], m[11]});  // [R|t] row-major: t = (m[3], m[7], m[11]); y (m[7]) is height
  }
  return track;
}

Summary SecondComputation(const std::vector<Xz>& all, int n, double range_m) {
  const auto frames = static_cast<long long>(all.size());
  std::vector<std::vector<Xz>> robot(static_cast<std::size_t>(n));
  std::size_t longest = 0;
  for (int r = 0; r < n; ++r) {
    for (long long f = r * frames / n; f < (r + 1) * frames / n; ++f) robot[static_cast<std::size_t>(r)].push_back(all[static_cast<std::size_t>(f)]);
    longest = std::max(longest, robot[static_cast<std::size_t>(r)].size());
  }
  const std::int64_t end_ns = static_cast<std::int64_t>(longest - 1) * kFramePeriodNs;
  Summary s;
  int samples = 0, connected = 0, with_pairs = 0;
  const int inf = 1 << 20;
  for (std::int64_t t = 0; t <= end_ns; t += kSampleNs) {
    std::vector<Xz> at(static_cast<std::size_t>(n));
    for (int r = 0; r < n; ++r) {
      const auto& tr = robot[static_cast<std::size_t>(r)];
      const double k = static_cast<double>(t) / static_cast<double>(kFramePeriodNs);
      const auto i = static_cast<std::size_t>(std::floor(k));
      if (i + 1 >= tr.size()) {
        at[static_cast<std::size_t>(r)] = tr.back();
      } else {
        const double w = k - static_cast<double>(i);
        at[static_cast<std::size_t>(r)] = Xz{tr[i].x + w * (tr[i + 1].x - tr[i].x), tr[i].z + w * (tr[i + 1].z - tr[i].z)};
      }
    }
    std::vector<std::vector<int>> d(static_cast<std::size_t>(n), std::vector<int>(static_cast<std::size_t>(n), inf));
    int pairs = 0;
    for (int a = 0; a < n; ++a) {
      d[a][a] = 0;
      for (int b = 0; b < n; ++b) {
        if (a == b) continue;
        const double dx = at[a].x - at[b].x, dz = at[a].z - at[b].z;
        if (std::sqrt(dx * dx + dz * dz) <= range_m) {
          d[a][b] = 1;
          if (a < b) ++pairs;
        }
      }
    }
    for (int k = 0; k < n; ++k)
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) d[a][b] = std::min(d[a][b], d[a][k] + d[k][b]);
    long long hop_sum = 0, reach = 0;
    std::vector<bool> seen(static_cast<std::size_t>(n), false);
    int components = 0;
    for (int a = 0; a < n; ++a) {
      if (!seen[a]) {
        ++components;
        for (int b = 0; b < n; ++b) seen[b] = seen[b] || d[a][b] < inf;
      }
      for (int b = 0; b < n; ++b) {
        if (a != b && d[a][b] < inf) hop_sum += d[a][b], ++reach;
      }
    }
    ++samples;
    connected += components == 1 ? 1 : 0;
    s.pair_share += pairs / (n * (n - 1) / 2.0);
    if (reach > 0) s.mean_hops += static_cast<double>(hop_sum) / static_cast<double>(reach), ++with_pairs;
    s.pairs.push_back(pairs);
    s.components.push_back(components);
  }
  s.share_connected = static_cast<double>(connected) / samples;
  s.pair_share /= samples;
  s.mean_hops = with_pairs > 0 ? s.mean_hops / with_pairs : 0.0;
  return s;
}

// --- The simulation's own positions and ConnectivityOver. ---
Summary Simulated(const Dataset& data, int n, double range_m) {
  const SequenceSplit split = SplitSequence(static_cast<int>(data.size()), n);
  const TrackMobility tracks = RobotTracks(data, split);
  int longest = 0;
  for (const FrameRange& r : split.ranges) longest = std::max(longest, r.size());
  RangePropagation range(tracks, range_m);
  const auto over = ConnectivityOver(range, n, SimTime::Nanos(kSampleNs), SimTime::Nanos((longest - 1) * kFramePeriodNs));
  Summary s;
  int connected = 0, with_pairs = 0;
  for (const ConnectivitySnapshot& c : over) {
    connected += c.connected() ? 1 : 0;
    s.pair_share += c.pairs_in_range / (n * (n - 1) / 2.0);
    if (c.largest_component > 1) s.mean_hops += c.mean_hops, ++with_pairs;
    s.pairs.push_back(c.pairs_in_range);
    s.components.push_back(c.components);
  }
  s.share_connected = static_cast<double>(connected) / static_cast<double>(over.size());
  s.pair_share /= static_cast<double>(over.size());
  s.mean_hops = with_pairs > 0 ? s.mean_hops / with_pairs : 0.0;
  return s;
}

Dataset KittiPosesOnly() {
  Dataset d;
  d.name = "kitti00";
  d.trajectory = LoadKittiPoses(kPoses);
  d.descriptors = DescriptorMatrix::Zero(d.trajectory.size(), 1);  // RobotTracks needs the frame count only
  return d;
}

TEST(KittiConnectivity, SplitMatchesASecondComputation) {
  const Dataset data = KittiPosesOnly();
  const std::vector<Xz> ground = ReadGroundTrack(kPoses);
  ASSERT_EQ(static_cast<Eigen::Index>(ground.size()), data.size());
  ASSERT_EQ(ground.size(), 4541u);  // KITTI 00
  for (const int n : {5, 10, 20}) {
    for (const double range_m : {100.0, 200.0, 300.0}) {
      SCOPED_TRACE("n = " + std::to_string(n) + ", range " + std::to_string(range_m));
      const Summary sim = Simulated(data, n, range_m);
      const Summary ref = SecondComputation(ground, n, range_m);
      ASSERT_EQ(sim.pairs.size(), ref.pairs.size());
      EXPECT_EQ(sim.pairs, ref.pairs);
      EXPECT_EQ(sim.components, ref.components);
      EXPECT_DOUBLE_EQ(sim.share_connected, ref.share_connected);
      EXPECT_NEAR(sim.pair_share, ref.pair_share, 1e-12);
      EXPECT_NEAR(sim.mean_hops, ref.mean_hops, 1e-9);
      std::cout << "n=" << n << " range=" << range_m << "m connected=" << sim.share_connected
                << " pairs_in_range=" << sim.pair_share << " mean_hops=" << sim.mean_hops << "\n";
    }
  }
}

}  // namespace
}  // namespace dvpr
