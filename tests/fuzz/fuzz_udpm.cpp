// LCM's UDP multicast receive path as the agents use it (agents/udpm/): datagrams from a few
// senders, put together by one Reassembler with small limits so that the fuzzer reaches them.
// The input is a sequence of datagrams, each framed as
//   one byte: sender (low 2 bits) and time step ((byte >> 2) x 50 ms before it arrives),
//   two bytes: length (big-endian, cut to what is left), then the datagram.
// Properties, after every datagram:
// - nothing crashes, reads or writes out of bounds, or allocates beyond the limits (the bytes
//   held for unfinished messages stay within max_partial_bytes; senders and partial messages
//   within their counts);
// - each datagram is counted once: as malformed exactly when ParseDatagram says so (or when it
//   claims more than max_message_bytes, or disagrees with its message), and the counts add up;
// - a message handed out has a channel of 1 to 63 bytes without NUL, at most max_message_bytes,
//   and a small message's payload is the datagram's tail.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "agents/udpm/udpm_datagram.h"
#include "agents/udpm/udpm_reassembler.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using dvpr::fuzz::Violated;
namespace udpm = dvpr::udpm;

udpm::Limits SmallLimits() {
  udpm::Limits limits;
  limits.max_message_bytes = 4096;
  limits.max_partial_bytes = 4096 + 65535 * 128 + 256;  // the smallest Validate takes
  limits.partials_per_sender = 2;
  limits.max_senders = 3;
  limits.partial_timeout = std::chrono::seconds(1);
  return limits;
}

void Check(const udpm::Reassembler& r, std::uint64_t fed) {
  const udpm::Counts& c = r.counts();
  if (c.datagrams != fed) Violated("a datagram was not counted exactly once");
  if (c.malformed + c.duplicates > c.datagrams) Violated("more malformed and duplicate datagrams than datagrams");
  if (c.messages > c.datagrams) Violated("more messages than datagrams");
  const udpm::Limits& l = r.limits();
  if (r.partial_bytes() > l.max_partial_bytes) Violated("unfinished messages hold more than max_partial_bytes");
  if (r.senders() > static_cast<std::size_t>(l.max_senders)) Violated("more senders than max_senders");
  if (r.partial_messages() > static_cast<std::size_t>(l.max_senders * l.partials_per_sender)) {
    Violated("more unfinished messages than the limits allow");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  udpm::Reassembler r(SmallLimits());
  const std::span<const std::uint8_t> input(data, size);
  auto now = udpm::Clock::time_point{};
  std::uint64_t fed = 0;
  for (std::size_t at = 0; at + 3 <= input.size();) {
    const std::uint8_t head = input[at];
    const std::size_t length = std::min<std::size_t>((std::size_t{input[at + 1]} << 8) | input[at + 2],
                                                     input.size() - at - 3);
    const std::span<const std::uint8_t> datagram = input.subspan(at + 3, length);
    at += 3 + length;
    now += std::chrono::milliseconds(50) * (head >> 2);
    const udpm::Sender sender{0x7f000001, static_cast<std::uint16_t>(40000 + (head & 3))};
    const udpm::Datagram parsed = udpm::ParseDatagram(datagram);
    const std::uint64_t malformed_before = r.counts().malformed;
    const auto message = r.Take(sender, datagram, now);
    ++fed;
    if (parsed.kind == udpm::DatagramKind::kMalformed && r.counts().malformed != malformed_before + 1) {
      Violated(std::string("a malformed datagram was not counted as such: ") + parsed.problem);
    }
    if (message) {
      if (parsed.kind == udpm::DatagramKind::kMalformed) Violated("a malformed datagram completed a message");
      if (message->channel.empty() || message->channel.size() > udpm::kMaxChannelBytes ||
          message->channel.find('\0') != std::string_view::npos) {
        Violated("a message with a channel LCM cannot send");
      }
      if (message->payload.size() > r.limits().max_message_bytes) Violated("a message above max_message_bytes");
      if (parsed.kind == udpm::DatagramKind::kShort &&
          (message->payload.data() != datagram.data() + datagram.size() - message->payload.size())) {
        Violated("a small message's payload is not the datagram's tail");
      }
    }
    Check(r, fed);
  }
  return 0;
}
