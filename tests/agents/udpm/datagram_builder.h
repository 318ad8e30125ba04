#pragma once
// Datagrams of LCM's UDP multicast protocol built byte by byte, as LCM's lcm_udpm.c lays them
// out (big-endian; agents/udpm/udpm_datagram.h), for the tests: well-formed ones, and streams of
// datagrams each of which is malformed by construction (HostileDatagrams), whatever the random
// numbers drawn for it.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace dvpr::udpm_test {

using Bytes = std::vector<std::uint8_t>;

inline void Put32(Bytes& b, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) b.push_back(static_cast<std::uint8_t>(v >> shift));
}
inline void Put16(Bytes& b, std::uint16_t v) {
  b.push_back(static_cast<std::uint8_t>(v >> 8));
  b.push_back(static_cast<std::uint8_t>(v));
}
inline void PutText(Bytes& b, const std::string& s) { b.insert(b.end(), s.begin(), s.end()); }

// "LC02" seqno channel NUL payload.
inline Bytes Small(std::uint32_t seqno, const std::string& channel, const Bytes& payload) {
  Bytes b{'L', 'C', '0', '2'};
  Put32(b, seqno);
  PutText(b, channel);
  b.push_back(0);
  b.insert(b.end(), payload.begin(), payload.end());
  return b;
}

// "LC03" seqno size offset fragment_no fragments [channel NUL if fragment 0] bytes.
inline Bytes Fragment(std::uint32_t seqno, std::uint32_t size, std::uint32_t offset, std::uint16_t no,
                      std::uint16_t fragments, const std::string& channel, const Bytes& bytes) {
  Bytes b{'L', 'C', '0', '3'};
  Put32(b, seqno);
  Put32(b, size);
  Put32(b, offset);
  Put16(b, no);
  Put16(b, fragments);
  if (no == 0) {
    PutText(b, channel);
    b.push_back(0);
  }
  b.insert(b.end(), bytes.begin(), bytes.end());
  return b;
}

// The datagram of issue 31: a fragment of a message claiming 2^28 bytes at offset 0xFFFFFFF0,
// 233 bytes long. Debian's liblcm 1.3.1 adds offset and length in 32 bits (0xFFFFFFF0 + 213
// wraps to 197, "inside" the message) and writes 213 bytes 4 GiB past its buffer.
inline Bytes WrappingFragment() {
  return Fragment(1, 1u << 28, 0xFFFFFFF0u, 1, 2, "", Bytes(213, 0x41));
}

// A stream of datagrams each malformed whatever is drawn: 15 kinds in turn (too short, no
// magic, channels without NUL or empty or too long, fragment headers cut short, sizes of 0 or
// above 2^28, counts of 0 or above the size, numbers not below the count, offsets that wrap or
// run past the end, fragment 0 off offset 0, fragments without bytes).
class HostileDatagrams {
 public:
  explicit HostileDatagrams(std::uint64_t seed) : random_(seed) {}

  static constexpr int kKinds = 15;

  Bytes Next() {
    const int kind = static_cast<int>(count_++ % kKinds);
    const std::uint32_t seqno = Draw(0, 0xFFFFFFFFu);
    switch (kind) {
      case 0: return Random(Draw(0, 7));
      case 1: {
        Bytes b = Random(Draw(8, 300));
        if (b[0] == 'L' && b[1] == 'C' && b[2] == '0') b[0] = 'X';
        return b;
      }
      case 2: {  // a channel that never ends (up to 63 bytes) or runs past 63 bytes
        Bytes b{'L', 'C', '0', '2'};
        Put32(b, seqno);
        const Bytes name = NonZero(Draw(1, 100));
        b.insert(b.end(), name.begin(), name.end());
        return b;
      }
      case 3: return Small(seqno, "", Random(Draw(0, 50)));
      case 4: {
        Bytes b = Fragment(seqno, 100, 0, 1, 2, "", Bytes(4, 1));
        b.resize(Draw(8, 19));
        return b;
      }
      case 5: return Fragment(seqno, 0, 0, 1, 2, "", Random(Draw(1, 50)));
      case 6: return Fragment(seqno, Draw((1u << 28) + 1, 0xFFFFFFFFu), 0, 1, 2, "", Random(Draw(1, 50)));
      case 7: return Fragment(seqno, Draw(1, 100000), 0, 1, 0, "", Random(Draw(1, 50)));
      case 8: {
        const auto fragments = static_cast<std::uint16_t>(Draw(1, 65534));
        return Fragment(seqno, 100000, 0, static_cast<std::uint16_t>(Draw(fragments, 65535)), fragments, "",
                        Random(Draw(1, 50)));
      }
      case 9: return Fragment(seqno, Draw(2, 1u << 28), Draw(0xFFFFFF00u, 0xFFFFFFFFu), 1, 2, "", Random(Draw(1, 255)));
      case 10: {  // past the end: `over` bytes more than fit after the offset
        const std::uint32_t size = Draw(10, 1000), offset = Draw(1, size - 1);
        return Fragment(seqno, size, offset, 1, 2, "", Random(size - offset + Draw(1, 100)));
      }
      case 11: {
        Bytes b = Fragment(seqno, 1000, Draw(1, 999), 1, 2, "", {});
        b[17] = 0;  // fragment_no 0 (offset != 0): the channel follows
        PutText(b, "DVPR_STATUS");
        b.push_back(0);
        const Bytes data = Random(Draw(1, 50));
        b.insert(b.end(), data.begin(), data.end());
        return b;
      }
      case 12: return Fragment(seqno, 1000, 0, 0, 2, NonZeroText(Draw(64, 120)), Random(Draw(0, 20)));
      case 13: {
        const std::uint32_t size = Draw(1, 100);
        return Fragment(seqno, size, 0, 1, static_cast<std::uint16_t>(Draw(size + 1, 65535)), "", Random(1));
      }
      default: return Fragment(seqno, 1000, 10, 1, 2, "", {});  // no bytes
    }
  }

 private:
  std::uint32_t Draw(std::uint32_t low, std::uint32_t high) {
    return std::uniform_int_distribution<std::uint32_t>(low, high)(random_);
  }
  Bytes Random(std::size_t n) {
    Bytes b(n);
    for (auto& x : b) x = static_cast<std::uint8_t>(Draw(0, 255));
    return b;
  }
  Bytes NonZero(std::size_t n) {
    Bytes b(n);
    for (auto& x : b) x = static_cast<std::uint8_t>(Draw(1, 255));
    return b;
  }
  std::string NonZeroText(std::size_t n) {
    const Bytes b = NonZero(n);
    return std::string(b.begin(), b.end());
  }

  std::mt19937_64 random_;
  std::uint64_t count_ = 0;
};

}  // namespace dvpr::udpm_test
