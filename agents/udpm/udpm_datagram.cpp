#include "agents/udpm/udpm_datagram.h"

#include <algorithm>

namespace dvpr::udpm {

namespace {

std::uint32_t Read32(std::span<const std::uint8_t> b, std::size_t at) {
  return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) | (std::uint32_t{b[at + 2]} << 8) |
         std::uint32_t{b[at + 3]};
}

std::uint16_t Read16(std::span<const std::uint8_t> b, std::size_t at) {
  return static_cast<std::uint16_t>((b[at] << 8) | b[at + 1]);
}

Datagram Malformed(const char* problem) {
  Datagram d;
  d.problem = problem;
  return d;
}

// The NUL-terminated channel at the start of `rest`; its length, or a problem.
struct Channel {
  std::string_view name;
  const char* problem = nullptr;
};

Channel ReadChannel(std::span<const std::uint8_t> rest) {
  const std::size_t scan = std::min(rest.size(), kMaxChannelBytes + 1);
  const auto nul = std::find(rest.begin(), rest.begin() + static_cast<std::ptrdiff_t>(scan), std::uint8_t{0});
  const auto length = static_cast<std::size_t>(nul - rest.begin());
  if (length == scan) {
    return {{}, scan > kMaxChannelBytes ? "channel longer than 63 bytes" : "channel without its terminating NUL"};
  }
  if (length == 0) return {{}, "empty channel"};
  return {std::string_view(reinterpret_cast<const char*>(rest.data()), length), nullptr};
}

Datagram ParseShort(std::span<const std::uint8_t> b) {
  const Channel c = ReadChannel(b.subspan(kShortHeaderBytes));
  if (c.problem != nullptr) return Malformed(c.problem);
  Datagram d;
  d.kind = DatagramKind::kShort;
  d.seqno = Read32(b, 4);
  d.channel = c.name;
  d.bytes = b.subspan(kShortHeaderBytes + c.name.size() + 1);
  return d;
}

Datagram ParseFragment(std::span<const std::uint8_t> b) {
  if (b.size() < kFragmentHeaderBytes) return Malformed("fragment shorter than its 20-byte header");
  Datagram d;
  d.kind = DatagramKind::kFragment;
  d.seqno = Read32(b, 4);
  d.message_size = Read32(b, 8);
  d.offset = Read32(b, 12);
  d.fragment_no = Read16(b, 16);
  d.fragments = Read16(b, 18);
  if (d.message_size == 0) return Malformed("fragmented message of 0 bytes");
  if (d.message_size > kMaxMessageBytes) return Malformed("message larger than LCM's 2^28 bytes");
  if (d.fragments == 0) return Malformed("message of 0 fragments");
  if (d.fragment_no >= d.fragments) return Malformed("fragment number not below the fragment count");
  if (d.fragments > d.message_size) return Malformed("more fragments than the message has bytes");
  std::span<const std::uint8_t> rest = b.subspan(kFragmentHeaderBytes);
  if (d.fragment_no == 0) {
    if (d.offset != 0) return Malformed("fragment 0 not at offset 0");
    const Channel c = ReadChannel(rest);
    if (c.problem != nullptr) return Malformed(c.problem);
    d.channel = c.name;
    rest = rest.subspan(c.name.size() + 1);
  }
  if (rest.empty()) return Malformed("fragment without bytes");
  // offset + size <= message_size, written so that nothing can wrap.
  if (d.offset >= d.message_size || rest.size() > d.message_size - d.offset) {
    return Malformed("fragment outside its message");
  }
  d.bytes = rest;
  return d;
}

}  // namespace

Datagram ParseDatagram(std::span<const std::uint8_t> datagram) {
  if (datagram.size() < kShortHeaderBytes) return Malformed("shorter than LCM's 8-byte header");
  const std::uint32_t magic = Read32(datagram, 0);
  if (magic == kShortMagic) return ParseShort(datagram);
  if (magic == kFragmentMagic) return ParseFragment(datagram);
  return Malformed("no LCM magic (LC02 or LC03)");
}

}  // namespace dvpr::udpm
