#pragma once
// The simulation's LCM event log, recorded from a Network's hooks: every
// message that reaches a receiver is written once, at its first delivery,
// stamped with virtual time in microseconds since the start (SimTime::us(),
// truncating), so lcm-logplayer replays the run at its virtual pace.
#include <cstdint>
#include <vector>

#include "experiments/results/lcm_event_log.h"
#include "net_models/network_observer.h"

namespace dvpr {

class EventLogRecorder : public NetworkObserver {
 public:
  // The writer must outlive the recorder.
  explicit EventLogRecorder(LcmEventLogWriter& writer) : writer_(writer) {}
  void OnDelivered(const MessageCopy& copy, SimTime at) override;

 private:
  LcmEventLogWriter& writer_;
  std::vector<bool> logged_;  // by MessageCopy::message
};

}  // namespace dvpr
