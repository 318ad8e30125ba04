#pragma once
// What a network counts (network.h): per directed pair, per sending node, and what became of all
// copies whatever their pair. The simulation turns them into runs.csv, per_robot.csv and
// routes.csv (experiments/results).
#include <array>
#include <cstdint>

#include "net_models/link/link_model.h"

namespace dvpr {

// Per directed pair (src -> dst). messages, payload_bytes and wire_bytes count
// every message sent to dst (delivered, dropped, or still in flight);
// wire_bytes is what one copy costs on the wire (wire_format.h) - on a shared
// medium a broadcast is one transmission heard by all, see NodeCounters.
struct LinkCounters {
  std::uint64_t messages = 0;
  std::int64_t payload_bytes = 0;
  std::int64_t wire_bytes = 0;
  std::uint64_t delivered = 0;
  std::uint64_t dropped = 0;
};

// Per sending node: what it published and what it put on the medium, its relaying for others
// (multi-hop routing, network_stack.h) included.
struct NodeCounters {
  std::uint64_t published = 0;       // Send() calls
  std::uint64_t transmissions = 0;   // copies put on a medium (LinkModel::Transmissions)
  std::int64_t medium_bytes = 0;     // frame bytes of those transmissions
  std::uint64_t relay_transmissions = 0;  // of the transmissions: others' messages it sent on
  std::int64_t relay_bytes = 0;           // and their frame bytes
  std::uint64_t routing_transmissions = 0;  // of the transmissions: on link-local channels (a routing
  std::int64_t routing_bytes = 0;           // protocol's beacons, SetLinkLocal) and their frame bytes
};

// What became of all copies, whatever their pair: delivered ones and the hops they took (1 for
// a copy that went straight to its destination), dropped ones by DropReason.
struct RouteCounters {
  std::uint64_t held = 0;            // copies taken into a buffer (store-and-forward), each once: when first held
  std::uint64_t delivered = 0;
  std::uint64_t delivered_hops = 0;  // summed over the delivered copies
  int max_hops = 0;                  // the most any delivered copy took
  std::array<std::uint64_t, kDropReasons> dropped{};  // by static_cast<std::size_t>(DropReason)
  bool operator==(const RouteCounters&) const = default;
};

}  // namespace dvpr
