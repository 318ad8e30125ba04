#pragma once
// The messages a network has in flight (network.h): one payload per message in a slot, shared by
// all its copies (no copy per destination) and counted: a copy on its way holds a reference, and
// the last one released frees the slot and gives its bytes to the PayloadBuffers a transport
// encodes its next message into (payload_buffers.h).
#include <cstdint>
#include <utility>
#include <vector>

#include "net_models/core/node_id.h"
#include "net_models/core/payload_buffers.h"
#include "net_models/core/slot_pool.h"
#include "net_models/network/network_observer.h"
#include "sim/sim_time.h"

namespace dvpr {

// 64 bytes (8-byte fields first): at 72, bench_network's KITTI broadcast ran 8% more
// instructions, most of them in malloc.
struct Payload {
  std::vector<std::uint8_t> bytes;
  std::uint64_t message = 0;
  SimTime sent;
  std::int64_t wire_bytes = 0;
  std::uint32_t refs = 0;  // the copies that still use it
  NodeId src;
  ChannelId channel{};
  MessageTypeId type{};
};
static_assert(sizeof(Payload) <= 64);

class PayloadSlab {
 public:
  // A slot for p (the last freed one, else a new one).
  std::uint32_t Acquire(Payload&& p) {
    const std::uint32_t slot = slots_.Acquire();
    slots_[slot] = std::move(p);
    return slot;
  }
  Payload& operator[](std::uint32_t slot) { return slots_[slot]; }
  const Payload& operator[](std::uint32_t slot) const { return slots_[slot]; }
  // One reference fewer (none taken yet counts as the last): the last frees the slot.
  void Release(std::uint32_t slot) {
    Payload& p = slots_[slot];
    if (p.refs > 0 && --p.refs > 0) return;
    buffers_.Give(std::move(p.bytes));  // kept for the next message, or freed: a slot may stay idle for long
    p.bytes = std::vector<std::uint8_t>();
    slots_.Release(slot);
  }
  PayloadBuffers& buffers() { return buffers_; }

 private:
  SlotPool<Payload> slots_;
  PayloadBuffers buffers_;
};

}  // namespace dvpr
