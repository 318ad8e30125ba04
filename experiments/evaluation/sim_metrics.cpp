#include "experiments/evaluation/sim_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <unordered_map>

namespace dvpr {

LatencyStats ComputeLatency(const std::vector<QueryRecord>& queries) {
  LatencyStats stats;
  std::vector<std::int64_t> ns;
  ns.reserve(queries.size());
  for (const auto& q : queries) {
    if (q.latency) {
      ns.push_back(q.latency->ns());
    } else {
      ++stats.incomplete;
    }
  }
  stats.complete = static_cast<std::int64_t>(ns.size());
  if (ns.empty()) return stats;
  std::sort(ns.begin(), ns.end());
  // Sum in integer nanoseconds: exact, so the mean does not depend on order.
  const auto total = std::accumulate(ns.begin(), ns.end(), std::int64_t{0});
  stats.mean_ms = static_cast<double>(total) / static_cast<double>(ns.size()) * 1e-6;
  const auto rank = static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(ns.size())));
  stats.p99_ms = static_cast<double>(ns[std::max<std::size_t>(rank, 1) - 1]) * 1e-6;
  return stats;
}

namespace {
double SquaredDistance(const Positions& p, Eigen::Index i, Eigen::Index j) {
  return (p.row(i) - p.row(j)).squaredNorm();
}

// Frames bucketed in cubes of side `radius`: every frame within the radius of
// a point lies in the 27 cubes around it, so a relevance test costs the
// frames nearby instead of the whole sequence (100 000-frame runs).
class PositionGrid {
 public:
  PositionGrid(const Positions& p, double radius) : p_(p), cell_(radius > 0 ? radius : 1.0) {
    for (Eigen::Index j = 0; j < p.rows(); ++j) cells_[Key(Cell(j, 0), Cell(j, 1), Cell(j, 2))].push_back(j);
  }
  template <typename Fn>  // fn(j) -> true to stop
  bool AnyNear(Eigen::Index i, Fn&& fn) const {
    const std::int64_t cx = Cell(i, 0), cy = Cell(i, 1), cz = Cell(i, 2);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(Key(cx + dx, cy + dy, cz + dz));
          if (it == cells_.end()) continue;
          for (Eigen::Index j : it->second)
            if (fn(j)) return true;
        }
    return false;
  }

 private:
  std::int64_t Cell(Eigen::Index i, int axis) const {
    return static_cast<std::int64_t>(std::floor(p_(i, axis) / cell_));
  }
  static std::uint64_t Key(std::int64_t x, std::int64_t y, std::int64_t z) {
    const auto h = [](std::int64_t v) { return static_cast<std::uint64_t>(v) * 0x9E3779B97F4A7C15ull; };
    return h(x) ^ (h(y) >> 21) ^ (h(z) << 17) ^ static_cast<std::uint64_t>(z);
  }
  const Positions& p_;
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<Eigen::Index>> cells_;
};
}  // namespace

OnlineTruth ComputeOnlineTruth(const std::vector<QueryRecord>& queries, const Positions& positions,
                               const std::vector<SimTime>& capture_time, double radius_m, int window) {
  const double r2 = radius_m * radius_m;
  const PositionGrid grid(positions, radius_m);
  OnlineTruth truth;
  truth.relevant.resize(queries.size());
  truth.correct.resize(queries.size());
  for (std::size_t q = 0; q < queries.size(); ++q) {
    const Eigen::Index i = queries[q].frame.value;
    const SimTime t = capture_time[static_cast<std::size_t>(i)];
    if (queries[q].best) {
      truth.correct[q] = SquaredDistance(positions, i, queries[q].best->frame.value) < r2;
    }
    truth.relevant[q] = truth.correct[q] || grid.AnyNear(i, [&](Eigen::Index j) {
      return std::abs(i - j) > window && capture_time[static_cast<std::size_t>(j)] <= t &&
             SquaredDistance(positions, i, j) < r2;
    });
  }
  return truth;
}

}  // namespace dvpr
