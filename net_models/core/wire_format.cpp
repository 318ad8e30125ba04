#include "net_models/core/wire_format.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "net_models/core/param_checks.h"

namespace dvpr {
namespace {

// Adds one UDP datagram of `udp_payload` bytes to fp (and its frames to *frames).
void AddDatagram(std::int64_t udp_payload, const WireParams& p, WireFootprint& fp, std::vector<Bytes>* frames) {
  const std::int64_t ip_data = udp_payload + wire::kUdpHeader;
  const std::int64_t framing = p.link_framing.value();
  // A link frame carries its IP packet padded to the link's minimum payload (Ethernet: 46 B).
  const auto frame = [&](std::int64_t ip_packet) { return std::max(ip_packet, p.link_min_payload.value()) + framing; };
  fp.lcm_datagrams += 1;
  fp.udp_payload_bytes += Bytes(udp_payload);
  std::int64_t per_fragment = ip_data;  // unfragmented: everything in one packet
  std::int64_t packets = 1;
  if (ip_data + wire::kIpv4Header > p.mtu.value()) {
    per_fragment = (p.mtu.value() - wire::kIpv4Header) / 8 * 8;  // fragment offsets count 8-byte units
    packets = (ip_data + per_fragment - 1) / per_fragment;
  }
  const std::int64_t last_data = ip_data - (packets - 1) * per_fragment;
  fp.ip_packets += packets;
  fp.ip_bytes += Bytes(ip_data + packets * wire::kIpv4Header);
  const std::int64_t full_frame = frame(per_fragment + wire::kIpv4Header);
  const std::int64_t last_frame = frame(last_data + wire::kIpv4Header);
  fp.wire_bytes += Bytes((packets - 1) * full_frame + last_frame);
  fp.largest_frame = std::max(fp.largest_frame, Bytes(packets > 1 ? full_frame : last_frame));
  if (frames != nullptr) {
    for (std::int64_t i = 0; i + 1 < packets; ++i) frames->push_back(Bytes(full_frame));
    frames->push_back(Bytes(last_frame));
  }
}

WireFootprint Compute(Bytes payload, std::int64_t channel_length, const WireParams& p, std::vector<Bytes>* frames) {
  WireFootprint fp;
  const std::int64_t stream = channel_length + 1 + payload.value() + p.trailer.value();  // channel, NUL, payload, trailer
  if (stream <= wire::kLcmShortMessageMax) {
    AddDatagram(wire::kLcmShortHeader + stream, p, fp, frames);
    return fp;
  }
  // LCM fragments: the channel + NUL + payload stream in chunks of at most
  // kLcmFragmentMaxPayload, each behind a fragment header.
  for (std::int64_t offset = 0; offset < stream; offset += wire::kLcmFragmentMaxPayload) {
    const std::int64_t chunk = std::min(wire::kLcmFragmentMaxPayload, stream - offset);
    AddDatagram(wire::kLcmFragmentHeader + chunk, p, fp, frames);
  }
  return fp;
}

}  // namespace

void WireParams::Validate() const {
  if (mtu.value() < wire::kIpv4Header + 8) {
    InvalidParam("mtu", "too small: an IPv4 packet needs 20 header bytes plus at least 8 data bytes, got " +
                            std::to_string(mtu.value()) + "B");
  }
  CheckInRange("mtu", mtu, Bytes(wire::kIpv4Header + 8), kMaxMtu);
  // Framing comes with the link model (LinkWire), never from a config: a bad one is a bug.
  if (link_framing.value() < 0 || link_min_payload.value() < 0 || trailer.value() < 0) {
    throw std::logic_error("WireParams: negative link framing or minimum payload");
  }
}

WireParams LinkWire(WireParams wire, LinkFraming framing) {
  switch (framing) {
    case LinkFraming::kPpp:
      wire.link_framing = Bytes(2);
      wire.link_min_payload = Bytes(0);
      break;
    case LinkFraming::kEthernetDix:
      wire.link_framing = Bytes(wire::kEthernetHeader + wire::kEthernetFcs);
      wire.link_min_payload = Bytes(wire::kEthernetMinPayload);
      break;
    case LinkFraming::kWifi:
      wire.link_framing = Bytes(wire::kWifiMacHeader + wire::kWifiFcs + wire::kLlcSnap);
      wire.link_min_payload = Bytes(0);
      break;
  }
  return wire;
}

WireFootprint ComputeWireFootprint(Bytes payload, std::int64_t channel_length, const WireParams& params) {
  return Compute(payload, channel_length, params, nullptr);
}

WireFootprint AppendLinkFrames(Bytes payload, std::int64_t channel_length, const WireParams& params,
                               std::vector<Bytes>& frames) {
  return Compute(payload, channel_length, params, &frames);
}

WireFootprint FramesOfDatagram(Bytes udp_payload, const WireParams& params, std::vector<Bytes>* frames) {
  WireFootprint fp;
  AddDatagram(udp_payload.value(), params, fp, frames);
  return fp;
}

}  // namespace dvpr
