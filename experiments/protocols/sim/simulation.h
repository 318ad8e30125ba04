#pragma once
// One simulation run (docs/design.md section 3): n robot agents drive their
// sub-sequences from t = 0, exchange LCM messages through the network model in
// virtual time, and record what happened. The team is a Scenario (scenario.h,
// physics only); the ground-truth oracle, the recorders and the log attach to
// it. Metrics come afterwards, from the returned log (SummarizeSimRun).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "agents/bow_robot_agent.h"
#include "agents/placement/agent_placement.h"
#include "agents/robot_agent.h"
#include "experiments/domain/data/dataset.h"
#include "experiments/domain/evaluation/sim_metrics.h"
#include "experiments/domain/scenario/scenario.h"
#include "experiments/results/results.h"
#include "net_models/helper/link_factory.h"
#include "net_models/network/network.h"
#include "net_models/propagation/connectivity.h"

namespace dvpr {

// A simulation run: the scenario (physics), what is measured, what is written.
struct SimRunParams {
  ScenarioParams scenario;
  struct Evaluation {
    double gt_radius_m = 5.0;             // the verification oracle accepts matches this close
  } evaluation;
  struct Outputs {
    bool record_messages = false;         // keep one MessageRow per message and destination
    bool query_hops = false;              // SimRunLog::query_hops (query_hops.h)
    bool hop_counts = false;              // SimRunLog::delivered_by_hops (hop_counts.h)
    std::filesystem::path lcm_log;        // non-empty: write every delivered message there
    // Positive: after the run, ask the network's propagation who reaches whom at 0, step,
    // 2 step, ... up to the last frame's capture time (SimRunLog::connectivity).
    SimTime connectivity_step;
  } outputs;
  void Validate(const Dataset& data) const { scenario.Validate(data); }
};

// What became of a dropped robot (docs/failover.md).
struct DropoutOutcome {
  RobotId robot;
  SimTime at;
  std::optional<SimTime> detected;  // when the last live robot declared it lost; empty: not all did
  std::int64_t stored = 0;          // descriptors in its store when it dropped: gone with it
  std::int64_t kept = 0;            // of which a live robot's store holds a copy (replication)
};

// What one directed pair of robots carried.
struct PairTraffic {
  int src = 0;
  int dst = 0;
  LinkCounters counters;
  RoleCopyBytes roles{};  // by message role; all zero when the log has no roles (SimRunLog::has_roles)
};

struct SimRunLog {
  int robots = 0;
  std::vector<QueryRecord> queries;       // robot by robot, frames in order
  std::vector<std::optional<int>> query_hops;  // when outputs.query_hops: per query, as query_hops.h says
  std::vector<RobotLoad> loads;           // per robot
  std::vector<PairTraffic> links;         // the pairs that carried a message, by source, then destination
  std::vector<NodeCounters> senders;      // per robot: transmissions it put on the medium
  std::vector<MacCounters> mac;           // per robot, on a contending medium (LinkModel::Mac); else empty
  SimTime medium_busy;                    // on a contending medium: its busy time (LinkModel::MediumBusy)
  RouteCounters routes;                   // hops of the delivered copies, dropped ones by reason
  std::vector<std::int64_t> delivered_by_hops;  // when outputs.hop_counts: [k] copies delivered after k + 1 hops
  RunRoleBytes roles;                     // the run's bytes by message role
  bool has_roles = false;                 // roles and links[].roles were counted (simulated networks)
  std::vector<MessageRow> messages;       // when record_messages
  std::vector<SimTime> capture_time;      // per frame of the sequence
  std::vector<RobotId> taker;             // per frame of the sequence: the robot that took it
  std::int64_t verify_requested = 0;
  std::int64_t verify_accepted = 0;
  std::uint64_t events = 0;
  SimTime end;
  std::vector<DropoutOutcome> dropouts;   // one per params.scenario.dropouts entry, in its order
  std::vector<ConnectivitySnapshot> connectivity;  // when outputs.connectivity_step is positive
};

// Every robot routes through its own component made by `routing` (a stateless strategy or one
// with per-robot state, such as re-clustering).
SimRunLog RunSimulation(const Dataset& data, const TeamPlacement& routing, const SimRunParams& params);
// A team of bag-of-words agents (agents/bow_robot_agent.h, docs/bow.md): `vectors` holds one
// BoW vector per frame of `data` (its descriptors are not used), `plan` how the team splits them.
SimRunLog RunBowSimulation(const Dataset& data, const std::vector<BowVector>& vectors, const BowTeamPlan& plan,
                           const SimRunParams& params);

struct SimRunSummary {
  double auc = 0.0;
  std::int64_t relevant = 0;
  std::int64_t queries = 0;
  std::int64_t messages = 0;
  std::int64_t payload_bytes = 0;
  std::int64_t wire_bytes = 0;            // per destination copy (sum over links.csv)
  std::int64_t medium_bytes = 0;          // what was transmitted: a shared-medium broadcast once
  std::int64_t dropped = 0;
  LatencyStats latency;
  double worst_balance_ratio = 0.0;       // from the searches each robot actually served
  std::vector<double> precision, recall;  // the PR curve
  OnlineTruth truth;
  ClosureStats closures;                  // inter- and intra-robot (sim_metrics.h)
};

SimRunSummary SummarizeSimRun(const SimRunLog& log, const Positions& positions, double radius_m,
                              const FrameWindow& window);

}  // namespace dvpr
