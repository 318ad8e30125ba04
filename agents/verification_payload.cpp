#include "agents/verification_payload.h"

#include <bit>
#include <cstring>

#include "agents/team_sync.h"
#include "sim/random_bits.h"

namespace dvpr {

static_assert(std::endian::native == std::endian::little, "the payload's bytes are defined little-endian");

std::vector<std::uint8_t> VerificationPayload(FrameId frame, std::span<const float> descriptor, std::size_t size) {
  std::vector<std::uint8_t> bytes(size);
  FillVerificationPayload(frame, descriptor, bytes);
  return bytes;
}

void FillVerificationPayload(FrameId frame, std::span<const float> descriptor, std::span<std::uint8_t> out) {
  Fnv1a hash;
  const std::int32_t id = frame.value;
  hash.AddValue(id);
  hash.Add(descriptor.data(), descriptor.size_bytes());
  std::uint64_t state = static_cast<std::uint64_t>(hash.value());
  const std::size_t size = out.size();
  std::size_t i = 0;
  for (; i + 8 <= size; i += 8) {  // whole words: a fixed-size copy is one store
    const std::uint64_t word = SplitMix64(state);
    std::memcpy(out.data() + i, &word, 8);
  }
  if (i < size) {
    const std::uint64_t word = SplitMix64(state);
    std::memcpy(out.data() + i, &word, size - i);
  }
}

}  // namespace dvpr
