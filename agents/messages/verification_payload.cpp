#include "agents/messages/verification_payload.h"

#include <bit>
#include <cstring>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define DVPR_PAYLOAD_AVX512 1
#else
#define DVPR_PAYLOAD_AVX512 0
#endif

#include "agents/messages/team_sync.h"
#include "sim/random_bits.h"

namespace dvpr {

static_assert(std::endian::native == std::endian::little, "the payload's bytes are defined little-endian");

namespace {

constexpr std::uint64_t kGolden = 0x9E3779B97F4A7C15ULL;  // SplitMix64's increment

// Words [0, words) of the stream from `state`, written little-endian, one at a time; returns the
// state after them.
std::uint64_t FillWords(std::uint64_t state, std::uint8_t* out, std::size_t words) {
  for (std::size_t w = 0; w < words; ++w) {  // a fixed-size copy is one store
    const std::uint64_t word = SplitMix64(state);
    std::memcpy(out + 8 * w, &word, 8);
  }
  return state;
}

#if DVPR_PAYLOAD_AVX512
// Whether this CPU has 64-bit vector multiplies (AVX-512 F and DQ), asked once. The build targets
// x86-64-v3, which has none; the scalar loop below is the reference.
bool HasWideMultiply() {
  static const bool has = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
  return has;
}

// z >> n in every lane. The zero-masked form with every lane selected: GCC 12's plain
// _mm512_srli_epi64 starts from an undefined vector and trips -Wmaybe-uninitialized.
__attribute__((target("avx512f"))) __m512i ShiftRight(__m512i z, unsigned n) {
  return _mm512_maskz_srli_epi64(0xFF, z, n);
}

__attribute__((target("avx512f,avx512dq"))) __m512i Mix(__m512i z) {
  z = _mm512_mullo_epi64(_mm512_xor_si512(z, ShiftRight(z, 30)), _mm512_set1_epi64(0xBF58476D1CE4E5B9LL));
  z = _mm512_mullo_epi64(_mm512_xor_si512(z, ShiftRight(z, 27)), _mm512_set1_epi64(0x94D049BB133111EBLL));
  return _mm512_xor_si512(z, ShiftRight(z, 31));
}

// SplitMix64's word w is a function of state + (w + 1) x increment alone, so 16 words are mixed
// side by side (two vectors of 8: independent multiplies in flight); the same bits as FillWords.
// Returns how many words it wrote (a multiple of 16) and advances `state` past them.
__attribute__((target("avx512f,avx512dq"))) std::size_t FillWordsWide(std::uint64_t& state, std::uint8_t* out,
                                                                      std::size_t words) {
  const auto step = [](std::uint64_t k) { return static_cast<long long>(k * kGolden); };
  __m512i a = _mm512_add_epi64(_mm512_set1_epi64(static_cast<long long>(state)),
                               _mm512_setr_epi64(step(1), step(2), step(3), step(4), step(5), step(6), step(7), step(8)));
  __m512i b = _mm512_add_epi64(a, _mm512_set1_epi64(step(8)));
  const __m512i sixteen = _mm512_set1_epi64(step(16));
  std::size_t w = 0;
  for (; w + 16 <= words; w += 16) {
    _mm512_storeu_si512(out + 8 * w, Mix(a));
    _mm512_storeu_si512(out + 8 * w + 64, Mix(b));
    a = _mm512_add_epi64(a, sixteen);
    b = _mm512_add_epi64(b, sixteen);
  }
  state += w * kGolden;
  return w;
}
#endif

}  // namespace

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
  const std::size_t words = out.size() / 8;
  std::size_t done = 0;
#if DVPR_PAYLOAD_AVX512
  if (HasWideMultiply()) done = FillWordsWide(state, out.data(), words);
#endif
  state = FillWords(state, out.data() + 8 * done, words - done);
  if (const std::size_t rest = out.size() - 8 * words; rest > 0) {
    const std::uint64_t word = SplitMix64(state);
    std::memcpy(out.data() + 8 * words, &word, rest);
  }
}

}  // namespace dvpr
