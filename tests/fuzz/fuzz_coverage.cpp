// Block coverage for libFuzzer from GCC's instrumentation (tests/fuzz/fuzz_flags.cmake): every
// basic block compiled with -fsanitize-coverage=trace-pc calls __sanitizer_cov_trace_pc, which
// counts the block's return address, hashed, in a byte of a table libFuzzer reads as "extra
// counters" (the section __libfuzzer_extra_counters): a new counter, or a count in a new
// power-of-two bucket, is new coverage and keeps the input. Two blocks may share a byte (64 K
// bytes for the few thousand blocks of the covered libraries): a collision hides one of them
// from the guidance, never from the sanitizers.
#include <cstddef>
#include <cstdint>

namespace {
constexpr std::size_t kCounterBits = 16;
constexpr std::size_t kCounters = std::size_t{1} << kCounterBits;
}  // namespace

extern "C" {

// The section's name is libFuzzer's; a program without libFuzzer (the tests) only counts.
__attribute__((section("__libfuzzer_extra_counters"), used)) std::uint8_t dvpr_fuzz_pc_counters[kCounters];

__attribute__((no_sanitize_address, no_sanitize_undefined)) void __sanitizer_cov_trace_pc() {
  const auto pc = reinterpret_cast<std::uintptr_t>(__builtin_return_address(0));
  const std::uintptr_t index = (pc ^ (pc >> kCounterBits)) & (kCounters - 1);
  ++dvpr_fuzz_pc_counters[index];
}

// GCC's trace-cmp also reports float and double comparisons, which libFuzzer has no hook for.
void __sanitizer_cov_trace_cmpf(float, float) {}
void __sanitizer_cov_trace_cmpd(double, double) {}

}  // extern "C"
