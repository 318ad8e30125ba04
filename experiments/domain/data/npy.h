#pragma once
// NumPy .npy files for descriptor and centroid matrices (the format numpy.save writes).
#include <filesystem>
#include <string>

#include "agents/algorithms/descriptors.h"

namespace dvpr {

// Reads a 2-D array of little-endian float32 ('<f4') or float64 ('<f8') in C or Fortran order,
// format version 1.0, 2.0 or 3.0. float64 values are narrowed to float. Throws
// std::runtime_error naming the file and what was expected (bad magic or header, not 2-D,
// unsupported dtype, truncated data).
DescriptorMatrix ReadNpyMatrix(const std::filesystem::path& path);

// The bytes of `m` as a .npy file: float32, C order, format version 1.0, byte-identical to
// numpy.save (numpy >= 1.24 header padding). dvpr's outputs put them in place through
// experiments/results/safe_output.h.
std::string NpyBytes(const DescriptorMatrix& m);

// Writes NpyBytes(m) to `path` (tests and tools that make input files). Atomic: the bytes go to a
// temporary file in the same directory, which is then renamed over `path`.
void WriteNpy(const std::filesystem::path& path, const DescriptorMatrix& m);

}  // namespace dvpr
