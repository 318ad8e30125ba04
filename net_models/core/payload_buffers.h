#pragma once
// Byte buffers for message payloads, recycled. The network gives each payload's buffer back
// here once its last copy is delivered or dropped, and a transport that publishes into the
// network encodes its next message into one of them (Transport::UseBuffers), so a run in its
// steady state allocates no payload memory. Without it every reply costs an allocation, and a
// verification request's 25 kB a fresh block of heap that is zeroed and faulted in each time.
//
// Buffers are kept by size class (capacity in [2^k, 2^(k+1))), at most kPerClass a class or as
// many as 2^k-byte buffers fit in kClassBytes if that is more (small classes), none above
// kMaxKept bytes and at most kMaxKeptBytes in all, so what the pool holds stays bounded whatever
// the run sends. The counts are generous: a 1000-robot team has some 160 verification requests
// of 25 kB in flight at once, and each one the pool cannot hand out is a fresh block of heap,
// zeroed and faulted in; the 100-robot broadcast has some 4000 replies of 35 bytes in flight
// (each robot answers 99 queries 50 us apart, each reply 2 ms on its way).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dvpr {

class PayloadBuffers {
 public:
  static constexpr std::size_t kMaxKept = std::size_t{1} << 20;
  static constexpr std::size_t kPerClass = 1024;
  static constexpr std::size_t kClassBytes = std::size_t{1} << 20;
  static constexpr std::size_t kMaxKeptBytes = std::size_t{64} << 20;

  // A kept buffer with capacity for at least `size` bytes (its contents and size unspecified),
  // taken from the smallest class that has one within four classes; else an empty buffer.
  std::vector<std::uint8_t> Take(std::size_t size);
  // Keeps `bytes` for a later Take, or frees it (empty, larger than kMaxKept, class full).
  void Give(std::vector<std::uint8_t>&& bytes);
  // Buffers kept now.
  std::size_t Kept() const;

 private:
  static constexpr int kClasses = 21;  // capacities 1 .. 2^21 - 1
  static int ClassOf(std::size_t capacity);  // floor(log2(capacity))
  static std::size_t LimitOf(int size_class);  // buffers a class may keep
  std::array<std::vector<std::vector<std::uint8_t>>, kClasses> kept_;
  std::size_t kept_bytes_ = 0;  // capacity of the buffers kept
};

}  // namespace dvpr
