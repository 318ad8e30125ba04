// The .npy reader, as a descriptor file (LoadDescriptors) and as a centroid file (ReadNpyMatrix).
// The input is the file. Properties (experiments/domain/data/npy.h, loaders.h):
// - a bad file throws std::runtime_error, nothing else;
// - a matrix that reads is written (WriteNpy) and read back bit for bit;
// - the descriptor loader keeps exactly the first `dim` columns of what the reader reads.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "experiments/domain/data/loaders.h"
#include "experiments/domain/data/npy.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using dvpr::DescriptorMatrix;

bool SameBits(const DescriptorMatrix& a, const DescriptorMatrix& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         (a.size() == 0 || std::memcmp(a.data(), b.data(), sizeof(float) * static_cast<std::size_t>(a.size())) == 0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& scratch = dvpr::fuzz::Scratch();
  const auto path = scratch.Write("input.npy", {data, size});
  DescriptorMatrix m;
  try {
    m = dvpr::ReadNpyMatrix(path);
  } catch (const std::runtime_error&) {
    return 0;
  }
  const auto copy = scratch.path() / "copy.npy";
  dvpr::WriteNpy(copy, m);
  if (!SameBits(dvpr::ReadNpyMatrix(copy), m)) dvpr::fuzz::Violated("WriteNpy does not read back");
  // Two or fewer columns (a wide dim is checked against the width, not read).
  const int dim = static_cast<int>(std::min<Eigen::Index>(m.cols(), 2));
  try {
    const DescriptorMatrix d = dvpr::LoadDescriptors(path, dim);
    if (!SameBits(d, m.leftCols(dim))) dvpr::fuzz::Violated("LoadDescriptors differs from ReadNpyMatrix");
  } catch (const std::runtime_error&) {
  }
  return 0;
}
