#include "experiments/sweep/sweep_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "agents/algorithms/ids.h"
#include "agents/messages/team_sync.h"
#include "experiments/domain/strategies/run_placement.h"
#include "experiments/protocols/strategy_inputs.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/sweep/sweep.h"
#include "experiments/sweep/sweep_size.h"
#include "net_models/core/param_checks.h"
#include "net_models/medium/csma_link.h"

namespace dvpr {

namespace {

std::string Robots(const SweepConfig& sweep) {
  std::string s;
  for (const int n : sweep.robots) s += (s.empty() ? "" : ", ") + std::to_string(n);
  return s;
}

// Link overrides (and every other network parameter) hold for a team of n robots if they hold
// for the smallest: a pair lies in every larger team too.
void CheckNetworks(const ExperimentConfig& c, const std::string& origin) {
  if (!AnyProtocol(c.sweep.protocols, &ProtocolTraits::simulated_network)) return;
  const int smallest = *std::min_element(c.sweep.robots.begin(), c.sweep.robots.end());
  for (const NetworkVariant& v : ExpandNetworks(c.network)) {
    try {
      ValidateNested("network.", [&] { v.params.Validate(smallest); });
    } catch (const std::invalid_argument& e) {
      throw ConfigError(origin + ": " + e.what() + " (robots: " + Robots(c.sweep) +
                        "; every team of the sweep runs the same network section)");
    }
  }
}

// The longest a heartbeat (agent_status_t on DVPR_STATUS) takes from its robot to a teammate on
// a network otherwise idle, in a team of `robots`: the propagation latency plus the time to put
// its frames on the link (point_to_point: every pair, its overrides included; shared_medium:
// every robot announces at the same instants, so the last heartbeat waits for all the others on
// the one channel); ideal delivers at once. Traffic queued ahead of it only adds to this.
SimTime WorstHeartbeatDelay(const NetworkModelParams& p, int robots) {
  if (p.model == LinkModelKind::kIdeal) return SimTime::Zero();
  // agent_status_t encoded: LCM's 8-byte type hash + utime 8, robot 2, robots 2, team_key 8,
  // state 1, ready_utime 8, frames_taken 4 (lcmtypes/dvpr/agent_status_t.lcm; this layer may not
  // include the generated type).
  const Bytes payload(41);
  const WireFootprint heartbeat =
      ComputeWireFootprint(payload, static_cast<std::int64_t>(channels::kStatus.size()), WireOf(p));
  const Bytes frames = heartbeat.wire_bytes;
  if (p.model == LinkModelKind::kSharedMedium) return p.latency + p.bandwidth.TxTime(frames) * robots;
  // csma: each teammate's heartbeat holds the bus for its frame and the channel delay, and a
  // station that finds it busy may wait out the longest backoff (1000 slots) before it looks again.
  if (p.model == LinkModelKind::kCsma) {
    return (p.latency + p.bandwidth.TxTime(frames) + CsmaParams::kSlot * CsmaParams::kMaxSlots) * robots;
  }
  // wifi: each teammate's heartbeat, broadcast at the basic rate after DIFS and at most a full
  // first window of backoff (a broadcast is never retried).
  if (p.model == LinkModelKind::kWifi) {
    return (WifiParams::kDifs + WifiParams::kSlot * WifiParams::kCwMin +
            OfdmDuration(heartbeat.largest_frame, p.wifi.basic_rate)) *
           robots;
  }
  SimTime worst = p.latency + p.bandwidth.TxTime(frames);
  for (const LinkOverrideParams& o : p.links) {
    if (o.src.value >= robots || o.dst.value >= robots) continue;
    worst = std::max(worst, o.latency.value_or(p.latency) + o.bandwidth.value_or(p.bandwidth).TxTime(frames));
  }
  return worst;
}

// A robot is declared lost when silent for longer than failover.timeout, checked every
// heartbeat_period. A healthy teammate's heartbeats arrive a period apart plus however much
// later one arrives than the one before, and the first arrives one delay after the start; so a
// timeout shorter than period + the worst delay declares robots lost with nobody gone
// (docs/failover.md). Real agents (dvpr launch) run on a real network, which no config describes.
void CheckFailoverTimeout(const ExperimentConfig& c, const std::string& origin) {
  if (!c.failover.enabled || !AnyProtocol(c.sweep.protocols, &ProtocolTraits::simulated_network)) return;
  for (const NetworkVariant& v : ExpandNetworks(c.network)) {
    for (const int n : c.sweep.robots) {
      const SimTime delay = WorstHeartbeatDelay(v.params, n);
      const SimTime need = c.failover.heartbeat_period + delay;
      if (c.failover.timeout < need) {
        throw ConfigError(origin + ": failover.timeout: must be at least heartbeat_period + the worst delay of a " +
                          "heartbeat (" + FormatDuration(c.failover.heartbeat_period) + " + " + FormatDuration(delay) +
                          " = " + FormatDuration(need) + " on network '" + NetworkName(v.label) + "' with " + std::to_string(n) +
                          " robots), got " + FormatDuration(c.failover.timeout) +
                          "; a shorter one declares robots lost with nobody gone");
      }
    }
  }
}

std::string Fps(double fps) {
  std::ostringstream out;
  out << fps;
  return out.str();
}

// A dropout lies inside the run of every team that has its robot: a run lasts as long as its longest sub-trajectory (frame k at k / fps,
// the run ending one frame after the last), so a later dropout would be reported as a robot lost.
void CheckDropouts(const SharedInputs& in, const std::string& origin) {
  const ExperimentConfig& c = *in.config;
  const auto frames = static_cast<std::int64_t>(in.deployment.size());
  for (std::size_t i = 0; i < c.dropout.size(); ++i) {
    const Dropout& d = c.dropout[i];
    const std::string key = origin + ": dropout[" + std::to_string(i) + "]";
    for (const int n : c.sweep.robots) {
      if (d.robot >= n || frames < n) continue;
      if (const auto& plan = in.Team(n).plan) {  // a planned team: one frame period after its last frame
        const SimTime last = plan->LastCapture(in.deployment.fps);
        const SimTime end = last + SimTime::Nanos(std::llround(1e9 / in.deployment.fps));
        if (d.at >= end) {
          throw ConfigError(key + ".at: " + FormatDuration(d.at) + " is not inside the run of the team plan's " +
                            std::to_string(n) + " robots, which ends at " +
                            FormatDuration(end) + " (its last frame at " + FormatDuration(last) + ")");
        }
        continue;
      }
      const std::int64_t longest = (frames + n - 1) / n;
      const auto end = SimTime::Nanos(static_cast<std::int64_t>(std::ceil(static_cast<double>(longest) / in.deployment.fps * 1e9)));
      if (d.at >= end) {
        throw ConfigError(key + ".at: " + FormatDuration(d.at) + " is not inside the run of " + std::to_string(n) +
                          " robots, which ends at " + FormatDuration(end) + " (" + std::to_string(longest) +
                          " frames at most per robot at " + Fps(in.deployment.fps) + " fps)");
      }
    }
  }
}

// A strategy that reads the training side: its name and index in `strategies`, for messages.
struct TrainingReader {
  std::size_t index = 0;
  const StrategySpec* spec = nullptr;
};

void CheckTrainingDescriptors(const SharedInputs& in, const TrainingReader& s, const TrainingUse& use,
                              const std::string& origin) {
  const ExperimentConfig& c = *in.config;
  const std::string key = origin + ": strategies[" + std::to_string(s.index) + "]: '" + s.spec->name + "' ";
  if (!c.training.run_centroids.centroids_pattern.empty()) {
    if (use.descriptors) {
      throw ConfigError(key + "needs the training descriptors, but training.centroids replaces them "
                        "(drop the strategy or training.centroids)");
    }
    return;
  }
  const int largest = *std::max_element(c.sweep.robots.begin(), c.sweep.robots.end());
  const auto k = static_cast<Eigen::Index>(largest) * use.clusters_per_robot;
  if (in.training.rows() < k) {
    throw ConfigError(key + "clusters the training descriptors into k = " + std::to_string(k) + " (" +
                      std::to_string(largest) + " robots x " + std::to_string(use.clusters_per_robot) +
                      "), but there are only " + std::to_string(in.training.rows()));
  }
}

// Every centroid file the sweep will read, once per clusters-per-robot value.
void CheckCentroidFilesOf(const SharedInputs& in, const std::map<int, TrainingReader>& readers,
                          const std::string& origin) {
  const ExperimentConfig& c = *in.config;
  for (const auto& [clusters, reader] : readers) {
    RunCentroidParams params = c.training.run_centroids;
    params.clusters_per_robot = clusters;
    const std::string strategy =
        clusters != c.training.run_centroids.clusters_per_robot ? " (strategy '" + reader.spec->name + "')" : "";
    try {
      CheckCentroidFiles(params, c.sweep.robots, c.sweep.runs, in.deployment.dim());
    } catch (const std::invalid_argument& e) {  // the file's shape or values
      throw ConfigError(origin + ": training.centroids: " + e.what() + strategy);
    } catch (const std::runtime_error& e) {  // the npy reader
      throw ConfigError(origin + ": training.centroids: " + e.what() + strategy);
    }
  }
}

void CheckStrategies(const SharedInputs& in, const std::string& origin) {
  const ExperimentConfig& c = *in.config;
  const StrategyInputs strategy_inputs = StrategyInputsOf(in);
  std::map<int, TrainingReader> centroid_readers;  // by clusters per robot
  // A re-clustering leader sends its table in a centroid_table_t, whose k is an int16 (the paper
  // protocol evaluates the plan without messages).
  const int largest = *std::max_element(c.sweep.robots.begin(), c.sweep.robots.end());
  const bool sends = AnyProtocol(c.sweep.protocols, &ProtocolTraits::sends_messages);
  for (std::size_t i = 0; i < c.sweep.strategies.size(); ++i) {
    const StrategySpec& spec = c.sweep.strategies[i];
    if (sends && spec.reclusters() && static_cast<std::int64_t>(largest) * spec.clusters_per_robot > kMaxWireInt16) {
      throw ConfigError(origin + ": strategies[" + std::to_string(i) + "]: '" + spec.name + "' sends tables of " +
                        std::to_string(static_cast<std::int64_t>(largest) * spec.clusters_per_robot) + " centroids (" +
                        std::to_string(largest) + " robots x " + std::to_string(spec.clusters_per_robot) +
                        "), but a centroid_table_t carries at most 32767 (its k is an int16 on the wire)");
    }
    const TrainingUse use = TrainingUseOf(spec, strategy_inputs);
    if (!use.run_centroids && !use.descriptors) continue;
    CheckTrainingDescriptors(in, TrainingReader{i, &spec}, use, origin);
    if (use.run_centroids) centroid_readers.try_emplace(use.clusters_per_robot, TrainingReader{i, &spec});
  }
  if (!c.training.run_centroids.centroids_pattern.empty()) CheckCentroidFilesOf(in, centroid_readers, origin);
}

// The bag-of-words strategies run only in the protocols whose traits say so (the static protocol
// and the simulation; docs/bow.md).
void CheckBowProtocols(const ExperimentConfig& c, const std::string& origin) {
  const auto& protocols = c.sweep.protocols;
  const auto other = std::find_if(protocols.begin(), protocols.end(),
                                  [](const std::string& p) { return !TraitsOf(p).bow_strategies; });
  for (std::size_t i = 0; i < c.sweep.strategies.size() && other != protocols.end(); ++i) {
    const StrategySpec& s = c.sweep.strategies[i];
    if (s.bag_of_words()) {
      throw ConfigError(origin + ": strategies[" + std::to_string(i) + "]: '" + s.name + "' runs in the paper and " +
                        "sim protocols only, not in '" + *other + "'; see docs/bow.md");
    }
  }
}

}  // namespace

void CheckSweepInputs(const SharedInputs& inputs, const std::string& origin, bool allow_large, int threads) {
  if (inputs.config == nullptr) throw std::invalid_argument("CheckSweepInputs: the shared inputs have no config");
  // First: the other checks list the network variants, which a hostile config makes too many.
  if (!allow_large) {
    CheckSweepSize(EstimateSweepSize(*inputs.config, inputs.deployment), SweepMachine::ThisOne(threads), origin);
  }
  CheckBowProtocols(*inputs.config, origin);
  CheckNetworks(*inputs.config, origin);
  CheckFailoverTimeout(*inputs.config, origin);
  CheckDropouts(inputs, origin);
  CheckStrategies(inputs, origin);
}

}  // namespace dvpr
