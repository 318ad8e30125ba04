#pragma once
// A transmitter that serializes frames first-in-first-out onto a medium at a
// data rate, with a drop-tail queue of `capacity` waiting frames (the frame
// being transmitted does not count, as in ns-3's PointToPointNetDevice, which
// dequeues a frame when its transmission starts).
//
// Because service is deterministic and FIFO, the transmitter needs no events:
// it remembers when the medium becomes free (`busy_until`) and the start times
// of the frames still waiting; a frame offered at time t is waiting behind
// exactly those queued frames whose transmission starts after t.
#include <cstdint>
#include <span>
#include <vector>

#include "net_models/core/units.h"
#include "sim/sim_time.h"

namespace dvpr {

class FifoTransmitter {
 public:
  struct Result {
    SimTime last_end;           // when the last accepted frame's last bit leaves
    std::size_t frames_sent = 0;
    Bytes bytes_sent;
    bool queue_full = false;    // some frame was dropped: the message is lost
  };

  explicit FifoTransmitter(int capacity = 100) : capacity_(capacity) {}

  // Offers the frames of one message at `now`. `medium_busy_until` is the
  // medium's own free time: the transmitter's for a point-to-point link, the
  // channel's for a shared medium (then several transmitters share it).
  Result Send(std::span<const Bytes> frames, SimTime now, DataRate rate, SimTime& medium_busy_until);

  int Waiting(SimTime now);

 private:
  void Push(std::int64_t start);

  int capacity_;
  std::vector<std::int64_t> starts_;  // ring buffer, allocated on first use
  std::size_t head_ = 0;
  std::size_t count_ = 0;
};

}  // namespace dvpr
