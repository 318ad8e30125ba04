#include "agents/verification_payload.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "agents/team_sync.h"
#include "sim/random_bits.h"

namespace dvpr {

static_assert(std::endian::native == std::endian::little, "the payload's bytes are defined little-endian");

std::vector<std::uint8_t> VerificationPayload(FrameId frame, std::span<const float> descriptor, std::size_t size) {
  Fnv1a hash;
  const std::int32_t id = frame.value;
  hash.AddValue(id);
  hash.Add(descriptor.data(), descriptor.size_bytes());
  std::uint64_t state = static_cast<std::uint64_t>(hash.value());
  std::vector<std::uint8_t> bytes(size);
  for (std::size_t i = 0; i < size; i += 8) {
    const std::uint64_t word = SplitMix64(state);
    std::memcpy(bytes.data() + i, &word, std::min<std::size_t>(8, size - i));
  }
  return bytes;
}

}  // namespace dvpr
