#include "experiments/protocols/sim/event_log_recorder.h"

namespace dvpr {

void EventLogRecorder::OnDelivered(const MessageCopy& copy, SimTime at) {
  const auto message = static_cast<std::size_t>(copy.message);
  if (message >= logged_.size()) logged_.resize(message + 1, false);
  if (logged_[message]) return;  // a broadcast is logged once, not per receiver
  logged_[message] = true;
  writer_.Write(start_utime_ + at.us(), copy.channel_name, copy.payload);
}

}  // namespace dvpr
