#pragma once
// Bytes on the wire for one LCM message (docs/design.md §4), following what LCM's
// UDP multicast provider (lcm/lcm_udpm.c, LCM 1.3.x on Linux) puts on a socket:
//
//  1. LCM datagrams. If channel + NUL + payload <= 65499 bytes, one "short"
//     datagram: 8-byte header (magic, sequence number), channel, NUL, payload.
//     Otherwise the channel + NUL + payload stream is cut into fragments of at
//     most 65487 bytes, each behind a 20-byte fragment header (magic, seqno,
//     size, offset, fragment number, count); the channel travels in the first
//     fragment only. (8 + 65499 = 20 + 65487 = 65507, the largest IPv4 UDP
//     payload.)
//  2. IP packets. Each datagram gains UDP 8 + IPv4 20 header bytes. When that
//     exceeds the MTU, IPv4 fragments it: every fragment has its own 20-byte
//     IP header and carries a multiple of 8 data bytes (1480 at MTU 1500),
//     the UDP header riding in the first fragment's data.
//  3. Link frames. Each IP packet gains the link's framing (2 bytes for PPP,
//     as ns-3's PointToPointNetDevice adds).
//
// Worked example: a 517-byte UDP payload is a 517 + 8 + 20 = 545-byte IP
// packet and a 547-byte PPP frame.
#include <cstdint>
#include <vector>

#include "net_models/units.h"

namespace dvpr {

struct WireParams {
  // The MTU a config may give: IPv4's minimum (RFC 791) up to its largest packet (a 16-bit
  // total length).
  static constexpr Bytes kMinConfigMtu{68};
  static constexpr Bytes kMaxMtu{65535};

  Bytes mtu{1500};          // IP MTU of the link: largest IP packet, headers included
  Bytes link_framing{2};    // per-packet link-layer overhead (PPP: 2)
  // Throws std::invalid_argument "<field>: ..." (mtu must leave room for the
  // IP header and 8 data bytes, i.e. >= 28, and be at most kMaxMtu; framing >= 0).
  void Validate() const;
  bool operator==(const WireParams&) const = default;
};

namespace wire {
inline constexpr std::int64_t kLcmShortHeader = 8;
inline constexpr std::int64_t kLcmFragmentHeader = 20;
inline constexpr std::int64_t kLcmShortMessageMax = 65499;   // channel + NUL + payload
inline constexpr std::int64_t kLcmFragmentMaxPayload = 65487;
inline constexpr std::int64_t kUdpHeader = 8;
inline constexpr std::int64_t kIpv4Header = 20;
}  // namespace wire

// The wire footprint of one message: counts and total bytes at each layer.
struct WireFootprint {
  std::int64_t lcm_datagrams = 0;  // 1, or the number of LCM fragments
  std::int64_t ip_packets = 0;     // link frames: IP packets after IP fragmentation
  Bytes udp_payload_bytes;         // sum of LCM datagram sizes (headers, channel, payload)
  Bytes ip_bytes;                  // sum of IP packet sizes
  Bytes wire_bytes;                // sum of link frame sizes: what the link serializes
  Bytes largest_frame;
};

// Footprint of a message with `payload` encoded bytes on a channel whose
// name is `channel_length` bytes long.
WireFootprint ComputeWireFootprint(Bytes payload, std::int64_t channel_length, const WireParams& params);

// Appends the size of every link frame of the message, in transmission order
// (the link serializes them one by one). Returns the footprint as well.
WireFootprint AppendLinkFrames(Bytes payload, std::int64_t channel_length, const WireParams& params,
                               std::vector<Bytes>& frames);

// The link frames of one UDP datagram of `udp_payload` bytes.
WireFootprint FramesOfDatagram(Bytes udp_payload, const WireParams& params, std::vector<Bytes>* frames);

}  // namespace dvpr
