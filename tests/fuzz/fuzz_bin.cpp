// The raw float32 .bin descriptor loader. The input is 2 bytes bin_frame_width and 2 bytes dim
// (little-endian int16, so zero, negative and dim > width are tried too), then the file.
// Properties (experiments/domain/data/loaders.h):
// - a bad file or parameter throws std::runtime_error, nothing else;
// - a file that loads has size / (4 * width) frames, and value (i, j) is float i * width + j of
//   the file, bit for bit.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "experiments/domain/data/loaders.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

int Int16(const std::uint8_t* p) { return static_cast<std::int16_t>(p[0] | (p[1] << 8)); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  const int width = Int16(data), dim = Int16(data + 2);
  const std::uint8_t* file = data + 4;
  const std::size_t bytes = size - 4;
  const auto path = dvpr::fuzz::Scratch().Write("input.bin", {file, bytes});
  dvpr::DescriptorMatrix m;
  try {
    m = dvpr::LoadDescriptors(path, dim, width);
  } catch (const std::runtime_error&) {
    return 0;
  }
  const std::size_t frame_bytes = 4 * static_cast<std::size_t>(width);
  if (m.cols() != dim || static_cast<std::size_t>(m.rows()) * frame_bytes != bytes) {
    dvpr::fuzz::Violated("wrong shape for the file size");
  }
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    const std::uint8_t* frame = file + static_cast<std::size_t>(i) * frame_bytes;
    if (std::memcmp(&m(i, 0), frame, 4 * static_cast<std::size_t>(dim)) != 0) {
      dvpr::fuzz::Violated("values differ from the file's");
    }
  }
  return 0;
}
