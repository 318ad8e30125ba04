// Empty .npy matrices of extreme shape. The header alone says (2147483647, 0): a valid matrix
// without values, read without visiting its rows. (Reading took seconds before; a unit test
// cannot assert that without timing, so tests/fuzz/corpus/npy/slow-zero_columns_2147483647_rows.npy
// replays it under fuzz.sh's 10 s timeout. Found by fuzz_npy.)
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "experiments/domain/data/loaders.h"
#include "experiments/domain/data/npy.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

// A version 1.0 file with this header dict and no data, as numpy writes it (padded to 64 bytes).
fs::path HeaderOnly(const std::string& name, const std::string& shape) {
  std::string dict = "{'descr': '<f4', 'fortran_order': False, 'shape': " + shape + ", }";
  dict.append(64 - (10 + dict.size() + 1) % 64, ' ');
  dict.push_back('\n');
  const fs::path dir = fs::path(DVPR_TEST_TMP) / "npy_empty_shapes";
  fs::create_directories(dir);
  std::ofstream out(dir / name, std::ios::binary);
  out << "\x93NUMPY\x01" << '\0' << static_cast<char>(dict.size() & 0xff)
      << static_cast<char>(dict.size() >> 8) << dict;
  return dir / name;
}

TEST(NpyEmptyShapesTest, MaximalRowsOfZeroColumns) {
  const DescriptorMatrix m = ReadNpyMatrix(HeaderOnly("rows.npy", "(2147483647, 0)"));
  EXPECT_EQ(m.rows(), 2147483647);
  EXPECT_EQ(m.cols(), 0);
  // As descriptors: no column to keep.
  EXPECT_THROW(LoadDescriptors(HeaderOnly("rows_d.npy", "(2147483647, 0)"), 1), std::runtime_error);
}

TEST(NpyEmptyShapesTest, ZeroRowsOfMaximalColumns) {
  const DescriptorMatrix m = ReadNpyMatrix(HeaderOnly("cols.npy", "(0, 2147483647)"));
  EXPECT_EQ(m.rows(), 0);
  EXPECT_EQ(m.cols(), 2147483647);
}

}  // namespace
}  // namespace dvpr
