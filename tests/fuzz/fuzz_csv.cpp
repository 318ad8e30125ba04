// The .csv descriptor loader. The input is the file. Properties (experiments/domain/data/loaders.h):
// - a bad file throws std::runtime_error, nothing else;
// - loaded with dim 1 and with the full width (the first line's fields), both give the same
//   first column when both load.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "experiments/domain/data/loaders.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

std::optional<dvpr::DescriptorMatrix> Load(const std::filesystem::path& path, int dim) {
  try {
    return dvpr::LoadDescriptors(path, dim);
  } catch (const std::runtime_error&) {
    return std::nullopt;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = dvpr::fuzz::Scratch().Write("input.csv", {data, size});
  const std::uint8_t* line_end = std::find(data, data + size, '\n');
  const int width = 1 + static_cast<int>(std::count(data, line_end, ','));
  const auto first = Load(path, 1);
  const auto all = Load(path, width);
  if (all && all->cols() != width) dvpr::fuzz::Violated("full-width load has the wrong width");
  if (first && all) {
    if (first->rows() != all->rows()) dvpr::fuzz::Violated("dim 1 and full width differ in rows");
    for (Eigen::Index i = 0; i < all->rows(); ++i) {
      if (std::memcmp(&(*first)(i, 0), &(*all)(i, 0), sizeof(float)) != 0) {
        dvpr::fuzz::Violated("dim 1 and full width differ in column 0");
      }
    }
  }
  return 0;
}
