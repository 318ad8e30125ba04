#pragma once
// Bytes on the wire for one LCM message (docs/design.md §4), following what LCM's
// UDP multicast provider (lcm/lcm_udpm.c, LCM 1.3.x on Linux) puts on a socket:
//
//  0. The team's trailer. A team's transport appends its authentication trailer to every LCM
//     message (34 bytes: robot, instance, counter and a 16-byte tag; agents/auth/message_auth.h,
//     docs/security.md): LCM carries payload + trailer. WireParams::trailer says how many bytes;
//     every team dvpr runs or launches has it (wire::kTeamTrailer), a bare WireParams has none.
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
//  3. Link frames. Each IP packet gains the link's framing (LinkWire): 2 bytes for PPP, as
//     ns-3's PointToPointNetDevice adds; DIX Ethernet's 14-byte header and 4-byte FCS around
//     a payload padded to 46 bytes (csma, as ns-3's CsmaNetDevice); 802.11's 24-byte MAC
//     header, 8-byte LLC/SNAP header and 4-byte FCS (wifi, as ns-3's WifiNetDevice).
//
// Worked example: a 517-byte UDP payload is a 517 + 8 + 20 = 545-byte IP
// packet and a 547-byte PPP frame.
#include <cstdint>
#include <vector>

#include "net_models/core/units.h"

namespace dvpr {

struct WireParams {
  // The MTU a config may give: IPv4's minimum (RFC 791) up to its largest packet (a 16-bit
  // total length).
  static constexpr Bytes kMinConfigMtu{68};
  static constexpr Bytes kMaxMtu{65535};

  Bytes mtu{1500};          // IP MTU of the link: largest IP packet, headers included
  Bytes link_framing{2};    // per-packet link-layer overhead (PPP: 2)
  Bytes link_min_payload{0};  // an IP packet shorter than this is padded to it (Ethernet: 46)
  Bytes trailer{0};         // appended to each LCM message by the team's transport (step 0 above)
  // Throws std::invalid_argument "mtu: ..." (mtu must leave room for the IP header and 8 data
  // bytes, i.e. >= 28, and be at most kMaxMtu); std::logic_error for a negative framing.
  void Validate() const;
  bool operator==(const WireParams&) const = default;
};

namespace wire {
// A launched team's authentication trailer: robot u16, instance u64, counter u64, 16-byte tag
// (agents/auth/message_auth.h's kTrailerBytes; experiments/protocols/lcm checks they agree).
inline constexpr std::int64_t kTeamTrailer = 2 + 8 + 8 + 16;
inline constexpr std::int64_t kLcmShortHeader = 8;
inline constexpr std::int64_t kLcmFragmentHeader = 20;
inline constexpr std::int64_t kLcmShortMessageMax = 65499;   // channel + NUL + payload
inline constexpr std::int64_t kLcmFragmentMaxPayload = 65487;
inline constexpr std::int64_t kUdpHeader = 8;
inline constexpr std::int64_t kIpv4Header = 20;
inline constexpr std::int64_t kEthernetHeader = 14;     // DIX: destination, source, EtherType
inline constexpr std::int64_t kEthernetFcs = 4;
inline constexpr std::int64_t kEthernetMinPayload = 46;  // 64-byte minimum frame less header and FCS
inline constexpr std::int64_t kWifiMacHeader = 24;       // 802.11 data frame, no QoS, no address 4
inline constexpr std::int64_t kWifiFcs = 4;
inline constexpr std::int64_t kLlcSnap = 8;
}  // namespace wire

// The framing of each link model: PPP (point_to_point, shared_medium, radio; ideal counts it
// too), DIX Ethernet (csma), 802.11 data frames (wifi).
enum class LinkFraming { kPpp, kEthernetDix, kWifi };
// `wire` with the framing's link_framing and link_min_payload.
WireParams LinkWire(WireParams wire, LinkFraming framing);

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
