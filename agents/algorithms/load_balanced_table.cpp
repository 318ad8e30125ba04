#include "agents/algorithms/load_balanced_table.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>


namespace dvpr {

void LoadBalanceParams::Validate() const {
  if (std::isnan(epsilon) || std::isinf(epsilon)) {
    throw std::invalid_argument("load_balance.epsilon must be finite (< 0 for LPT), got " + std::to_string(epsilon));
  }
}

std::vector<double> ExpectedLoads(const CentroidMatrix& centroids, const DescriptorMatrix& sample, double prior) {
  if (sample.rows() > 0 && sample.cols() != centroids.cols()) {
    throw std::invalid_argument("ExpectedLoads: sample has " + std::to_string(sample.cols()) +
                                " columns, centroids " + std::to_string(centroids.cols()));
  }
  // The table is only a lookup here; its owners do not matter.
  const CentroidTable lookup = CentroidTable::RoundRobin(centroids, 1);
  std::vector<double> loads(static_cast<std::size_t>(centroids.rows()), prior);
  for (Eigen::Index i = 0; i < sample.rows(); ++i) {
    loads[static_cast<std::size_t>(lookup.NearestCentroidOf(sample.row(i).data()))] += 1.0;
  }
  return loads;
}

namespace {

// Clusters by decreasing load, ties by index (stable).
std::vector<int> ByDecreasingLoad(const std::vector<double>& loads) {
  std::vector<int> order(loads.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return loads[static_cast<std::size_t>(a)] > loads[static_cast<std::size_t>(b)];
  });
  return order;
}

int LeastLoaded(const std::vector<double>& robot_load) {
  return static_cast<int>(std::min_element(robot_load.begin(), robot_load.end()) - robot_load.begin());
}

// Bounded loads: the round-robin robot c mod n if the cluster fits under the capacity, else the
// next robot in ring order that fits, else the least loaded.
int BoundedChoice(int cluster, double load, const std::vector<double>& robot_load, double capacity) {
  const int n = static_cast<int>(robot_load.size());
  for (int step = 0; step < n; ++step) {
    const int r = (cluster + step) % n;
    if (robot_load[static_cast<std::size_t>(r)] + load <= capacity) return r;
  }
  return LeastLoaded(robot_load);
}

}  // namespace

std::vector<RobotId> AssignByLoad(const std::vector<double>& loads, int num_robots, const LoadBalanceParams& params) {
  params.Validate();
  if (num_robots < 1) throw std::invalid_argument("AssignByLoad: num_robots must be >= 1");
  for (double l : loads) {
    if (!(l >= 0.0) || std::isinf(l)) throw std::invalid_argument("AssignByLoad: loads must be finite and >= 0");
  }
  const double total = std::accumulate(loads.begin(), loads.end(), 0.0);
  // A small slack keeps an exactly-at-capacity packing from failing on rounding.
  const double capacity = (1.0 + params.epsilon) * total / num_robots * (1.0 + 1e-12);
  std::vector<double> robot_load(static_cast<std::size_t>(num_robots), 0.0);
  std::vector<RobotId> owners(loads.size(), RobotId(0));
  for (int c : ByDecreasingLoad(loads)) {
    const double load = loads[static_cast<std::size_t>(c)];
    const int r = params.epsilon < 0 ? LeastLoaded(robot_load) : BoundedChoice(c, load, robot_load, capacity);
    robot_load[static_cast<std::size_t>(r)] += load;
    owners[static_cast<std::size_t>(c)] = RobotId(r);
  }
  return owners;
}

CentroidTable LoadBalancedTable(CentroidMatrix centroids, const DescriptorMatrix& sample, int num_robots,
                                const LoadBalanceParams& params) {
  // A prior of one descriptor per cluster: clusters the sample never hit are spread too, not
  // all piled on robot 0.
  std::vector<RobotId> owners = AssignByLoad(ExpectedLoads(centroids, sample, 1.0), num_robots, params);
  return CentroidTable(std::move(centroids), std::move(owners), num_robots);
}

}  // namespace dvpr
