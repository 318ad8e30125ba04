#include "experiments/protocols/sim/simulation.h"

#include <algorithm>
#include <functional>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>

#include "agents/algorithms/ids.h"
#include "experiments/domain/evaluation/metrics.h"
#include "experiments/protocols/sim/event_log_recorder.h"
#include "experiments/protocols/sim/hop_counts.h"
#include "experiments/protocols/sim/message_roles.h"
#include "experiments/protocols/sim/message_rows.h"
#include "experiments/protocols/sim/pose_oracle.h"
#include "experiments/protocols/sim/query_hops.h"
#include "experiments/results/lcm_log/lcm_event_log.h"

namespace dvpr {

namespace {

// What a run records of its network: its bytes by role always; as the outputs ask,
// messages.csv rows, the queries' hops and an LCM event log. Subscribed to the scenario's
// network before it runs.
struct RunRecorders {
  RunRecorders(Network& network, const SimRunParams& params)
      : roles(network.nodes()), roles_subscription(network.Subscribe(roles)) {
    if (params.outputs.record_messages) rows_subscription = network.Subscribe(rows);
    if (params.outputs.hop_counts) hop_counts_subscription = network.Subscribe(hop_counts);
    if (params.outputs.query_hops) {
      query_hops = std::make_unique<QueryHopsRecorder>();
      query_hops_subscription = network.Subscribe(*query_hops);
    }
    if (!params.outputs.lcm_log.empty()) {
      event_log_file = std::make_unique<LcmEventLogWriter>(params.outputs.lcm_log);
      event_log = std::make_unique<EventLogRecorder>(*event_log_file, params.scenario.start_utime);
      event_log_subscription = network.Subscribe(*event_log);
    }
  }
  RoleBytesRecorder roles;
  ObserverSubscription roles_subscription;
  MessageRowRecorder rows;
  ObserverSubscription rows_subscription;
  HopCountRecorder hop_counts;
  ObserverSubscription hop_counts_subscription;
  std::unique_ptr<QueryHopsRecorder> query_hops;
  ObserverSubscription query_hops_subscription;
  std::unique_ptr<LcmEventLogWriter> event_log_file;
  std::unique_ptr<EventLogRecorder> event_log;
  ObserverSubscription event_log_subscription;
};

// The (robot that saw it, frame) of every descriptor an agent stores whole
// (TeamAgent::WholeFramesStored: a BoW agent lists none).
std::vector<std::pair<int, int>> StoredCopies(const TeamAgent& agent) {
  std::vector<std::pair<int, int>> out;
  for (const IndexEntry& e : agent.WholeFramesStored()) out.emplace_back(e.robot.value, e.frame.value);
  return out;
}

// Per dropout: what its store held, how much of it a robot that stayed keeps a copy of, and
// when the last robot that stayed declared it lost.
std::vector<DropoutOutcome> DropoutOutcomes(const Scenario& scenario) {
  const auto& agents = scenario.agents();
  const auto stayed = [&](std::size_t r) { return !scenario.IsDropped(RobotId(static_cast<int>(r))); };
  std::set<std::pair<int, int>> live_copies;  // (robot that saw it, frame)
  for (std::size_t r = 0; r < agents.size(); ++r) {
    if (!stayed(r)) continue;
    for (const auto& copy : StoredCopies(*agents[r])) live_copies.insert(copy);
  }
  std::vector<DropoutOutcome> out;
  for (const auto& d : scenario.params().dropouts) {
    DropoutOutcome o{d.robot, d.at, std::nullopt, 0, 0};
    const TeamAgent& dropped = *agents[static_cast<std::size_t>(d.robot.value)];
    o.stored = dropped.load().stored;
    for (const auto& copy : StoredCopies(dropped)) o.kept += live_copies.count(copy) > 0 ? 1 : 0;
    bool all = true;
    for (std::size_t r = 0; r < agents.size() && all; ++r) {
      if (!stayed(r)) continue;
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

// The log of a scenario that has run: what each agent recorded and served, what the network
// counted and the recorders kept.
SimRunLog Harvest(const Scenario& scenario, const RunRecorders& recorders) {
  const Network& network = scenario.network();
  SimRunLog log;
  log.robots = scenario.params().robots;
  log.capture_time = scenario.CaptureTimes();
  log.taker = scenario.split().owner;
  log.events = scenario.simulator().EventsExecuted();
  log.end = scenario.simulator().Now();
  for (const auto& agent : scenario.agents()) {
    log.loads.push_back(agent->load());
    for (const QueryRecord& q : agent->outcomes()) {
      if (!q.Taken()) continue;  // the robot went offline first
      log.verify_requested += q.verify_requested ? 1 : 0;
      log.verify_accepted += q.verify_accepted.value_or(false) ? 1 : 0;
      log.queries.push_back(q);
      if (recorders.query_hops) log.query_hops.push_back(recorders.query_hops->HopsOf(q));
    }
  }
  network.ForEachPair([&](NodeId src, NodeId dst, const LinkCounters& c) {
    log.links.push_back(PairTraffic{src.value, dst.value, c, recorders.roles.Pair(src.value, dst.value)});
  });
  for (int s = 0; s < log.robots; ++s) log.senders.push_back(network.Sender(NodeId(s)));
  const std::span<const MacCounters> mac = network.link().Mac();
  log.mac.assign(mac.begin(), mac.end());
  log.medium_busy = network.link().MediumBusy();
  log.routes = network.Routes();
  log.delivered_by_hops = recorders.hop_counts.by_hops();
  log.roles = recorders.roles.Run();
  log.has_roles = true;
  log.messages = recorders.rows.Rows();
  log.dropouts = DropoutOutcomes(scenario);
  return log;
}

// What makes robot r's agent, talking through its transport, verifying with the run's oracle.
using AgentMaker = std::function<std::unique_ptr<TeamAgent>(const AgentSetup&, Transport&, const GeometricVerifier&)>;

// The scenario of params.scenario with the evaluation and the outputs attached: agents verify
// against the ground-truth poses (PoseOracle), the recorders hear the network.
SimRunLog RunTeam(const Dataset& data, const SimRunParams& params, const AgentMaker& make_agent) {
  const GeometricVerifier verifier = PoseOracle(data.trajectory.positions, params.evaluation.gt_radius_m);
  Scenario scenario(data, params.scenario, [&](const AgentSetup& setup, Transport& transport) {
    return make_agent(setup, transport, verifier);
  });
  RunRecorders recorders(scenario.network(), params);
  scenario.Run();
  SimRunLog log = Harvest(scenario, recorders);
  if (params.outputs.connectivity_step > SimTime::Zero()) {
    // The run's own propagation over the positions its network used; from 0 to the last frame.
    const SimTime last = *std::max_element(log.capture_time.begin(), log.capture_time.end());
    log.connectivity = ConnectivityOver(scenario.network().propagation(), log.robots, params.outputs.connectivity_step, last);
  }
  if (recorders.event_log_file) recorders.event_log_file->Close();
  return log;
}

}  // namespace

SimRunLog RunSimulation(const Dataset& data, const TeamPlacement& routing, const SimRunParams& params) {
  params.Validate(data);
  if (routing.num_robots() != params.scenario.robots) {
    throw std::invalid_argument("routing strategy built for " + std::to_string(routing.num_robots()) +
                                " robots, run has " + std::to_string(params.scenario.robots));
  }
  return RunTeam(data, params, [&](const AgentSetup& setup, Transport& transport,
                                   const GeometricVerifier& verifier) -> std::unique_ptr<TeamAgent> {
    return std::make_unique<RobotAgent>(setup, transport, routing.MakeAgentPlacement(), verifier);
  });
}

SimRunLog RunBowSimulation(const Dataset& data, const std::vector<BowVector>& vectors, const BowTeamPlan& plan,
                           const SimRunParams& params) {
  params.Validate(data);
  if (plan.robots != params.scenario.robots) {
    throw std::invalid_argument("bag-of-words plan built for " + std::to_string(plan.robots) + " robots, run has " +
                                std::to_string(params.scenario.robots));
  }
  if (static_cast<Eigen::Index>(vectors.size()) != data.size()) {
    throw std::invalid_argument(std::to_string(vectors.size()) + " BoW vectors for " + std::to_string(data.size()) +
                                " frames");
  }
  return RunTeam(data, params, [&](const AgentSetup& setup, Transport& transport,
                                   const GeometricVerifier& verifier) -> std::unique_ptr<TeamAgent> {
    return std::make_unique<BowRobotAgent>(setup, transport, plan, vectors, verifier);
  });
}

SimRunSummary SummarizeSimRun(const SimRunLog& log, const Positions& positions, double radius_m,
                              const FrameWindow& window) {
  SimRunSummary s;
  s.truth = ComputeOnlineTruth(log.queries, positions, log.capture_time, log.taker, radius_m, window);
  std::vector<MatchOutcome> outcomes;
  outcomes.reserve(log.queries.size());
  for (const auto& q : log.queries) outcomes.push_back(OutcomeOf(q));
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
  s.closures = ComputeClosures(log.queries, s.truth, positions, log.taker, radius_m, log.robots);
  return s;
}

}  // namespace dvpr
