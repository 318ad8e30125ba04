#pragma once
// A small deployment for the paper protocol's tests (tests/protocols/paper, tests/sweep): every
// 10th pose of KITTI 00 (455 frames, revisits after ~1500 m) with random-but-smooth descriptors,
// sin(a_j . p / 20 m + 3 b_j) plus 10% noise, so revisits are found but not all of them.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "experiments/domain/data/dataset.h"
#include "sim/random_bits.h"

namespace dvpr::testing_support {

// rows x cols values uniform in [-1, 1) from Xoshiro256(seed), row by row.
inline DescriptorMatrix UniformMatrix(int rows, int cols, std::uint64_t seed) {
  Xoshiro256 rng(seed);
  DescriptorMatrix x(rows, cols);
  for (int i = 0; i < x.size(); ++i) x.data()[i] = static_cast<float>(rng.Uniform() * 2 - 1);
  return x;
}

// The deployment, with `dim`-dimensional descriptors; headings are zero (the paper protocol does
// not use them). When poses_out is given, the poses used are written there (KITTI format).
inline Dataset KittiEveryTenth(int dim, const std::filesystem::path& poses_out = {}) {
  std::ifstream in(DVPR_SOURCE_DIR "/data/kitti/00_poses.txt");
  std::ofstream poses;
  if (!poses_out.empty()) poses.open(poses_out);
  std::vector<double> xyz;
  int line_no = 0;
  for (std::string line; std::getline(in, line); ++line_no) {
    if (line_no % 10 != 0) continue;
    if (poses.is_open()) poses << line << "\n";
    std::istringstream row(line);
    double v[12];
    for (double& e : v) row >> e;
    xyz.insert(xyz.end(), {v[3], v[7], v[11]});
  }
  Dataset data;
  const auto n = static_cast<Eigen::Index>(xyz.size() / 3);
  data.trajectory.positions = Eigen::Map<const Positions>(xyz.data(), n, 3);
  data.trajectory.headings = Positions::Zero(n, 3);
  const DescriptorMatrix a = UniformMatrix(dim, 3, 3);
  const DescriptorMatrix b = UniformMatrix(1, dim, 4);
  const DescriptorMatrix noise = UniformMatrix(static_cast<int>(n), dim, 5);
  data.descriptors.resize(n, dim);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int j = 0; j < dim; ++j) {
      const double phase = a.row(j).cast<double>().dot(data.trajectory.positions.row(i)) / 20.0;
      data.descriptors(i, j) = static_cast<float>(std::sin(phase + 3.0 * b(0, j)) + 0.1 * noise(i, j));
    }
  }
  return data;
}

}  // namespace dvpr::testing_support
