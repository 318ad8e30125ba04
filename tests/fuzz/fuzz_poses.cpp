// The KITTI pose loader. The input is the pose file. Properties (experiments/domain/data/loaders.h):
// - a bad file throws std::runtime_error, nothing else;
// - a file that loads gives finite positions and finite unit headings.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "experiments/domain/data/loaders.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = dvpr::fuzz::Scratch().Write("poses.txt", {data, size});
  dvpr::Trajectory t;
  try {
    t = dvpr::LoadKittiPoses(path);
  } catch (const std::runtime_error&) {
    return 0;
  }
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    if (!t.positions.row(i).allFinite()) dvpr::fuzz::Violated("position not finite");
    const double norm = t.headings.row(i).norm();
    if (!t.headings.row(i).allFinite() || std::abs(norm - 1.0) > 1e-9) {
      dvpr::fuzz::Violated("heading of frame " + std::to_string(i) + " is not a unit vector (norm " +
                           std::to_string(norm) + ")");
    }
  }
  return 0;
}
