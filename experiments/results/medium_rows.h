#pragma once
// The rows of medium.csv (docs/network_model.md, "Contending media"), written only when a network
// variant of the sweep contends for its medium (`csma`, `wifi`): per run, what the medium access
// did - attempts, backoffs, collisions, retries, how long the medium was busy - and what became of
// the copies. Each robot's share is at the end of per_robot.csv (RobotLoadRow's mac_ fields).
// Plain data, as results.h.
#include <array>
#include <cstdint>

#include "experiments/results/radio_rows.h"  // kRadioDropReasons: the network's drop reasons
#include "experiments/results/results.h"

namespace dvpr {

// One row of medium.csv: one run of one strategy on a contending variant.
struct MediumRow {
  RunKey key;
  std::int64_t delivered_copies = 0;
  std::int64_t attempts = 0;     // frames put on the medium by all robots, retransmissions included
  std::int64_t backoffs = 0;
  std::int64_t collisions = 0;   // attempts that overlapped another at a receiver (wifi)
  std::int64_t retries = 0;      // retransmissions (wifi)
  std::int64_t airtime_ns = 0;   // summed over the robots: the medium time of their attempts
  std::int64_t busy_ns = 0;      // the medium's busy time (csma: transmitting or propagating; wifi: a frame in the air)
  double utilisation = kNotApplicable;  // busy_ns over the run's simulated time
  std::array<std::int64_t, kRadioDropReasons.size()> dropped{};  // copies lost, by kRadioDropReasons
};

}  // namespace dvpr
