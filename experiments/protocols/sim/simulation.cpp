#include "experiments/protocols/sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>

#include "agents/ids.h"
#include "agents/decoded_messages.h"
#include "agents/sim_transport.h"
#include "experiments/protocols/sim/event_log_recorder.h"
#include "experiments/protocols/sim/message_roles.h"
#include "experiments/protocols/sim/message_rows.h"
#include "experiments/protocols/sim/pose_oracle.h"
#include "experiments/evaluation/metrics.h"
#include "experiments/data/split.h"
#include "experiments/results/lcm_event_log.h"
#include "sim/simulator.h"

namespace dvpr {

void SimRunParams::Validate(const Dataset& data) const {
  if (robots < 2) throw std::invalid_argument("robots: at least 2 robots are needed, got " + std::to_string(robots));
  if (robots > data.size()) {
    throw std::invalid_argument("robots: " + std::to_string(robots) + " robots but only " +
                                std::to_string(data.size()) + " frames");
  }
  if (robots > kMaxWireInt16) throw std::invalid_argument("robots: at most 32767 (int16 robot ids on the wire)");
  if (data.dim() > kMaxWireInt16) {
    throw std::invalid_argument("dataset.dim: at most 32767 values per descriptor (query_t's int16 dim), got " +
                                std::to_string(data.dim()));
  }
  agent.Validate();
  network.Validate(robots);
  for (const auto& d : dropouts) {
    if (d.robot.value < 0 || d.robot.value >= robots) {
      throw std::invalid_argument("dropout.robot: " + std::to_string(d.robot.value) + " is not a robot of 0.." +
                                  std::to_string(robots - 1));
    }
  }
}

namespace {

// What a run records of its network: its bytes by role always; as params ask, messages.csv rows
// and an LCM event log.
struct NetworkRecorders {
  NetworkRecorders(Network& network, const SimRunParams& params)
      : roles(network.nodes()), roles_subscription(network.Subscribe(roles)) {
    if (params.record_messages) rows_subscription = network.Subscribe(rows);
    if (!params.lcm_log.empty()) {
      event_log_file = std::make_unique<LcmEventLogWriter>(params.lcm_log);
      event_log = std::make_unique<EventLogRecorder>(*event_log_file, params.start_utime);
      event_log_subscription = network.Subscribe(*event_log);
    }
  }
  RoleBytesRecorder roles;
  ObserverSubscription roles_subscription;
  MessageRowRecorder rows;
  ObserverSubscription rows_subscription;
  std::unique_ptr<LcmEventLogWriter> event_log_file;
  std::unique_ptr<EventLogRecorder> event_log;
  ObserverSubscription event_log_subscription;
};

bool IsDropped(const SimRunParams& params, int robot) {
  for (const auto& d : params.dropouts) {
    if (d.robot.value == robot) return true;
  }
  return false;
}

// The (robot that saw it, frame) of every descriptor an agent stores whole
// (TeamAgent::WholeFramesStored: a BoW agent lists none).
std::vector<std::pair<int, int>> StoredCopies(const TeamAgent& agent) {
  std::vector<std::pair<int, int>> out;
  for (const IndexEntry& e : agent.WholeFramesStored()) out.emplace_back(e.robot.value, e.frame.value);
  return out;
}

// Per dropout: what its store held, how much of it a robot that stayed keeps a copy of, and
// when the last robot that stayed declared it lost.
std::vector<DropoutOutcome> DropoutOutcomes(const SimRunParams& params,
                                            const std::vector<std::unique_ptr<TeamAgent>>& agents) {
  std::set<std::pair<int, int>> live_copies;  // (robot that saw it, frame)
  for (std::size_t r = 0; r < agents.size(); ++r) {
    if (IsDropped(params, static_cast<int>(r))) continue;
    for (const auto& copy : StoredCopies(*agents[r])) live_copies.insert(copy);
  }
  std::vector<DropoutOutcome> out;
  for (const auto& d : params.dropouts) {
    DropoutOutcome o{d.robot, d.at, std::nullopt, 0, 0};
    const TeamAgent& dropped = *agents[static_cast<std::size_t>(d.robot.value)];
    o.stored = dropped.load().stored;
    for (const auto& copy : StoredCopies(dropped)) o.kept += live_copies.count(copy) > 0 ? 1 : 0;
    bool all = true;
    for (std::size_t r = 0; r < agents.size() && all; ++r) {
      if (IsDropped(params, static_cast<int>(r))) continue;
      const auto lost = agents[r]->Lost();
      const auto it = std::find_if(lost.begin(), lost.end(), [&](const LostRobot& l) { return l.robot == d.robot; });
      if (it == lost.end()) all = false;
      else if (!o.detected || it->detected > *o.detected) o.detected = it->detected;
    }
    if (!all) o.detected.reset();
    out.push_back(o);
  }
  return out;
}

// What makes robot r's agent, talking through its transport.
using AgentMaker = std::function<std::unique_ptr<TeamAgent>(RobotId, Transport&, const FrameStream&,
                                                            const GeometricVerifier&)>;

SimRunLog RunTeam(const Dataset& data, const SimRunParams& params, const AgentMaker& make_agent) {
  params.Validate(data);
  const int n = params.robots;
  Simulator sim;
  Network network(sim, n, MakeLinkModel(params.network, n, params.seed), params.network.wire);
  NetworkRecorders recorders(network, params);

  const SequenceSplit split = SplitSequence(static_cast<int>(data.size()), n);
  const GeometricVerifier verifier = PoseOracle(data.trajectory.positions, params.gt_radius_m);
  DecodedMessages decoded;  // shared by the transports: a broadcast is decoded once, not once a robot
  std::vector<std::unique_ptr<SimTransport>> transports;
  std::vector<std::unique_ptr<TeamAgent>> agents;
  SimRunLog log;
  log.robots = n;
  log.capture_time.resize(static_cast<std::size_t>(data.size()));
  for (int r = 0; r < n; ++r) {
    const FrameRange range = split.ranges[static_cast<std::size_t>(r)];
    FrameStream frames{&data.descriptors, range.begin, range.size(), data.fps};
    for (int k = 0; k < range.size(); ++k) log.capture_time[static_cast<std::size_t>(range.begin.value + k)] = frames.TimeOf(k);
    transports.push_back(std::make_unique<SimTransport>(network, NodeId(r), params.start_utime));
    transports.back()->UseBuffers(&network.payload_buffers());
    transports.back()->ShareDecodes(&decoded);
    agents.push_back(make_agent(RobotId(r), *transports.back(), frames, verifier));
  }
  for (auto& agent : agents) agent->Start();
  for (const auto& d : params.dropouts) {
    network.SetOffline(NodeId(d.robot.value), d.at);
    TeamAgent* agent = agents[static_cast<std::size_t>(d.robot.value)].get();
    sim.ScheduleAt(d.at, [agent] { agent->GoOffline(); });
  }
  sim.Run();

  log.events = sim.EventsExecuted();
  log.end = sim.Now();
  for (const auto& agent : agents) {
    log.loads.push_back(agent->load());
    for (const QueryRecord& q : agent->outcomes()) {
      if (!q.Taken()) continue;  // the robot went offline first
      log.verify_requested += q.verify_requested ? 1 : 0;
      log.verify_accepted += q.verify_accepted.value_or(false) ? 1 : 0;
      log.queries.push_back(q);
    }
  }
  network.ForEachPair([&](NodeId src, NodeId dst, const LinkCounters& c) {
    log.links.push_back(PairTraffic{src.value, dst.value, c, recorders.roles.Pair(src.value, dst.value)});
  });
  for (int s = 0; s < n; ++s) log.senders.push_back(network.Sender(NodeId(s)));
  log.roles = recorders.roles.Run();
  log.has_roles = true;
  log.messages = recorders.rows.Rows();
  log.dropouts = DropoutOutcomes(params, agents);
  if (recorders.event_log_file) recorders.event_log_file->Close();
  return log;
}

}  // namespace

SimRunLog RunSimulation(const Dataset& data, const TeamRouting& routing, const SimRunParams& params) {
  params.Validate(data);
  if (routing.num_robots() != params.robots) {
    throw std::invalid_argument("routing strategy built for " + std::to_string(routing.num_robots()) +
                                " robots, run has " + std::to_string(params.robots));
  }
  return RunTeam(data, params, [&](RobotId r, Transport& transport, const FrameStream& frames,
                                   const GeometricVerifier& verifier) -> std::unique_ptr<TeamAgent> {
    return std::make_unique<RobotAgent>(AgentSetup{r, params.robots, params.agent, frames}, transport,
                                        routing.MakeAgentRouting(), verifier);
  });
}

SimRunLog RunBowSimulation(const Dataset& data, const std::vector<BowVector>& vectors, const BowTeamPlan& plan,
                           const SimRunParams& params) {
  params.Validate(data);
  if (plan.robots != params.robots) {
    throw std::invalid_argument("bag-of-words plan built for " + std::to_string(plan.robots) + " robots, run has " +
                                std::to_string(params.robots));
  }
  if (static_cast<Eigen::Index>(vectors.size()) != data.size()) {
    throw std::invalid_argument(std::to_string(vectors.size()) + " BoW vectors for " + std::to_string(data.size()) +
                                " frames");
  }
  return RunTeam(data, params, [&](RobotId r, Transport& transport, const FrameStream& frames,
                                   const GeometricVerifier& verifier) -> std::unique_ptr<TeamAgent> {
    return std::make_unique<BowRobotAgent>(AgentSetup{r, params.robots, params.agent, frames}, transport, plan, vectors,
                                           verifier);
  });
}

SimRunSummary SummarizeSimRun(const SimRunLog& log, const Positions& positions, double radius_m, int window) {
  SimRunSummary s;
  s.truth = ComputeOnlineTruth(log.queries, positions, log.capture_time, radius_m, window);
  std::vector<MatchOutcome> outcomes;
  outcomes.reserve(log.queries.size());
  for (const auto& q : log.queries) {
    MatchOutcome o;
    o.query = q.frame;
    if (q.best) {
      o.match = q.best->frame;
      o.score = q.best->distance;
    }
    outcomes.push_back(o);
  }
  for (bool r : s.truth.relevant) s.relevant += r ? 1 : 0;
  const PrResult pr = EvaluatePr(outcomes, positions, radius_m, s.relevant);
  s.auc = pr.auc;
  s.precision = pr.precision;
  s.recall = pr.recall;
  s.queries = static_cast<std::int64_t>(log.queries.size());
  for (const PairTraffic& pair : log.links) {
    const LinkCounters& c = pair.counters;
    s.messages += static_cast<std::int64_t>(c.messages);
    s.payload_bytes += c.payload_bytes;
    s.wire_bytes += c.wire_bytes;
    s.dropped += static_cast<std::int64_t>(c.dropped);
  }
  for (const auto& c : log.senders) s.medium_bytes += c.medium_bytes;
  s.latency = ComputeLatency(log.queries);
  std::vector<std::int64_t> served;
  for (const auto& l : log.loads) served.push_back(l.searches);
  s.worst_balance_ratio = WorstBalanceRatio(served);
  return s;
}

}  // namespace dvpr
