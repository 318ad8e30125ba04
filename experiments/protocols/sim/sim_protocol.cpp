#include "experiments/protocols/sim/sim_protocol.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "agents/decentralized_routing.h"
#include "agents/recluster/recluster_routing.h"
#include "experiments/protocols/sim/simulation.h"
#include "experiments/data/split.h"
#include "experiments/protocols/paper/static_recluster.h"
#include "experiments/strategies/strategy_catalogue.h"

namespace dvpr {

namespace {

LossParams ToLossParams(const LossConfig& c) {
  LossParams p;
  switch (c.model) {
    case LossModel::kNone: p.model = LossModelKind::kNone; break;
    case LossModel::kBernoulli:
      p.model = LossModelKind::kBernoulli;
      p.bernoulli.p = c.p;
      break;
    case LossModel::kGilbertElliott:
      p.model = LossModelKind::kGilbertElliott;
      p.gilbert_elliott = {c.p_good_to_bad, c.p_bad_to_good, c.loss_good, c.loss_bad};
      break;
  }
  return p;
}

LinkModelKind ToKind(NetworkModel m) {
  switch (m) {
    case NetworkModel::kIdeal: return LinkModelKind::kIdeal;
    case NetworkModel::kPointToPoint: return LinkModelKind::kPointToPoint;
    case NetworkModel::kSharedMedium: return LinkModelKind::kSharedMedium;
  }
  throw std::logic_error("unknown network model");
}

SimRunParams ToSimParams(const ExperimentConfig& c, const RunSpec& spec) {
  SimRunParams p;
  p.robots = spec.robots;
  p.seed = spec.seed;
  p.agent = ToAgentParams(c);
  p.network = ToNetworkModelParams(spec.network->settings);
  p.gt_radius_m = c.evaluation.gt_radius_m;
  // A dropout applies to the teams that have that robot.
  for (const Dropout& d : c.dropout) {
    if (d.robot < spec.robots) p.dropouts.push_back({RobotId(d.robot), d.at});
  }
  p.record_messages = c.outputs.messages;
  return p;
}

std::string LogName(const RunSpec& spec, const std::string& strategy) {
  return "sim_" + strategy + "_n" + std::to_string(spec.robots) + "_r" + std::to_string(spec.run) + "_v" +
         std::to_string(spec.network->index) + ".lcmlog";
}

// Adaptive re-clustering (agents/recluster/recluster_routing.h): the team's plan for this run.
// The leader waits half a period for the samples.
std::unique_ptr<TeamRouting> MakeReclusterRouting(const StrategySpec& s, std::shared_ptr<const CentroidTable> initial,
                                                      const Dataset& data, std::uint64_t config_seed,
                                                      const RunSpec& spec) {
  ReclusterPlan plan;
  plan.params = ReclusterParamsOf(s, config_seed, spec.robots, spec.run);
  plan.initial = std::move(initial);
  const SequenceSplit split = SplitSequence(static_cast<int>(data.size()), spec.robots);
  int longest = 0;
  for (const FrameRange& r : split.ranges) {
    plan.stream_first.push_back(r.begin);
    longest = std::max(longest, r.size());
  }
  plan.epochs = ReclusterEpochs(longest, plan.params);
  plan.sample_timeout = SimTime::Seconds(0.5 * plan.params.period / data.fps);
  return std::make_unique<ReclusterRouting>(std::move(plan));
}

}  // namespace

void AppendRows(const RunSpec& spec, const std::string& strategy, const SimRunLog& log, const SimRunSummary& s,
                const ExperimentConfig& c, RunOutput& out) {
  const RunKey key = spec.Key(strategy);
  for (int r = 0; r < log.robots; ++r) {
    const RobotLoad& l = log.loads[static_cast<std::size_t>(r)];
    RobotLoadRow row;
    row.key = key;
    row.robot = r;
    row.queries_received = l.searches;
    row.comparisons = l.comparisons;
    row.stored = l.stored;
    row.busy_fraction = log.end.ns() > 0 ? static_cast<double>(l.busy.ns()) / static_cast<double>(log.end.ns()) : 0.0;
    row.max_queue = l.max_queue;
    out.per_robot.push_back(row);
    for (int d = 0; d < log.robots; ++d) {
      const LinkCounters& lc = log.links[static_cast<std::size_t>(r * log.robots + d)];
      if (lc.messages == 0) continue;
      out.links.push_back(LinkRow{key, r, d, static_cast<std::int64_t>(lc.messages), lc.payload_bytes, lc.wire_bytes,
                                  static_cast<std::int64_t>(lc.dropped)});
    }
  }
  if (c.outputs.queries) {
    for (std::size_t i = 0; i < log.queries.size(); ++i) {
      const QueryRecord& q = log.queries[i];
      QueryRow row;
      row.key = key;
      row.robot = q.robot.value;
      row.frame = q.frame.value;
      row.sent_ns = q.sent.ns();
      if (q.best) {
        row.match_robot = q.best->robot.value;
        row.match_frame = q.best->frame.value;
        row.distance = q.best->distance;
      }
      if (q.latency) row.latency_ns = q.latency->ns();
      row.relevant = s.truth.relevant[i];
      row.correct = s.truth.correct[i];
      out.queries.push_back(row);
    }
  }
  for (MessageRow m : log.messages) {
    m.key = key;
    out.messages.push_back(std::move(m));
  }
}

RunResult MakeRow(const RunSpec& spec, const std::string& strategy, const SimRunSummary& s, double reference_auc) {
  RunResult row;
  row.key = spec.Key(strategy);
  row.seed = spec.seed;
  row.auc = s.auc;
  row.auc_reference = reference_auc;
  row.relative_auc = RelativeAuc(s.auc, reference_auc);
  row.worst_balance_ratio = s.worst_balance_ratio;
  row.queries = s.queries;
  row.messages = s.messages;
  row.payload_bytes = s.payload_bytes;
  // What went on the air or the wires: a shared-medium broadcast counts once.
  row.wire_bytes = s.medium_bytes;
  row.bytes_per_query = s.queries > 0 ? static_cast<double>(s.medium_bytes) / static_cast<double>(s.queries) : 0.0;
  if (s.latency.complete > 0) {
    row.mean_latency_ms = s.latency.mean_ms;
    row.p99_latency_ms = s.latency.p99_ms;
  }
  row.dropped_messages = s.dropped;
  return row;
}

AgentParams ToAgentParams(const ExperimentConfig& c) {
  AgentParams p;
  p.suppression_frames = c.evaluation.suppression_frames;
  p.service_fixed = c.service.fixed;
  p.service_per_comparison = c.service.per_comparison;
  p.verify_service = c.service.fixed;
  p.verify_max_distance = static_cast<float>(c.verification.max_distance);
  p.verify_request_bytes = static_cast<int>(c.verification.request_bytes.value());
  return p;
}

RunCentroidParams CentroidParams(const ExperimentConfig& c) {
  RunCentroidParams p;
  p.seed = c.seed;
  p.clusters_per_robot = c.training.clusters_per_robot;
  p.centroids_pattern = c.training.centroids.value_or("");
  return p;
}

NetworkModelParams ToNetworkModelParams(const NetworkSettings& settings) {
  NetworkModelParams p;
  p.model = ToKind(settings.model);
  p.bandwidth = settings.bandwidth;
  p.latency = settings.latency;
  p.queue_packets = settings.queue_packets;
  p.wire.mtu = settings.mtu;
  p.loss = ToLossParams(settings.loss);
  for (const LinkOverride& o : settings.links) {
    LinkOverrideParams lp;
    lp.src = NodeId(o.src);
    lp.dst = NodeId(o.dst);
    lp.bandwidth = o.bandwidth;
    lp.latency = o.latency;
    if (o.loss) lp.loss = ToLossParams(*o.loss);
    p.links.push_back(lp);
  }
  return p;
}

std::unique_ptr<RoutingStrategy> MakeStrategy(const std::string& name, std::shared_ptr<const CentroidTable> table,
                                              int robots) {
  if (name == "broadcast") return std::make_unique<BroadcastRouting>(robots);
  if (name == "decentralized") return std::make_unique<DecentralizedRouting>(std::move(table));
  // Catalogued routings over the paper's table (issue 8); load-balanced tables are built per run.
  if (const StrategySpec* s = FindStrategySpec(name); s && s->table == StrategySpec::Table::kPaper) {
    return MakeSpecRouting(*s, std::move(table));
  }
  throw std::invalid_argument("strategies: '" + name + "' has no simulation form");
}

RunFunction MakeSimRun(const SharedInputs& in) {
  const ExperimentConfig* config = in.config;
  const Dataset* data = &in.deployment;
  const DescriptorMatrix* training = &in.training;
  std::filesystem::path log_dir;
  if (config->outputs.lcm_log) {
    log_dir = in.out_dir / "lcm";
    std::filesystem::create_directories(log_dir);
  }
  const RunCentroidParams centroid_params = CentroidParams(*config);
  return [config, data, training, log_dir, centroid_params](const RunSpec& spec) {
    auto table = std::make_shared<const CentroidTable>(
        CentroidTable::RoundRobin(RunCentroids(*training, centroid_params, spec.robots, spec.run), spec.robots));
    SimRunParams params = ToSimParams(*config, spec);
    const auto run_one = [&](const std::string& strategy) {
      params.lcm_log = log_dir.empty() ? std::filesystem::path() : log_dir / LogName(spec, strategy);
      const StrategySpec* own_table = FindStrategySpec(strategy);
      if (own_table && own_table->table == StrategySpec::Table::kPaper) own_table = nullptr;
      std::unique_ptr<TeamRouting> routing;
      if (own_table) {
        auto own = BuildStrategyTable(*own_table, *training, data->descriptors, centroid_params, spec.robots, spec.run);
        routing = own_table->recluster_period > 0
                      ? MakeReclusterRouting(*own_table, std::move(own), *data, centroid_params.seed, spec)
                      : MakeSpecRouting(*own_table, std::move(own));
      } else {
        routing = MakeStrategy(strategy, table, spec.robots);
      }
      SimRunLog log = RunSimulation(*data, *routing, params);
      SimRunSummary summary = SummarizeSimRun(log, data->trajectory.positions, config->evaluation.gt_radius_m,
                                              config->evaluation.suppression_frames);
      return std::make_pair(std::move(log), std::move(summary));
    };
    // Broadcast first: it is the reference of every strategy's relative AUC.
    RunOutput out;
    const auto& wanted = spec.strategies;
    auto [broadcast_log, broadcast] = run_one("broadcast");
    for (const std::string& strategy : wanted) {
      if (strategy == "broadcast") {
        out.runs.push_back(MakeRow(spec, strategy, broadcast, broadcast.auc));
        AppendRows(spec, strategy, broadcast_log, broadcast, *config, out);
        continue;
      }
      auto [log, summary] = run_one(strategy);
      out.runs.push_back(MakeRow(spec, strategy, summary, broadcast.auc));
      AppendRows(spec, strategy, log, summary, *config, out);
    }
    return out;
  };
}

}  // namespace dvpr
