#pragma once
// The simulation's LCM event log, recorded from a Network's hooks: every
// message that reaches a receiver is written once, at its first delivery,
// stamped like the messages' utime: the run's start instant (microseconds
// since the Unix epoch, the config's start_time) + virtual time (SimTime::us(),
// truncating), so lcm-logplayer replays the run at its virtual pace.
#include <cstdint>
#include <vector>

#include "experiments/results/lcm_log/lcm_event_log.h"
#include "net_models/network/network_observer.h"

namespace dvpr {

class EventLogRecorder : public NetworkObserver {
 public:
  // The writer must outlive the recorder.
  EventLogRecorder(LcmEventLogWriter& writer, std::int64_t start_utime) : writer_(writer), start_utime_(start_utime) {}
  void OnDelivered(const MessageCopy& copy, SimTime at) override;

 private:
  LcmEventLogWriter& writer_;
  std::int64_t start_utime_;
  std::vector<bool> logged_;  // by MessageCopy::message
};

}  // namespace dvpr
