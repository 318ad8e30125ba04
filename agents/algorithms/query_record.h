#pragma once
// What a robot recorded about one of its queries: the one record of a query's outcome. The agent
// fills it while the replies come in (RobotAgent::outcomes); the simulation's metrics
// (experiments/domain/evaluation/sim_metrics.h) read it, and a real agent process logs it for the
// launcher (experiments/protocols/lcm/agent_log.h). Only the PR ranking (MatchOutcome) and the
// queries.csv row (QueryRow) have types of their own.
#include <optional>

#include "agents/algorithms/descriptor_index.h"
#include "agents/algorithms/ids.h"
#include "sim/sim_time.h"

namespace dvpr {

struct QueryRecord {
  RobotId robot;                    // the querying robot
  FrameId frame;
  SimTime sent;                     // when the query went out (agent clock)
  int expected_replies = 0;         // searches asked for, the local one included; 0: never taken
  int received_replies = 0;
  std::optional<IndexMatch> best;   // best over the replies received
  std::optional<SimTime> latency;   // from sending to the last reply, once every reply came
  bool verify_requested = false;
  std::optional<bool> verify_accepted;

  bool Taken() const { return expected_replies > 0; }
  bool Complete() const { return received_replies == expected_replies; }
};

}  // namespace dvpr
