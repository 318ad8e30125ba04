#include "experiments/protocols/lcm/agent_process.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>

#include "agents/algorithms/ids.h"
#include "agents/auth/message_auth.h"
#include "agents/auth/team_secret.h"
#include "agents/bow_robot_agent.h"
#include "agents/lcm/lcm_transport.h"
#include "agents/messages/channels.h"
#include "agents/messages/team_sync.h"
#include "agents/robot_agent.h"
#include "agents/udpm/udpm_url.h"
#include "experiments/config/option_reader.h"
#include "experiments/domain/data/split.h"
#include "experiments/domain/strategies/run_centroids.h"
#include "experiments/domain/strategies/run_placement.h"
#include "experiments/protocols/inputs.h"
#include "experiments/protocols/lcm/agent_log.h"
#include "experiments/protocols/lcm/emulated_range.h"
#include "experiments/protocols/sim/pose_oracle.h"
#include "experiments/protocols/sim/sim_protocol.h"
#include "experiments/protocols/strategy_inputs.h"
#include "lcmtypes/channels/channels.h"
#include "net_models/core/wire_format.h"

namespace dvpr {

void AgentProcessOptions::Validate() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument(what); };
  if (config.empty()) fail("--config is required");
  if (robot < 0) fail("--robot is required (0..robots-1)");
  if (robots && *robots < 2) fail("--robots must be at least 2, got " + std::to_string(*robots));
  if (robots && robot >= *robots) fail("--robot " + std::to_string(robot) + " is not in a team of " + std::to_string(*robots));
  if (run < 0) fail("--run must be >= 0");
  CheckLcmUrl(lcm_url);
  CheckSpeedup(speedup);
  CheckWallSeconds("--grace", grace_s, 0, false);
  CheckWallSeconds("--barrier-timeout", barrier_timeout_s, 0, true);
  if (team_secret.empty()) {
    fail("--team-secret is required: a file with the team's secret, 64 hexadecimal digits readable by its owner "
         "only (dvpr launch makes one for each launch; docs/security.md)");
  }
  CheckHoldBytes(hold_bytes);
}

void CheckHoldBytes(std::int64_t bytes) {
  if (bytes < kMinHoldBytes || bytes > kMaxHoldBytes) {
    throw std::invalid_argument("--hold-bytes must be a number of bytes in [" + std::to_string(kMinHoldBytes) + ", " +
                                std::to_string(kMaxHoldBytes) + "], got " + std::to_string(bytes));
  }
}

static_assert(wire::kTeamTrailer == static_cast<std::int64_t>(auth::kTrailerBytes),
              "the wire model's team trailer is the authentication trailer");

namespace {

// A flag's value as the user would write it: 100000, 1e+308, nan (FormatDouble is for CSV cells).
std::string Shown(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}

}  // namespace

void CheckSpeedup(double speedup) {
  if (!(speedup > 0.0 && speedup <= kMaxSpeedup)) {
    throw std::invalid_argument("--speedup must be a number in (0, " + Shown(kMaxSpeedup) + "], got " + Shown(speedup));
  }
}

void CheckWallSeconds(const char* flag, double seconds, double low, bool low_open) {
  const bool above = low_open ? seconds > low : seconds >= low;
  if (!(above && seconds <= kMaxWallSeconds)) {
    throw std::invalid_argument(std::string(flag) + " must be a number of seconds in " + (low_open ? "(" : "[") +
                                Shown(low) + ", " + Shown(kMaxWallSeconds) + "], got " + Shown(seconds));
  }
}

void CheckLcmUrl(const std::string& url) {
  try {
    udpm::ParseUrl(url);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--lcm: ") + e.what());
  }
}

std::uint64_t ParseTeamNonce(const std::string& text) {
  std::uint64_t v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v, 16);
  if (text.empty() || text.size() > 16 || r.ec != std::errc() || r.ptr != text.data() + text.size()) {
    throw std::invalid_argument("--team-nonce: expected 1 to 16 hexadecimal digits, got '" + text + "'");
  }
  return v;
}

std::string TeamNonceText(std::uint64_t nonce) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(nonce));
  return text;
}

void FitTeamSize(std::int64_t robots, Dataset& data) {
  const std::int64_t frames = data.size();
  if (robots < 2 || robots > frames || robots > kMaxWireInt16) {
    throw std::invalid_argument("--robots: " + std::to_string(robots) + " robots for " + std::to_string(frames) +
                                " frames (at least 2, at most one per frame and 32767)");
  }
  if (!data.plan || data.plan->robots() == robots) return;
  if (data.plan->robots() < robots) {
    throw std::invalid_argument("--robots: " + std::to_string(robots) + " robots, but the config's team plan "
                                "(dataset.trajectories or dataset.scenario) has " +
                                std::to_string(data.plan->robots()));
  }
  data = FirstRobots(data, static_cast<int>(robots));
}

void CheckRealNetwork(const ExperimentConfig& config, const std::string& origin) {
  if (config.network.schedule) {
    throw std::invalid_argument(origin + ": network.schedule: talk windows are simulated only (dvpr run); "
                                "a launched team's agents do not emulate them");
  }
  EmulatedRange::CheckConfig(config, origin);
}

AgentProcessOptions ParseAgentArgs(const std::vector<std::string>& args) {
  AgentProcessOptions o;
  OptionReader in(args);
  while (in.Next()) {
    const std::string& f = in.flag();
    if (f == "--config") o.config = in.Text();
    else if (f == "--set") o.overrides.push_back(ParseOverride(in.Text()));
    else if (f == "--robot") o.robot = in.Int();
    else if (f == "--robots") o.robots = in.Int();
    else if (f == "--run") o.run = in.Int();
    else if (f == "--strategy") o.strategy = in.Text();
    else if (f == "--lcm") o.lcm_url = in.Text();
    else if (f == "--team-nonce") o.team_nonce = ParseTeamNonce(in.Text());
    else if (f == "--team-secret") o.team_secret = in.Text();
    else if (f == "--hold-bytes") o.hold_bytes = in.Int64();
    else if (f == "--speedup") o.speedup = in.Double();
    else if (f == "--out") o.out = in.Text();
    else if (f == "--grace") o.grace_s = in.Double();
    else if (f == "--barrier-timeout") o.barrier_timeout_s = in.Double();
    else in.Unknown();
  }
  o.Validate();
  return o;
}

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kAnnouncePeriod = std::chrono::milliseconds(50);
constexpr int kFinalAnnouncements = 4;  // DONE repeated before leaving, so others hear it despite loss

std::int64_t WallUtime() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// Everything the agents of one team must agree on, hashed: if one process has
// other data, centroids or parameters, it routes differently and must not join.
// Broadcast has no table: its robots need no centroids in common. The nonce keeps two teams
// of the same config apart (each `dvpr launch` draws its own).
std::int64_t TeamKey(const ExperimentConfig& c, const Dataset& data, const CentroidTable* table, const BowData* bow,
                     const std::string& strategy, int robots, int run, std::uint64_t nonce) {
  Fnv1a h;
  h.AddValue(nonce);
  h.AddValue(robots);
  h.AddValue(run);
  h.Add(strategy.data(), strategy.size());
  if (table != nullptr) {
    const CentroidMatrix& centroids = table->centroids();
    h.Add(centroids.data(), static_cast<std::size_t>(centroids.size()) * sizeof(float));
  }
  h.Add(data.descriptors.data(), static_cast<std::size_t>(data.descriptors.size()) * sizeof(float));
  if (bow != nullptr) {  // a bow_ team matches on these, so every robot must have the same
    h.AddValue(c.agent.verification.bow_max_distance);
    h.AddValue(bow->vocabulary);
    for (const BowVector& v : bow->frames) {
      h.AddValue(static_cast<std::int64_t>(v.size()));
      for (const BowEntry& e : v) {
        h.AddValue(e.word);
        h.AddValue(e.weight);
      }
    }
  }
  h.AddValue(data.fps);
  h.AddValue(c.evaluation.suppression_frames);
  h.AddValue(c.agent.service.fixed.ns());
  h.AddValue(c.agent.service.per_comparison.ns());
  h.AddValue(c.agent.verification.max_distance);
  if (c.failover.enabled) {  // a robot that fails over routes otherwise than one that does not
    h.AddValue(c.failover.timeout.ns());
    h.AddValue(c.failover.heartbeat_period.ns());
  }
  return h.value();
}

// The destination robot of a unicast channel (the reply channel of robot 3 -> 3).
std::optional<int> UnicastDestination(const std::string& channel) {
  const auto pos = channel.rfind('_');
  if (pos == std::string::npos || pos + 1 >= channel.size()) return std::nullopt;
  int v = 0;
  for (std::size_t i = pos + 1; i < channel.size(); ++i) {
    if (channel[i] < '0' || channel[i] > '9') return std::nullopt;
    v = v * 10 + (channel[i] - '0');
  }
  return v;
}

// The sender of a message received on one of the agent's channels, when it
// decodes and every robot and frame id in it is in range; -1 when it decodes
// but is not of this team; empty when it does not decode (the transport
// counts it as malformed).
std::optional<int> SourceOf(const std::string& channel, std::span<const std::uint8_t> bytes, int robots, int frames) {
  const auto robot = [&](int r, bool none_ok) { return (r >= 0 && r < robots) || (none_ok && r == -1); };
  const auto frame = [&](int f, bool none_ok) { return (f >= 0 && f < frames) || (none_ok && f == -1); };
  auto check = [](bool ok, int src) { return ok ? src : -1; };
  using channels::ChannelKind;
  const auto kind = channels::KindOf(channel);
  if (!kind) return std::nullopt;
  switch (*kind) {
    case ChannelKind::kQuery:
    case ChannelKind::kProbe:
    case ChannelKind::kStore:
    case ChannelKind::kQueryAll:
      if (auto q = Decode<query_t>(bytes)) return check(robot(q->robot, false) && frame(q->frame, false), q->robot);
      break;
    case ChannelKind::kMatch:
      if (auto m = Decode<match_t>(bytes)) {
        return check(robot(m->responder, false) && robot(m->query_robot, false) && frame(m->query_frame, false) &&
                         robot(m->match_robot, !m->has_match) && frame(m->match_frame, !m->has_match),
                     m->responder);
      }
      break;
    case ChannelKind::kBowQuery:
    case ChannelKind::kBowProbe:
      if (auto q = Decode<bow_query_t>(bytes)) return check(robot(q->robot, false) && frame(q->frame, false), q->robot);
      break;
    case ChannelKind::kBowMatch:
      if (auto m = Decode<bow_match_t>(bytes)) {
        return check(robot(m->responder, false) && robot(m->query_robot, false) && frame(m->query_frame, false) &&
                         robot(m->match_robot, !m->has_match) && frame(m->match_frame, !m->has_match),
                     m->responder);
      }
      break;
    case ChannelKind::kVerifyRequest:
      if (auto r = Decode<verify_request_t>(bytes)) {
        return check(robot(r->query_robot, false) && robot(r->match_robot, false) && frame(r->query_frame, false) &&
                         frame(r->match_frame, false), r->query_robot);
      }
      break;
    case ChannelKind::kVerifyResult:
      if (auto r = Decode<verify_result_t>(bytes)) {
        return check(robot(r->query_robot, false) && robot(r->match_robot, false) && frame(r->query_frame, false) &&
                         frame(r->match_frame, false), r->match_robot);
      }
      break;
    default: break;  // re-clustering and heartbeats: not counted per source here
  }
  return std::nullopt;
}

// Counts what the agent sends and receives, per robot (links.csv).
struct TrafficCounters {
  int self = 0;
  WireParams wire;
  std::vector<AgentLinkCount> sent;
  std::vector<std::int64_t> received_from;
  std::int64_t medium_wire_bytes = 0;
  int frames = 0;
  std::uint64_t foreign = 0;  // well-formed messages naming robots or frames outside the team, or
                              // sent by a process that is not the robot they name
  EmulatedRange* range = nullptr;  // a radio config: messages from robots out of range are dropped
  std::uint64_t out_of_range = 0;  // and counted here

  // A teammate's message that the emulated radio does not let through (emulated_range.h).
  bool OutOfRange(int src, SimTime now) {
    if (range == nullptr || src == self || range->Hears(src, now)) return false;
    ++out_of_range;
    return true;
  }

  void OnPublish(const std::string& channel, std::size_t size) {
    if (channel == channels::kStatus) return;
    const std::int64_t wire_bytes =
        ComputeWireFootprint(Bytes(static_cast<std::int64_t>(size)), static_cast<std::int64_t>(channel.size()), wire)
            .wire_bytes.value();
    medium_wire_bytes += wire_bytes;
    auto count = [&](std::size_t dst) {
      if (dst >= sent.size() || static_cast<int>(dst) == self) return;
      ++sent[dst].messages;
      sent[dst].payload_bytes += static_cast<std::int64_t>(size);
      sent[dst].wire_bytes += wire_bytes;
    };
    if (channel == channels::kQueryAll) {
      for (std::size_t d = 0; d < sent.size(); ++d) count(d);
    } else if (const auto dst = UnicastDestination(channel)) {
      count(static_cast<std::size_t>(*dst));
    }
  }
  // Takes the heartbeats into `sync` (which learns each robot's sender from them); counts
  // messages per source; drops well-formed messages from outside the team.
  // now: the agent time it arrives at (the emulated radio's question).
  bool OnReceive(const std::string& channel, std::span<const std::uint8_t> bytes, std::uint64_t sender,
                 TeamSync& sync, SimTime now) {
    // The robot whose secret-holding process sent it (every message here has a verified tag);
    // -1 for a transport that does not authenticate.
    const int authenticated = auth::RobotOfSender(sender);
    if (channel == channels::kStatus) {
      const auto s = Decode<agent_status_t>(bytes);
      if (!s) return true;  // one that does not decode: the handler counts it
      if (authenticated >= 0 && s->robot != authenticated) {  // a teammate speaking for another robot
        ++foreign;
        return false;
      }
      // A teammate's heartbeat out of range is not heard either (failover then notices).
      if (s->robot >= 0 && s->robot < static_cast<int>(received_from.size()) && sync.FromMember(RobotId(s->robot), sender) &&
          OutOfRange(s->robot, now)) {
        return false;
      }
      return sync.OnStatus(*s, sender);
    }
    const auto src = SourceOf(channel, bytes, static_cast<int>(received_from.size()), frames);
    if (!src) return true;  // let the handler's decoder count it as malformed
    if (*src < 0 || (authenticated >= 0 && *src != authenticated) || !sync.FromMember(RobotId(*src), sender)) {
      ++foreign;
      return false;
    }
    if (OutOfRange(*src, now)) return false;
    if (*src != self) ++received_from[static_cast<std::size_t>(*src)];
    return true;
  }
};

struct OwnProgress {
  int taken = 0;
  bool all_answered = false;  // every frame taken, every reply and verification in
};

OwnProgress Progress(const TeamAgent& agent) {
  OwnProgress p;
  bool answered = true;
  for (const QueryRecord& o : agent.outcomes()) {
    if (!o.Taken()) {
      answered = false;
      continue;
    }
    ++p.taken;
    if (!o.Complete() || (o.verify_requested && !o.verify_accepted)) answered = false;
  }
  p.all_answered = answered;
  return p;
}

}  // namespace

namespace {

struct Team {
  ExperimentConfig config;
  SharedInputs inputs;
  int robots = 0;
  StrategySpec strategy;
  std::optional<RunPlacement> routing;  // LoadTeam builds it
  std::int64_t key = 0;
};

// --strategy, or the config's first strategy.
StrategySpec TeamStrategy(const AgentProcessOptions& o, const ExperimentConfig& config) {
  if (o.strategy.empty()) return config.sweep.strategies.front();
  try {
    return ParseStrategy(o.strategy);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--strategy: ") + e.what());
  }
}

Team LoadTeam(const AgentProcessOptions& o, ExperimentConfig config) {
  Team t;
  t.config = std::move(config);
  t.strategy = TeamStrategy(o, t.config);  // before the data: a typo fails at once
  if (t.strategy.reclusters()) {
    throw std::invalid_argument("--strategy: '" + t.strategy.name +
                                "' re-clusters during the run, which dvpr agent does not implement; run it in the "
                                "simulation (dvpr run)");
  }
  // The BoW vectors are loaded only for a config that runs a bow_ strategy: --strategy may name
  // one the config's list lacks.
  const auto& listed = t.config.sweep.strategies;
  if (t.strategy.bag_of_words() && std::find(listed.begin(), listed.end(), t.strategy) == listed.end()) {
    t.config.sweep.strategies.push_back(t.strategy);
  }
  t.inputs = LoadSharedInputs(t.config, o.config.string());
  t.inputs.config = &t.config;
  t.robots = o.robots.value_or(t.config.sweep.robots.front());
  FitTeamSize(t.robots, t.inputs.deployment);
  CheckDescriptorsFitTheWire(t.inputs.deployment, o.config.string());
  CheckRealNetwork(t.config, o.config.string());
  if (o.robot >= t.robots) throw std::invalid_argument("--robot " + std::to_string(o.robot) + " is not in a team of " + std::to_string(t.robots));
  // Built by every process from the same inputs, so the whole team routes alike.
  t.routing.emplace(BuildRunPlacement(t.strategy, StrategyInputsOf(t.inputs), t.robots, o.run));
  t.key = TeamKey(t.config, t.inputs.deployment, t.routing->table(),
                  t.routing->As<BowFamily>() != nullptr ? &t.inputs.bow : nullptr, t.strategy.name, t.robots, o.run,
                  o.team_nonce);
  // The process announces the heartbeats (DVPR_STATUS, every kAnnouncePeriod); failover listens.
  if (StatelessFamily* f = t.routing->As<StatelessFamily>(); f != nullptr && f->failover != nullptr) {
    f->failover->UseProcessHeartbeats(t.key);
  }
  return t;
}

AgentLog MakeLog(const AgentProcessOptions& o, const Team& t, const TeamAgent& agent, const LcmTransport& transport,
                 const TeamSync& sync, const TrafficCounters& traffic, std::int64_t start_utime,
                 const std::string& end_reason) {
  AgentLog l;
  l.robot = o.robot;
  l.robots = t.robots;
  l.run = o.run;
  l.strategy = t.strategy.name;
  l.speedup = o.speedup;
  l.start_utime = start_utime;
  l.end_ns = transport.Now().ns();
  l.end_reason = end_reason;
  l.published = transport.Published();
  l.published_bytes = transport.PublishedBytes();
  l.publish_failures = transport.PublishFailures();
  l.received = transport.Received();
  l.malformed = transport.MalformedCount();
  const udpm::Counts& datagrams = transport.ReceiveCounts();
  l.datagrams = datagrams.datagrams;
  l.malformed_datagrams = datagrams.malformed;
  const LcmTransport::AuthCounts& tags = transport.auth_counts();
  l.duplicates = datagrams.duplicates + tags.replayed;
  l.unauthenticated = tags.unauthenticated;
  l.held_dropped = tags.held_dropped;
  l.held_bytes_peak = tags.held_bytes_peak;
  l.incomplete_messages = datagrams.incomplete;
  l.kernel_dropped = transport.KernelDropped();
  l.foreign = sync.foreign() + traffic.foreign;
  l.out_of_range = traffic.out_of_range;
  l.medium_wire_bytes = traffic.medium_wire_bytes;
  l.load = agent.load();
  l.sent = traffic.sent;
  l.received_from = traffic.received_from;
  l.lost = agent.Lost();
  for (QueryRecord q : agent.outcomes()) {
    if (!q.Taken()) continue;
    // Latency as the network delivered it: the wall clock, not agent time.
    if (q.latency) q.latency = SimTime::Nanos(std::llround(static_cast<double>(q.latency->ns()) / o.speedup));
    l.queries.push_back(q);
  }
  return l;
}

// The robot's agent: a BoW agent for the bow_ strategies (docs/bow.md), else a RobotAgent.
std::unique_ptr<TeamAgent> MakeAgent(const AgentProcessOptions& o, const Team& t, Transport& transport,
                                     const SequenceSplit& split) {
  const Dataset& data = t.inputs.deployment;
  const FrameStream frames = split.StreamOf(o.robot, &data.descriptors, data.fps);
  GeometricVerifier verifier = PoseOracle(data.trajectory.positions, t.config.evaluation.radius_m);
  return t.routing->Visit(
      [&](const BowFamily& f) -> std::unique_ptr<TeamAgent> {
        const AgentSetup setup{RobotId(o.robot), f.team.robots, t.config.agent, frames, split.WindowStreams()};
        return std::make_unique<BowRobotAgent>(setup, transport, f.team, t.inputs.bow.frames, std::move(verifier));
      },
      [&](const auto& descriptor) -> std::unique_ptr<TeamAgent> {
        const AgentSetup setup{RobotId(o.robot), descriptor.team->num_robots(), t.config.agent, frames,
                               split.WindowStreams()};
        return std::make_unique<RobotAgent>(setup, transport, descriptor.team->MakeAgentPlacement(),
                                            std::move(verifier));
      });
}

// `dropout:` in a real team: the robot's process kills itself at that agent time, as the
// operating system would kill it (SIGKILL: no log, no last heartbeat, nothing flushed).
void ScheduleDropout(const ExperimentConfig& c, int robot, Transport& transport) {
  for (const Dropout& d : c.dropout) {
    if (d.robot != robot) continue;
    // Called before the team's start: a timer set then counts from the start (agent time 0), so
    // the delay is `at` itself (it was `at` - Now(), which added the wait for the start: the
    // robot died 1.5 s of agent time late at speedup 5).
    transport.ScheduleAfter(std::max(SimTime::Zero(), d.at - std::max(transport.Now(), SimTime::Zero())),
                            [] { raise(SIGKILL); });
  }
}

// The folder the log goes to must be there before the team runs: found missing at the end, the
// whole run was lost (and its teammates waited for nothing).
void CheckLogFolder(const std::filesystem::path& log) {
  const std::filesystem::path folder = log.parent_path().empty() ? std::filesystem::path(".") : log.parent_path();
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) {
    throw std::runtime_error("--out " + log.string() + ": the folder " + folder.string() + " does not exist");
  }
  if (access(folder.c_str(), W_OK) != 0) {
    throw std::runtime_error("--out " + log.string() + ": the folder " + folder.string() + " is not writable");
  }
}

// What reassembling may hold: the team's largest message is a verification request (its
// payload is verification.request_bytes) or a query, far below LCM's 2^28 bytes. A message may
// be no larger (with its trailer), and unfinished messages hold at most twice that and 16 MiB:
// all that a flood of fragments from anyone on the group can make an agent keep
// (docs/security.md, "Memory").
udpm::Limits ReceiveLimits(const ExperimentConfig& c) {
  constexpr std::int64_t kHeaders = 1 << 20;  // a query's descriptor (32767 floats) and any header
  const std::int64_t largest = c.agent.verification.request_bytes.value() + kHeaders;
  if (largest + wire::kTeamTrailer > std::int64_t{udpm::kMaxMessageBytes}) {
    throw std::invalid_argument("verification.request_bytes: " +
                                std::to_string(c.agent.verification.request_bytes.value()) +
                                " bytes do not fit one LCM message (at most 2^28 = 268435456 bytes with headers)");
  }
  udpm::Limits limits;
  limits.max_message_bytes = static_cast<std::uint32_t>(largest + wire::kTeamTrailer);
  limits.max_partial_bytes = 2 * std::size_t{limits.max_message_bytes} + (16u << 20);
  return limits;
}

}  // namespace

int RunAgentProcess(const AgentProcessOptions& o, std::ostream& out) {
  o.Validate();
  ExperimentConfig config = LoadConfig(o.config, o.overrides);
  const std::string strategy_name = TeamStrategy(o, config).name;
  const int robots = o.robots.value_or(config.sweep.robots.front());
  const std::filesystem::path path =
      o.out.empty() ? std::filesystem::path("agent_" + strategy_name + "_n" + std::to_string(robots) + "_r" +
                                            std::to_string(o.run) + "_robot" + std::to_string(o.robot) + ".log")
                    : o.out;
  CheckLogFolder(path);
  const auth::Secret secret = auth::ReadSecretFile(o.team_secret);
  // LCM next: an agent that cannot talk fails at once, before minutes of loading and k-means.
  LcmTransport transport(o.lcm_url, o.speedup, ReceiveLimits(config));
  transport.Authenticate(auth::MessageAuth(secret, o.robot));
  const Team t = LoadTeam(o, std::move(config));
  const Dataset& data = t.inputs.deployment;
  const SequenceSplit split = TeamSplit(data, t.robots);

  TrafficCounters traffic{o.robot, WireParams{}, std::vector<AgentLinkCount>(static_cast<std::size_t>(t.robots)),
                          std::vector<std::int64_t>(static_cast<std::size_t>(t.robots), 0), 0,
                          static_cast<int>(data.size()), 0};
  traffic.wire.mtu = t.config.network.mtu.front();
  traffic.wire.trailer = Bytes(wire::kTeamTrailer);
  transport.SetPublishObserver([&](const std::string& c, std::span<const std::uint8_t> b) { traffic.OnPublish(c, b.size()); });
  std::optional<EmulatedRange> radio;
  const auto& models = t.config.network.model;
  if (std::find(models.begin(), models.end(), LinkModelKind::kRadio) != models.end()) {
    radio.emplace(t.config, data, split, o.robot, RunSeed(t.config.seed, t.robots, o.run));
    traffic.range = &*radio;
  }
  TeamSync sync(RobotId(o.robot), t.robots, t.key);
  transport.SetReceiveFilter([&](const std::string& c, std::span<const std::uint8_t> b, std::uint64_t sender) {
    return traffic.OnReceive(c, b, sender, sync, transport.Now());
  });
  // The filter takes the heartbeats (it knows their sender); this keeps their channel open and
  // counts one that does not decode as malformed.
  Subscription status = transport.Subscribe<agent_status_t>(channels::kStatus, [](const agent_status_t&) {});
  const std::unique_ptr<TeamAgent> agent_owner = MakeAgent(o, t, transport, split);
  TeamAgent& agent = *agent_owner;

  const std::int64_t ready_utime = WallUtime();
  auto announce = [&](std::int8_t state) {
    const agent_status_t s = sync.Announce(WallUtime(), state, ready_utime, Progress(agent).taken);
    sync.OnStatus(s);  // hear ourselves even if the loopback copy is lost
    transport.Publish(channels::kStatus, s);
  };

  // What teammates that leave the barrier first send us is kept until agent.Start() subscribes.
  transport.HoldUntilSubscribed(agent.Inbox(), static_cast<std::size_t>(o.hold_bytes));
  // Start barrier: announce READY until every robot of the team is heard.
  const auto barrier_end = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.barrier_timeout_s));
  std::optional<std::int64_t> start;
  const auto margin_us = static_cast<std::int64_t>(o.start_margin_s * 1e6);
  while (!(start = sync.StartUtime(margin_us))) {
    if (Clock::now() > barrier_end) {
      throw std::runtime_error("start barrier: heard " + std::to_string(sync.HeardCount()) + " of " +
                               std::to_string(t.robots) + " robots in " + std::to_string(o.barrier_timeout_s) +
                               " s (" + std::to_string(sync.foreign()) + " heartbeats of another team: same config, "
                               "data, --robots, --run and --strategy everywhere? same --lcm URL?)");
    }
    announce(agent_status_t::READY);
    transport.RunUntilWall(Clock::now() + kAnnouncePeriod);
  }
  transport.SetEpoch(std::chrono::system_clock::time_point(std::chrono::microseconds(*start)));
  agent.Start();
  ScheduleDropout(t.config, o.robot, transport);

  // The run: serve until every robot is done, or give up at the deadline.
  const SimTime deadline = split.LastCapture(data.fps) + SimTime::Seconds(o.grace_s * o.speedup);
  std::string end_reason = "deadline";
  int final_announcements = 0;
  while (transport.Now() < deadline) {
    const SimTime now = transport.Now();
    const bool done = now >= SimTime::Zero() && Progress(agent).all_answered;
    announce(now < SimTime::Zero() ? agent_status_t::READY : done ? agent_status_t::DONE : agent_status_t::RUNNING);
    if (done && sync.AllDone() && ++final_announcements >= kFinalAnnouncements) {
      end_reason = "all_done";
      break;
    }
    const auto to_deadline = std::chrono::nanoseconds(std::llround(static_cast<double>((deadline - now).ns()) / o.speedup));
    transport.RunUntilWall(Clock::now() + std::min<Clock::duration>(kAnnouncePeriod, to_deadline));
  }

  const AgentLog log = MakeLog(o, t, agent, transport, sync, traffic, *start, end_reason);
  WriteAgentLog(path, log);
  const auto complete = std::count_if(log.queries.begin(), log.queries.end(), [](const QueryRecord& q) { return q.Complete(); });
  out << "robot " << o.robot << ": " << log.queries.size() << " queries, " << complete << " with every reply, "
      << log.malformed_datagrams << " malformed datagrams, " << log.malformed << " malformed messages, "
      << log.foreign << " foreign, " << log.unauthenticated << " unauthenticated, " << log.out_of_range
      << " out of range, " << log.duplicates << " duplicates, " << log.held_dropped << " dropped past --hold-bytes, "
      << log.kernel_dropped
      << " dropped by a full receive buffer, end: " << end_reason << ", log " << path.string() << "\n";
  return 0;
}

}  // namespace dvpr
