#include "net_models/medium/fifo_transmitter.h"

#include <algorithm>

namespace dvpr {

int FifoTransmitter::Waiting(SimTime now) {
  // Frames whose transmission has started by `now` have left the queue.
  while (count_ > 0 && starts_[head_] <= now.ns()) {
    head_ = head_ + 1 == starts_.size() ? 0 : head_ + 1;
    --count_;
  }
  return static_cast<int>(count_);
}

void FifoTransmitter::Push(std::int64_t start) {
  if (starts_.empty()) starts_.resize(static_cast<std::size_t>(std::max(capacity_, 1)));
  std::size_t tail = head_ + count_;
  if (tail >= starts_.size()) tail -= starts_.size();
  starts_[tail] = start;
  ++count_;
}

FifoTransmitter::Result FifoTransmitter::Send(std::span<const Bytes> frames, SimTime now, DataRate rate,
                                              SimTime& medium_busy_until) {
  Result r;
  r.last_end = now;
  int waiting = Waiting(now);
  for (const Bytes frame : frames) {
    const SimTime start = std::max(now, medium_busy_until);
    if (start > now) {  // must wait for the medium: needs a queue place
      if (waiting >= capacity_) {
        r.queue_full = true;
        return r;
      }
      Push(start.ns());
      ++waiting;
    }
    medium_busy_until = start + rate.TxTime(frame);
    r.last_end = medium_busy_until;
    ++r.frames_sent;
    r.bytes_sent += frame;
  }
  return r;
}

}  // namespace dvpr
