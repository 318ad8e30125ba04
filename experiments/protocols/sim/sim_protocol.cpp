#include "experiments/protocols/sim/sim_protocol.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "experiments/domain/evaluation/metrics.h"
#include "experiments/domain/strategies/run_placement.h"
#include "experiments/protocols/sim/simulation.h"
#include "experiments/protocols/strategy_inputs.h"
#include "net_models/core/param_checks.h"

namespace dvpr {

namespace {

// The run's scenario (physics) from the config and the spec, then what it measures and writes.
SimRunParams ToSimParams(const ExperimentConfig& c, const RunSpec& spec) {
  SimRunParams p;
  ScenarioParams& s = p.scenario;
  s.robots = spec.robots;
  s.seed = spec.seed;
  s.agent = c.agent;
  s.network = spec.network->params;
  // Whether the links lie in this team is known only now; the error names the config key.
  ValidateNested("network.", [&] { s.network.Validate(spec.robots); });
  // A dropout applies to the teams that have that robot.
  for (const Dropout& d : c.dropout) {
    if (d.robot < spec.robots) s.dropouts.push_back({RobotId(d.robot), d.at});
  }
  // So do the talk windows (network.schedule; ReadTalkSchedule sorted them by robot and start).
  for (const ScheduledWindow& w : c.network.windows) {
    if (w.robot >= spec.robots) continue;
    if (s.talk_windows.empty() || s.talk_windows.back().robot != RobotId(w.robot)) {
      s.talk_windows.push_back({RobotId(w.robot), {}});
    }
    s.talk_windows.back().windows.push_back(w.window);
  }
  s.start_utime = c.start_utime;
  p.evaluation.gt_radius_m = c.evaluation.radius_m;
  p.outputs.record_messages = c.outputs.messages;
  p.outputs.hop_counts = s.network.model == LinkModelKind::kRadio;  // radio.csv
  // queries.csv has its hops column when a variant of the sweep is a radio, for every row.
  p.outputs.query_hops = c.outputs.queries && std::count(c.network.model.begin(), c.network.model.end(),
                                                         LinkModelKind::kRadio) > 0;
  // One step per frame period, as the robots move between frames (FrameStream::TimeOf(1)).
  if (c.outputs.connectivity && s.network.model == LinkModelKind::kRadio) {
    p.outputs.connectivity_step = SimTime::Nanos(std::llround(1e9 / c.dataset.fps));
  }
  return p;
}

// The simulated network counted bytes by role; real agents' logs (lcm protocol) have none.
// Also how long the robots drove: the last frame's capture time plus one frame period.
RunResult WithRoles(RunResult row, const SimRunLog& log, double fps) {
  if (log.has_roles) row.roles = log.roles;
  SimTime last = SimTime::Zero();
  for (const SimTime t : log.capture_time) last = std::max(last, t);
  row.duration_s = static_cast<double>(last.ns()) * 1e-9 + 1.0 / fps;
  return row;
}

// radio.csv's row: the run's hops, relaying and drops by reason (kRadioDropReasons follows
// DropReason's order after kNone).
RadioRow RadioRowOf(const RunKey& key, const SimRunLog& log) {
  static_assert(kRadioDropReasons.size() + 1 == kDropReasons);
  RadioRow row;
  row.key = key;
  const RouteCounters& routes = log.routes;
  row.delivered_copies = static_cast<std::int64_t>(routes.delivered);
  if (routes.delivered > 0) {
    row.mean_hops = static_cast<double>(routes.delivered_hops) / static_cast<double>(routes.delivered);
  }
  row.max_hops = routes.max_hops;
  row.delivered_by_hops = log.delivered_by_hops;
  row.held_copies = static_cast<std::int64_t>(routes.held);
  for (const NodeCounters& s : log.senders) {
    row.relay_transmissions += static_cast<std::int64_t>(s.relay_transmissions);
    row.relay_bytes += s.relay_bytes;
    row.routing_transmissions += static_cast<std::int64_t>(s.routing_transmissions);
    row.routing_bytes += s.routing_bytes;
  }
  for (std::size_t i = 0; i < row.dropped.size(); ++i) {
    row.dropped[i] = static_cast<std::int64_t>(routes.dropped[i + 1]);
  }
  return row;
}

// medium.csv's row: what the medium access of a contending variant did in the run.
MediumRow MediumRowOf(const RunKey& key, const SimRunLog& log) {
  MediumRow row;
  row.key = key;
  row.delivered_copies = static_cast<std::int64_t>(log.routes.delivered);
  SimTime airtime;
  for (const MacCounters& m : log.mac) {
    row.attempts += static_cast<std::int64_t>(m.attempts);
    row.backoffs += static_cast<std::int64_t>(m.backoffs);
    row.collisions += static_cast<std::int64_t>(m.collisions);
    row.retries += static_cast<std::int64_t>(m.retries);
    airtime += m.airtime;
  }
  row.airtime_ns = airtime.ns();
  row.busy_ns = log.medium_busy.ns();
  if (log.end.ns() > 0) row.utilisation = static_cast<double>(row.busy_ns) / static_cast<double>(log.end.ns());
  for (std::size_t i = 0; i < row.dropped.size(); ++i) {
    row.dropped[i] = static_cast<std::int64_t>(log.routes.dropped[i + 1]);
  }
  return row;
}

std::string LogName(const RunSpec& spec, const std::string& strategy) {
  return "sim_" + strategy + "_n" + std::to_string(spec.robots) + "_r" + std::to_string(spec.run) + "_v" +
         std::to_string(spec.network->index) + ".lcmlog";
}

}  // namespace

void AppendRows(const RunSpec& spec, const std::string& strategy, const SimRunLog& log, const SimRunSummary& s,
                const ExperimentConfig& c, RunOutput& out) {
  const RunKey key = spec.Key(strategy);
  std::size_t next_link = 0;  // log.links is sorted by source
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
    const NodeCounters& sent = log.senders[static_cast<std::size_t>(r)];
    row.relay_transmissions = static_cast<std::int64_t>(sent.relay_transmissions);
    row.relay_bytes = sent.relay_bytes;
    row.routing_transmissions = static_cast<std::int64_t>(sent.routing_transmissions);
    row.routing_bytes = sent.routing_bytes;
    if (static_cast<std::size_t>(r) < log.mac.size()) {
      const MacCounters& m = log.mac[static_cast<std::size_t>(r)];
      row.mac_attempts = static_cast<std::int64_t>(m.attempts);
      row.mac_backoffs = static_cast<std::int64_t>(m.backoffs);
      row.mac_collisions = static_cast<std::int64_t>(m.collisions);
      row.mac_retries = static_cast<std::int64_t>(m.retries);
      row.mac_dropped_queue_full = static_cast<std::int64_t>(m.dropped_queue_full);
      row.mac_dropped_retry_limit = static_cast<std::int64_t>(m.dropped_retry_limit);
      if (log.end.ns() > 0) {
        row.airtime_share = static_cast<double>(m.airtime.ns()) / static_cast<double>(log.end.ns());
      }
    }
    out.per_robot.push_back(row);
    for (; next_link < log.links.size() && log.links[next_link].src == r; ++next_link) {
      const PairTraffic& pair = log.links[next_link];
      const LinkCounters& lc = pair.counters;
      if (lc.messages == 0) continue;
      out.links.push_back(LinkRow{key, r, pair.dst, static_cast<std::int64_t>(lc.messages), lc.payload_bytes,
                                  lc.wire_bytes, static_cast<std::int64_t>(lc.dropped),
                                  log.has_roles ? std::optional<RoleCopyBytes>(pair.roles) : std::nullopt});
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
      row.query_class = QueryClassName(s.truth.query_class[i]);
      if (i < log.query_hops.size()) row.hops = log.query_hops[i];
      out.queries.push_back(row);
    }
  }
  for (MessageRow m : log.messages) {
    m.key = key;
    out.messages.push_back(std::move(m));
  }
  for (const PairClosure& p : s.closures.pairs) {
    std::optional<std::int64_t> first;
    if (p.first) first = p.first->ns();
    out.closure_pairs.push_back(ClosurePairRow{key, p.a.value, p.b.value, first});
  }
  if (spec.network != nullptr && spec.network->params.model == LinkModelKind::kRadio) {
    out.radio.push_back(RadioRowOf(key, log));
  }
  if (spec.network != nullptr && Contends(spec.network->params.model)) out.medium.push_back(MediumRowOf(key, log));
  for (const DropoutOutcome& d : log.dropouts) {
    std::optional<std::int64_t> detected;
    if (d.detected) detected = d.detected->ns();
    out.failover.push_back(FailoverRow{key, d.robot.value, d.at.ns(), detected, d.stored, d.kept, s.latency.incomplete});
  }
  for (const ConnectivitySnapshot& c : log.connectivity) {
    out.connectivity.push_back(ConnectivityRow{key, c.at.ns(), c.pairs_in_range, c.components, c.largest_component,
                                               c.mean_hops, c.max_hops, c.in_range});
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
  const ClosureStats& cl = s.closures;
  RunClosures& c = row.closures.emplace();
  c.inter_queries = cl.inter_queries;
  c.intra_queries = cl.intra_queries;
  c.inter_recognised = cl.inter_recognised;
  c.intra_recognised = cl.intra_recognised;
  if (cl.inter_queries > 0) c.inter_auc = cl.inter_auc;
  if (cl.intra_queries > 0) c.intra_auc = cl.intra_auc;
  c.inter_candidates = cl.inter_candidates;
  c.inter_closures = cl.inter_closures;
  for (const PairClosure& p : cl.pairs) c.pairs_closed += p.first ? 1 : 0;
  if (const std::optional<SimTime> median = MedianFirstClosure(cl.pairs)) c.median_first_closure_ns = median->ns();
  return row;
}

RunFunction MakeSimRun(const SharedInputs& in) {
  const ExperimentConfig* config = in.config;
  const SharedInputs* inputs = &in;
  const BowData* bow = &in.bow;
  std::filesystem::path log_dir;
  if (config->outputs.lcm_log) {
    log_dir = in.out_dir / "lcm";
    std::filesystem::create_directories(log_dir);
  }
  return [config, inputs, bow, log_dir](const RunSpec& spec) {
    SimRunParams params = ToSimParams(*config, spec);
    const Dataset* data = &inputs->Team(spec.robots);  // a plan swept over team sizes: this run's team
    // Its cache is the sweep's: each (robots, run) clusters once for every protocol and variant.
    const StrategyInputs run_inputs = StrategyInputsOf(*inputs, spec.robots);
    const auto run_one = [&](const StrategySpec& strategy) {
      params.outputs.lcm_log = log_dir.empty() ? std::filesystem::path() : log_dir / LogName(spec, strategy.name);
      const RunPlacement routing = BuildRunPlacement(strategy, run_inputs, spec.robots, spec.run);
      SimRunLog log = routing.Visit(
          [&](const BowFamily& f) { return RunBowSimulation(*data, bow->frames, f.team, params); },
          [&](const auto& descriptor) { return RunSimulation(*data, *descriptor.team, params); });
      SimRunSummary summary = SummarizeSimRun(log, data->trajectory.positions, config->evaluation.radius_m,
                                              SuppressionWindow(*data, config->evaluation.suppression_frames));
      return std::make_pair(std::move(log), std::move(summary));
    };
    // The references first: broadcast for the descriptor strategies' relative AUC, the BoW team's
    // centralized server (bow_centralized, docs/bow.md) for the bow_ strategies'. Each runs only
    // when a strategy of its kind does.
    using Team = std::pair<SimRunLog, SimRunSummary>;
    const auto any = [&](bool bag_of_words) {
      return std::any_of(spec.strategies.begin(), spec.strategies.end(),
                         [&](const StrategySpec& s) { return s.bag_of_words() == bag_of_words; });
    };
    std::optional<Team> broadcast, bow_reference;
    if (any(false)) broadcast = run_one(ParseStrategy("broadcast"));
    if (any(true)) bow_reference = run_one(ParseStrategy("bow_centralized"));
    RunOutput out;
    for (const StrategySpec& strategy : spec.strategies) {
      const Team& reference = strategy.bag_of_words() ? *bow_reference : *broadcast;
      const double reference_auc = reference.second.auc;
      if (strategy.broadcast() || strategy.bow == StrategySpec::Bow::kCentralized) {
        out.runs.push_back(WithRoles(MakeRow(spec, strategy.name, reference.second, reference_auc), reference.first,
                                     data->fps));
        AppendRows(spec, strategy.name, reference.first, reference.second, *config, out);
        continue;
      }
      auto [log, summary] = run_one(strategy);
      out.runs.push_back(WithRoles(MakeRow(spec, strategy.name, summary, reference_auc), log, data->fps));
      AppendRows(spec, strategy.name, log, summary, *config, out);
    }
    return out;
  };
}

}  // namespace dvpr
