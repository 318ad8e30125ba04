#pragma once
// What a contending medium access (csma_link.h, wifi_link.h) did at one station, for
// per_robot.csv: how often it deferred and retried, what it lost and why, and how long it held
// the medium. A model that does not contend has none (LinkModel::Mac is empty).
#include <cstdint>

#include "sim/sim_time.h"

namespace dvpr {

struct MacCounters {
  std::uint64_t attempts = 0;     // frames put on the medium, retransmissions included
  std::uint64_t backoffs = 0;     // backoffs drawn (csma: the medium was busy; wifi: every procedure)
  std::uint64_t collisions = 0;   // of the attempts: those that overlapped another at a receiver (wifi)
  std::uint64_t retries = 0;      // of the attempts: retransmissions of an unacknowledged frame (wifi)
  std::uint64_t dropped_queue_full = 0;   // frames its full queue refused
  std::uint64_t dropped_retry_limit = 0;  // frames given up after the last retry
  SimTime airtime;                // the medium time of its attempts (wifi: PPDUs, ACKs not included)
  bool operator==(const MacCounters&) const = default;
};

}  // namespace dvpr
