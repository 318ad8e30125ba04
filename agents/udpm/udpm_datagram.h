#pragma once
// One datagram of LCM's UDP multicast protocol ("udpm", the wire format of LCM's
// lcm/lcm_udpm.c), read without trusting a byte of it. Two kinds, all integers big-endian:
//
//   small message   "LC02" seqno:u32 channel NUL payload
//   fragment        "LC03" seqno:u32 message_size:u32 offset:u32 fragment_no:u16 fragments:u16
//                   then, in fragment 0 only, channel NUL; then the fragment's bytes
//
// A sender numbers its messages (seqno, per sending socket); the fragments of one message share
// its number. This file only classifies one datagram; putting fragments together is
// udpm_reassembler.h. Everything a well-behaved LCM sender never produces is malformed: no
// magic, a header cut short, a channel without its NUL, empty or longer than LCM's 63 bytes, a
// fragment number not below the count, more fragments than the message has bytes, a fragment
// without bytes, fragment 0 not at offset 0, or bytes that do not fit inside the message. The
// last check is written so that it cannot wrap (offset 0xFFFFFFF0 with 32 bytes is outside a
// 1 KiB message; Debian's liblcm 1.3.1 added the two and wrote there: LCM pull request #628).
#include <cstdint>
#include <span>
#include <string_view>

namespace dvpr::udpm {

inline constexpr std::uint32_t kShortMagic = 0x4c433032;     // "LC02"
inline constexpr std::uint32_t kFragmentMagic = 0x4c433033;  // "LC03"
inline constexpr std::size_t kShortHeaderBytes = 8;
inline constexpr std::size_t kFragmentHeaderBytes = 20;
inline constexpr std::size_t kMaxChannelBytes = 63;             // LCM_MAX_CHANNEL_NAME_LENGTH
inline constexpr std::uint32_t kMaxMessageBytes = 1u << 28;     // LCM_MAX_MESSAGE_SIZE

enum class DatagramKind { kMalformed, kShort, kFragment };

struct Datagram {
  DatagramKind kind = DatagramKind::kMalformed;
  const char* problem = "";          // why it is malformed (a constant string)
  std::uint32_t seqno = 0;
  std::string_view channel;          // small messages and fragment 0; empty otherwise
  std::span<const std::uint8_t> bytes;  // the payload (small) or this fragment's part of it
  // Fragments only.
  std::uint32_t message_size = 0;
  std::uint32_t offset = 0;
  std::uint16_t fragment_no = 0;
  std::uint16_t fragments = 0;
};

// Classifies `datagram`; the views point into it.
Datagram ParseDatagram(std::span<const std::uint8_t> datagram);

}  // namespace dvpr::udpm
