#pragma once
// What the network does with a copy that has no route (config: network.disconnected;
// docs/network_model.md, "Disconnection"): drop it (`drop`, DropReason::kNoRoute), or hold it at
// the robot that has it and send it on when a route appears (`store_and_forward`, as a
// delay-tolerant network's custody: Fall 2003, DTN architecture RFC 4838).
//
// A holder asks its routing again every `retry` of virtual time, at whole multiples of it (the
// shortest-path graph changes at most once per its 100 ms window, shortest_path_routing.h, so
// asking more often finds nothing new). Each held copy takes its message's wire bytes
// (wire_format.h) of the holder's buffer of hold_bytes; a copy that does not fit is dropped
// `buffer_full`, one held hold_time or longer is dropped `expired` at the first retry that finds
// it so.
#include <cstdint>
#include <string_view>

#include "net_models/core/units.h"
#include "sim/sim_time.h"

namespace dvpr {

enum class DisconnectedKind { kDrop, kStoreAndForward };

// "drop" | "store_and_forward"; Parse throws std::invalid_argument "unknown value '<name>'
// (expected one of: drop, store_and_forward)".
DisconnectedKind ParseDisconnectedKind(std::string_view name);
std::string_view ToString(DisconnectedKind kind);

struct DisconnectedParams {
  // The valid ranges (docs/config.md): a buffer of up to 1024 GiB; a copy held up to 100 000 h.
  static constexpr Bytes kMaxHoldBytes = Bytes(std::int64_t{1} << 40);
  static constexpr SimTime kMaxHoldTime = SimTime::Millis(100000LL * 3600 * 1000);
  static constexpr SimTime kRetry = SimTime::Millis(100);

  DisconnectedKind kind = DisconnectedKind::kDrop;
  Bytes hold_bytes = Bytes(10'000'000);   // 10MB per robot (store_and_forward)
  SimTime hold_time = SimTime::Millis(60'000);  // 60s
  SimTime retry = kRetry;

  // Throws std::invalid_argument "<field>: ..." ("hold_bytes: must be in [1B, 1024GiB], got 0B").
  void Validate() const;
  bool operator==(const DisconnectedParams&) const = default;
};

}  // namespace dvpr
