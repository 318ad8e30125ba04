#include "experiments/sweep/sweep_size.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>
#include <thread>
#include <utility>
#include <vector>

#include "experiments/results/protocol_traits.h"
#include "experiments/sweep/sweep.h"
#include "net_models/network/disconnected_params.h"

namespace dvpr {

namespace {

// 3 significant digits: "1.8e+09", "4.19e+09", "760".
std::string Figure(double x) {
  std::ostringstream out;
  out.precision(3);
  out << x;
  return out.str();
}

std::string GiB(double bytes) { return Figure(bytes / (1024.0 * 1024.0 * 1024.0)) + " GiB"; }

std::size_t Index(SizeTerm term) { return static_cast<std::size_t>(term); }

bool Lists(const NetworkConfig& n, LinkModelKind model) {
  return std::find(n.model.begin(), n.model.end(), model) != n.model.end();
}

// The number of network variants ExpandNetworks gives, without listing them (a hostile config's
// lists multiply to more variants than memory holds).
double NetworkVariants(const NetworkConfig& n) {
  double count = 0;
  for (const LinkModelKind model : n.model) {
    const bool wifi = model == LinkModelKind::kWifi;
    const double radios = static_cast<double>(PropagationsOf(n, model).size());
    // Only the radio sweeps its routing entries (ExpandNetworks).
    const double routings = model == LinkModelKind::kRadio ? static_cast<double>(n.routing.size()) : 1.0;
    // wifi has its own rate: the bandwidth and latency lists do not multiply it (ExpandNetworks).
    const double rates = wifi ? 1.0 : static_cast<double>(n.bandwidth.size()) * static_cast<double>(n.latency.size());
    count += model == LinkModelKind::kIdeal ? 1.0
                                            : radios * routings * rates * static_cast<double>(n.queue_packets.size()) *
                                                  static_cast<double>(n.mtu.size());
  }
  return count;
}

// A robot's frames, taken evenly from start_ns to end_ns (the copies it may hold are sent then).
struct Drive {
  double start_ns = 0;
  double end_ns = 0;
  double frames = 0;
};

// A team of the sweep: its robots, frames, the most one robot takes, and mission (when it takes
// its last frame).
struct Team {
  int robots = 0;
  double frames = 0;
  double own_frames = 0;
  double mission_ns = 0;
  std::vector<Drive> drives;
};

// The time of frame k at fps, as FrameStream::TimeOf rounds it.
double FrameNs(double k, double fps) { return static_cast<double>(std::llround(k * 1e9 / fps)); }

// The paper's split of `frames` among n robots: robot r's k-th frame at k / fps, the longest
// share ceil(frames / n) frames.
Team SplitTeam(int n, double frames, double fps) {
  const double longest = std::ceil(frames / n);
  const double mission = FrameNs(longest - 1, fps);
  return {n, frames, longest, mission, {Drive{0, mission, frames}}};
}

// A scenario's team before its poses are loaded, each robot driving `frames` of the sequence
// (staggered, reverse), or a stretch of `length` from time 0 (random_routes: its start is drawn
// in [0, (frames - length) / fps], so the mission ends by the sequence's last frame time).
Team ScenarioTeam(const ScenarioSpec& s, int n, double frames, double fps) {
  const bool routes = s.kind == ScenarioKind::kRandomRoutes;
  const double each = routes ? std::min<double>(s.length, frames) : frames;
  Team team{n, 0, each, 0, {}};
  const double drive = FrameNs(each - 1, fps);
  for (int r = 0; r < n; ++r) {
    const double start = routes ? 0.0 : std::round(r * s.offset_s * 1e9);
    team.drives.push_back(Drive{start, start + drive, each});
    team.frames += each;
    team.mission_ns = std::max(team.mission_ns, start + drive);
  }
  if (routes) team.mission_ns = FrameNs(frames - 1, fps);
  return team;
}

// A loaded plan's team: each robot's captures as they are.
Team PlannedTeam(const SequenceSplit& plan, double fps) {
  Team team{plan.robots(), static_cast<double>(plan.frames()), 0,
            static_cast<double>(plan.LastCapture(fps).ns()), {}};
  for (int r = 0; r < plan.robots(); ++r) {
    const FrameStream s = plan.StreamOf(r, nullptr, fps);
    team.own_frames = std::max(team.own_frames, static_cast<double>(s.count));
    if (s.count == 0) continue;
    team.drives.push_back(Drive{static_cast<double>(s.TimeOf(0).ns()), static_cast<double>(s.TimeOf(s.count - 1).ns()),
                                static_cast<double>(s.count)});
  }
  return team;
}

// Sum over a drive's frames of min(hold, mission - t): how long each copy sent at a frame may be
// held, its frames spread evenly over [start, end].
double HeldNs(const Drive& d, double mission, double hold) {
  const double a = d.start_ns, b = std::min(d.end_ns, mission);
  if (d.frames <= 0 || b < a) return 0;
  if (b == a) return d.frames * std::min(hold, mission - a);
  const double c = std::clamp(mission - hold, a, b);  // before c a copy is held `hold`
  const double integral = hold * (c - a) + mission * (b - c) - (b * b - c * c) / 2;
  return d.frames * integral / (b - a);
}

// What a run of the sweep has, each on its costliest variant and strategy.
struct RunShape {
  const ExperimentConfig* config = nullptr;
  bool sim = false;
  bool paper = false;
  double dim = 0;
  double strategies = 0;
  bool bow = false;             // a bow_ strategy: its queries go to each robot as messages of their own
  double probes = 1;            // the most robots a descriptor query goes to as messages of their own
  double replicas = 1;          // the most robots that keep a frame
  bool connectivity = false;    // outputs.connectivity on a radio
  std::vector<LinkStateParams> link_state;  // the radio's link_state entries
};

// A run of any of `protocols` (the sweep's, or one of them).
RunShape ShapeOf(const ExperimentConfig& c, double dim, const std::vector<std::string>& protocols) {
  RunShape shape;
  shape.config = &c;
  shape.sim = AnyProtocol(protocols, &ProtocolTraits::simulated_network);
  shape.paper = AnyProtocol(protocols, &ProtocolTraits::static_evaluation);
  shape.dim = dim;
  shape.strategies = static_cast<double>(c.sweep.strategies.size());
  for (const StrategySpec& s : c.sweep.strategies) {
    shape.bow = shape.bow || s.bag_of_words();
    if (s.placement == StrategySpec::Placement::kProbe) shape.probes = std::max<double>(shape.probes, s.probe.probes);
    if (s.placement == StrategySpec::Placement::kReplicate) {
      shape.probes = std::max<double>(shape.probes, s.replicate.max_replicas);
      shape.replicas = std::max<double>(shape.replicas, s.replicate.max_replicas);
    }
  }
  const bool radio = Lists(c.network, LinkModelKind::kRadio);
  shape.connectivity = shape.sim && radio && c.outputs.connectivity;
  for (const NextHopEntry& e : c.network.routing) {
    if (shape.sim && radio && e.kind == NextHopKind::kLinkState) shape.link_state.push_back(e.link_state);
  }
  return shape;
}

// The verification requests a robot may have in flight at once (sweep_size.h): what its queues
// hold and what has left them but not arrived, on the variant where that is most. One on ideal
// links; none when every variant drops the request as it is sent.
double RequestsInFlight(const NetworkConfig& n, int robots, double request_bytes) {
  double in_flight = 0;
  for (const LinkModelKind model : n.model) {
    if (model == LinkModelKind::kIdeal) {
      in_flight = std::max(in_flight, 1.0);
      continue;
    }
    const bool wifi = model == LinkModelKind::kWifi;
    double bps = wifi ? static_cast<double>(n.wifi.rate.bps()) : 0.0;
    double latency_ns = 0;
    if (!wifi) {
      for (const DataRate r : n.bandwidth) bps = std::max(bps, static_cast<double>(r.bps()));
      for (const SimTime l : n.latency) latency_ns = std::max(latency_ns, static_cast<double>(l.ns()));
      for (const LinkOverrideParams& o : n.links) {
        if (o.bandwidth) bps = std::max(bps, static_cast<double>(o.bandwidth->bps()));
        if (o.latency) latency_ns = std::max(latency_ns, static_cast<double>(o.latency->ns()));
      }
    }
    const double mtu = static_cast<double>(std::max_element(n.mtu.begin(), n.mtu.end())->value());
    const double queue = *std::max_element(n.queue_packets.begin(), n.queue_packets.end());
    // IP packets of 8-byte multiples of data behind a 20-byte header; LCM's and UDP's headers and
    // the channel about 64 bytes; 22 bytes of IP and link framing a packet.
    const double packets = std::ceil((request_bytes + 64) / (std::floor((mtu - 20) / 8) * 8));
    if (packets - 1 > queue || bps <= 0) continue;
    const double wire_s = (request_bytes + 64 + 22 * packets) * 8 / bps;
    const double per_queue = 1 + std::floor(queue / packets) + std::floor(latency_ns * 1e-9 / wire_s) + 1;
    // A queue per destination on point-to-point links, one per robot on the other models.
    const double queues = model == LinkModelKind::kPointToPoint ? robots - 1 : 1;
    in_flight = std::max(in_flight, queues * per_queue);
  }
  return in_flight;
}

// link_state's beacons of the team on its costliest entry: HELLOs every hello, TCs every topology
// from 0 to the mission's end, each TC sent on once by every robot.
void AddBeacons(const RunShape& shape, const Team& t, RunEstimate& e) {
  const double n = t.robots;
  for (const LinkStateParams& p : shape.link_state) {
    const double hellos = n * (std::floor(t.mission_ns / static_cast<double>(p.hello.ns())) + 1);
    const double tcs = n * n * (std::floor(t.mission_ns / static_cast<double>(p.topology.ns())) + 1);
    e.beacons = std::max(e.beacons, hellos + tcs);
  }
  e.seconds[Index(SizeTerm::kBeacons)] = e.beacons * n * kSecondsPerMessage;  // sent, and heard by n - 1
}

void AddHeartbeats(const RunShape& shape, const Team& t, RunEstimate& e) {
  const FailoverParams& f = shape.config->failover;
  if (!shape.sim || !f.enabled) return;
  e.heartbeats = t.robots * (std::floor(t.mission_ns / static_cast<double>(f.heartbeat_period.ns())) + 1);
  e.seconds[Index(SizeTerm::kHeartbeats)] = e.heartbeats * t.robots * kSecondsPerMessage;
}

// When the network stops holding copies for the team (Scenario::Run): the end of its mission, or
// the last edge of a talk window of one of its robots after it.
double HoldHorizonNs(const NetworkConfig& n, const Team& t) {
  double horizon = t.mission_ns;
  for (const ScheduledWindow& w : n.windows) {
    if (w.robot >= t.robots) continue;
    horizon = std::max(horizon, static_cast<double>(w.window.from.ns()));
    if (w.window.until != SimTime::Max()) horizon = std::max(horizon, static_cast<double>(w.window.until.ns()));
  }
  return horizon;
}

// Store-and-forward: each query copy (and heartbeat copy) may be held from when it is sent until
// hold_time or the hold horizon, asked again every retry period and twice more; each holder
// retries every period until the horizon and once past it.
void AddRetries(const RunShape& shape, const Team& t, RunEstimate& e) {
  const DisconnectedParams& d = shape.config->network.disconnected;
  if (!shape.sim || d.kind != DisconnectedKind::kStoreAndForward) return;
  const double n = t.robots;
  // Every row of the sim protocol runs a team whose queries may each go to every other robot: its
  // strategy (broadcast, a bow_ one) or the broadcast the descriptor strategies' relative AUC is
  // against, run beside them. Broadcast's copies of a query are one message, the others' each
  // their own.
  const double fan_out = n - 1;
  const double messages = t.frames * (shape.bow ? n - 1 : std::min(n - 1, shape.probes));
  const double hold = static_cast<double>(d.hold_time.ns()), retry = static_cast<double>(d.retry.ns());
  const double horizon = HoldHorizonNs(shape.config->network, t);
  double held_ns = 0;
  for (const Drive& drive : t.drives) held_ns += fan_out * HeldNs(drive, horizon, hold);
  const double heartbeat_copies = e.heartbeats * (n - 1);
  held_ns += HeldNs(Drive{0, t.mission_ns, heartbeat_copies}, horizon, hold);
  e.held_copies = t.frames * fan_out + heartbeat_copies;
  e.retries = held_ns / retry + 2 * e.held_copies + n * (std::floor(horizon / retry) + 1);
  e.seconds[Index(SizeTerm::kRetries)] = e.retries * kSecondsPerMessage;
  // Each copy costs its entry, each message its bytes (a broadcast's copies share its payload).
  const double query_wire = 4 * shape.dim + 100, heartbeat_wire = 125;
  const double held = e.held_copies * kBytesPerHeldCopy + messages * query_wire + e.heartbeats * heartbeat_wire;
  const double buffers = n * static_cast<double>(d.hold_bytes.value());
  e.bytes[Index(SizeTerm::kHeld)] =
      std::min(held, buffers * (1 + kBytesPerHeldCopy / std::min(query_wire, heartbeat_wire)));
}

void AddRequests(const RunShape& shape, const Team& t, RunEstimate& e) {
  if (!shape.sim) return;
  const ExperimentConfig& c = *shape.config;
  const double request = static_cast<double>(c.agent.verification.request_bytes.value());
  e.requests = t.frames;
  e.request_bytes = e.requests * request;
  e.seconds[Index(SizeTerm::kRequests)] = e.request_bytes * kSecondsPerRequestByte;
  e.requests_in_flight = std::min(RequestsInFlight(c.network, t.robots, request), t.own_frames);
  e.bytes[Index(SizeTerm::kRequests)] = t.robots * (1 + e.requests_in_flight) * request + request;
}

void AddConnectivity(const RunShape& shape, const Team& t, RunEstimate& e) {
  if (!shape.connectivity) return;
  const double n = t.robots;
  const double step = static_cast<double>(std::llround(1e9 / shape.config->dataset.fps));
  e.connectivity_steps = std::floor(t.mission_ns / step) + 1;
  e.seconds[Index(SizeTerm::kConnectivity)] =
      e.connectivity_steps * (kSecondsPerConnectivityStep + n * (n - 1) / 2 * kSecondsPerConnectivityPair);
  e.bytes[Index(SizeTerm::kConnectivity)] =
      e.connectivity_steps * (shape.strategies + 1) * (kBytesPerConnectivityRow + 8 * n);
}

RunEstimate EstimateRun(const RunShape& shape, const Team& t) {
  RunEstimate e;
  e.robots = t.robots;
  e.frames = t.frames;
  e.mission_s = t.mission_ns * 1e-9;
  const double f = t.frames;
  e.multiply_adds = f * f / 2 * shape.dim;
  e.seconds[Index(SizeTerm::kSearch)] = e.multiply_adds * kSecondsPerMultiplyAdd;
  if (shape.sim) {
    e.messages = 2 * f * t.robots;
    e.seconds[Index(SizeTerm::kMessages)] = e.messages * kSecondsPerMessage;
    e.stored = f * std::min<double>(shape.replicas, t.robots);
    e.bytes[Index(SizeTerm::kStores)] = e.stored * 2 * (6 * shape.dim + 12);
  }
  if (shape.sim || shape.paper) e.bytes[Index(SizeTerm::kStores)] += f * kBytesPerFrameRecord;
  AddBeacons(shape, t, e);
  AddHeartbeats(shape, t, e);
  AddRetries(shape, t, e);
  AddRequests(shape, t, e);
  AddConnectivity(shape, t, e);
  return e;
}

// Whether the sweep makes dataset.synthetic_bow's vectors: a bow_ strategy runs on no BoW file.
bool MakesSyntheticBow(const ExperimentConfig& c) {
  const auto& s = c.sweep.strategies;
  return !c.dataset.bow && std::any_of(s.begin(), s.end(), [](const StrategySpec& x) { return x.bag_of_words(); });
}

// synthetic_bow's words and vectors of `frames` frames at their largest: all of them at once
// while TfIdfFromWords makes the vectors from the words (sweep_size.h).
double SyntheticBowBytes(const SyntheticBowParams& p, double frames) {
  const double features = p.features, vocabulary = p.vocabulary;
  return frames * (4 * features + 16 * std::min(features, vocabulary) + 72) + 16 * vocabulary;
}

// The inputs made once: the deployment's descriptors, the training set's, the paper protocol's
// neighbour lists.
double InputBytes(const RunShape& shape, double frames) {
  const ExperimentConfig& c = *shape.config;
  double training = 0;
  switch (c.training.source) {
    case TrainingSource::kSyntheticDiverse:
    case TrainingSource::kSyntheticDeploymentLike:
      training = c.training.synthetic.samples;
      break;
    case TrainingSource::kDeployment:
      training = frames;
      break;
    case TrainingSource::kFiles:
      break;
  }
  return (frames + training) * shape.dim * 4 + (shape.paper ? frames * 64 * 8 : 0.0);
}

SweepSize Estimate(const ExperimentConfig& c, const std::vector<Team>& teams, double dim) {
  const SweepConfig& s = c.sweep;
  SweepSize size;
  // One run per (robots, run, strategy) for each protocol, times the network variants of one on
  // the sweep's simulated network.
  double per_run_and_count = 0;
  for (const std::string& p : s.protocols) per_run_and_count += TraitsOf(p).simulated_network ? NetworkVariants(c.network) : 1.0;
  size.runs = static_cast<double>(s.robots.size()) * s.runs * static_cast<double>(s.strategies.size()) *
              per_run_and_count;
  const RunShape shape = ShapeOf(c, dim, c.sweep.protocols);
  double frames = 0;
  for (const Team& t : teams) {
    const RunEstimate e = EstimateRun(shape, t);
    if (e.Bytes() > size.bytes_per_run || size.largest.robots == 0) size.largest = e;
    if (e.Seconds() > size.seconds_per_run || size.slowest.robots == 0) size.slowest = e;
    size.bytes_per_run = size.largest.Bytes();
    size.seconds_per_run = size.slowest.Seconds();
    frames = std::max(frames, t.frames);
  }
  if (c.dataset.Planned()) size.plan_key = c.dataset.trajectories.empty() ? "dataset.scenario" : "dataset.trajectories";
  if (MakesSyntheticBow(c)) {
    const SyntheticBowParams p = c.dataset.synthetic_bow.value_or(SyntheticBowParams{});
    size.input_seconds = frames * (2 * p.range_m) * (2 * p.range_m) * p.landmark_density * kSecondsPerLandmark;
    size.bow_bytes = SyntheticBowBytes(p, frames);
  }
  size.input_bytes = InputBytes(shape, frames) + size.bow_bytes;
  return size;
}

// The term with the most of `by_term`.
SizeTerm Largest(const std::array<double, kSizeTerms>& by_term) {
  return static_cast<SizeTerm>(std::max_element(by_term.begin(), by_term.end()) - by_term.begin());
}

// What a refusal says of a term: the keys that set it, what it counts, what to change.
struct Explained {
  std::string keys;
  std::string what;
  std::string advice;
};

// "of 20 robots in a mission of 22.7 s, each heard by up to 19"
std::string Mission(const RunEstimate& e) {
  return "of " + std::to_string(e.robots) + " robots in a mission of " + Figure(e.mission_s) + " s";
}

// A term of the run's time other than the search and the messages. The mission's length is the
// plan's (its key follows the term's) for the terms that last as long as it.
Explained TimeTerm(SizeTerm term, const RunEstimate& e, const std::string& plan_key) {
  const std::string plan = plan_key.empty() ? "" : ", " + plan_key;
  const std::string heard = ", each heard by up to " + std::to_string(e.robots - 1);
  switch (term) {
    case SizeTerm::kBeacons:
      return {"network.routing" + plan, Figure(e.beacons) + " link_state HELLO and TC transmissions " + Mission(e) + heard,
              "lengthen network.routing's hello and topology periods"};
    case SizeTerm::kHeartbeats:
      return {"failover.heartbeat_period" + plan, Figure(e.heartbeats) + " failover heartbeats " + Mission(e) + heard,
              "lengthen failover.heartbeat_period"};
    case SizeTerm::kRetries:
      return {"network.disconnected" + plan,
              Figure(e.retries) + " store-and-forward retries (" + Figure(e.held_copies) +
                  " copies held, each asked again every 100ms until hold_time or the end of the mission at " +
                  Figure(e.mission_s) + " s)",
              "shorten network.disconnected's hold_time or the mission"};
    case SizeTerm::kRequests:
      return {"verification.request_bytes",
              Figure(e.request_bytes) + " bytes of verification requests made, encoded and decoded (one a frame, " +
                  Figure(e.frames) + " frames)",
              "lower verification.request_bytes"};
    default:  // kConnectivity
      return {"outputs.connectivity" + plan,
              Figure(e.connectivity_steps) + " connectivity steps of " + Figure(e.robots * (e.robots - 1.0) / 2) +
                  " robot pairs (every frame period of a mission of " + Figure(e.mission_s) + " s)",
              "turn outputs.connectivity off or shorten the mission"};
  }
}

// A term of the run's memory, or the inputs'.
Explained MemoryTerm(std::optional<SizeTerm> term, const SweepSize& size, const std::string& plan_key) {
  const RunEstimate& e = size.largest;
  const std::string per_run = term ? GiB(e.bytes[Index(*term)]) + " a run of " : "";
  if (!term && size.bow_bytes > size.input_bytes / 2) {
    return {"dataset.synthetic_bow",
            GiB(size.input_bytes) + " of inputs made once (" + GiB(size.bow_bytes) +
                " of it dataset.synthetic_bow's words and vectors, frames x (4 features + 16 min(features, " +
                "vocabulary) + 72) + 16 vocabulary bytes)",
            "lower dataset.synthetic_bow's features or dataset.frames"};
  }
  if (!term) {
    return {"dataset, training", GiB(size.input_bytes) + " of inputs made once (the deployment's and the training " +
                                     "set's descriptors, the paper protocol's neighbour lists" +
                                     (size.bow_bytes > 0 ? ", dataset.synthetic_bow's words and vectors" : "") + ")",
            "lower dataset.frames or dataset.dim"};
  }
  switch (*term) {
    case SizeTerm::kRequests:
      return {"verification.request_bytes",
              per_run + "verification payloads (" + std::to_string(e.robots) + " robots x (1 kept + " +
                  Figure(e.requests_in_flight) + " in flight) x request_bytes, and one being sent or decoded)",
              "lower verification.request_bytes"};
    case SizeTerm::kHeld:
      return {"network.disconnected",
              per_run + "store-and-forward copies held (" + Figure(e.held_copies) + " copies, " +
                  Figure(kBytesPerHeldCopy) + " bytes each and their messages' bytes, at most what robots x " +
                  "hold_bytes take)",
              "lower network.disconnected's hold_bytes"};
    case SizeTerm::kConnectivity:
      return {"outputs.connectivity" + (plan_key.empty() ? "" : ", " + plan_key),
              per_run + "connectivity rows (" + Figure(e.connectivity_steps) +
                  " steps x (strategies + 1) x (" + Figure(kBytesPerConnectivityRow) + " + 8 x robots) bytes)",
              "turn outputs.connectivity off or shorten the mission"};
    default:  // kStores
      return {"robots, dataset", per_run + "descriptor stores (frames x copies x 2 x (6 dim + 12) bytes) and records (" +
                                     Figure(kBytesPerFrameRecord) + " bytes a frame)",
              "lower dataset.frames, dataset.dim or robots"};
  }
}

void CheckMemory(const SweepSize& size, const SweepMachine& machine, double at_once, const std::string& origin) {
  const double bytes = size.input_bytes + at_once * size.bytes_per_run;
  if (machine.memory_bytes <= 0 || bytes <= machine.memory_bytes) return;
  const SizeTerm largest = Largest(size.largest.bytes);
  const bool inputs = size.input_bytes >= at_once * size.largest.bytes[Index(largest)];
  const Explained x = MemoryTerm(inputs ? std::nullopt : std::optional<SizeTerm>(largest), size, size.plan_key);
  const std::string what = at_once > 1 ? Figure(at_once) + " runs at once (one a thread) may need up to " + GiB(bytes) +
                                             ", each up to " + GiB(size.bytes_per_run)
                                       : "a run may need up to " + GiB(bytes);
  throw ConfigError(origin + ": " + x.keys + ": " + what + " (" + x.what +
                    (inputs || size.input_bytes <= 0 ? "" : ", and " + GiB(size.input_bytes) + " of inputs made once") +
                    "), more than this machine's " + GiB(machine.memory_bytes) + " of memory; " + x.advice +
                    (at_once > 1 ? std::string(", run fewer at once (--threads)") : "") +
                    ", or pass --allow-large to run it anyway");
}

void CheckTime(const SweepSize& size, double parallel, const std::string& origin) {
  const double seconds = size.input_seconds + size.runs * size.seconds_per_run / parallel;
  if (seconds <= kMaxSweepHours * 3600) return;
  const SizeTerm largest = Largest(size.slowest.seconds);
  const bool own_key = largest != SizeTerm::kSearch && largest != SizeTerm::kMessages &&
                       size.runs * size.slowest.seconds[Index(largest)] / parallel > size.input_seconds;
  const Explained x = own_key ? TimeTerm(largest, size.slowest, size.plan_key) : Explained{};
  throw ConfigError(origin + ": " + (own_key ? x.keys : "robots, runs, strategies, network, dataset") +
                    ": the sweep would take about " + Figure(seconds / 3600) + " h on " + Figure(parallel) +
                    (parallel > 1 ? " cores (" : " core (") + Figure(size.runs) + (size.runs == 1 ? " run" : " runs") +
                    " of up to " + Figure(size.seconds_per_run) + " s each" +
                    (own_key ? ", " + Figure(size.slowest.seconds[Index(largest)]) + " s of it for " + x.what : "") +
                    (size.input_seconds > 0 ? ", and " + Figure(size.input_seconds) +
                                                  " s to make dataset.synthetic_bow's vectors"
                                            : std::string()) +
                    "), more than " + Figure(kMaxSweepHours) + " h; " + (own_key ? x.advice + ", " : "narrow it, ") +
                    "or pass --allow-large to run it anyway");
}

}  // namespace

double RunEstimate::Seconds() const { return std::accumulate(seconds.begin(), seconds.end(), 0.0); }
double RunEstimate::Bytes() const { return std::accumulate(bytes.begin(), bytes.end(), 0.0); }

SweepSize EstimateSweepSize(const ExperimentConfig& c, std::int64_t frames, std::int64_t dim) {
  std::vector<Team> teams;
  const auto f = static_cast<double>(frames);
  const DatasetConfig& d = c.dataset;
  for (const int n : c.sweep.robots) {
    // dataset.trajectories cannot be worked out before they are read (and takes no frames key).
    const bool scenario = d.trajectories.empty() && d.scenario.kind != ScenarioKind::kSplit;
    teams.push_back(scenario ? ScenarioTeam(d.scenario, n, f, d.fps) : SplitTeam(n, f, d.fps));
  }
  return Estimate(c, teams, static_cast<double>(dim));
}

SweepSize EstimateSweepSize(const ExperimentConfig& c, const Dataset& deployment) {
  std::vector<Team> teams;
  for (const int n : c.sweep.robots) {
    teams.push_back(deployment.plan ? PlannedTeam(deployment.plan->First(n), deployment.fps)
                                    : SplitTeam(n, static_cast<double>(deployment.size()), deployment.fps));
  }
  return Estimate(c, teams, static_cast<double>(deployment.dim()));
}

std::vector<double> RunSeconds(const ExperimentConfig& c, const Dataset& deployment, const std::vector<RunSpec>& specs) {
  std::map<std::pair<std::string, int>, double> seconds;  // by protocol and team
  std::vector<double> out;
  out.reserve(specs.size());
  for (const RunSpec& spec : specs) {
    auto [it, added] = seconds.try_emplace({spec.protocol, spec.robots}, 0.0);
    if (added) {
      const RunShape shape = ShapeOf(c, static_cast<double>(deployment.dim()), {spec.protocol});
      const Team team = deployment.plan ? PlannedTeam(deployment.plan->First(spec.robots), deployment.fps)
                                        : SplitTeam(spec.robots, static_cast<double>(deployment.size()), deployment.fps);
      it->second = EstimateRun(shape, team).Seconds();
    }
    out.push_back(it->second);
  }
  return out;
}

SweepMachine SweepMachine::ThisOne(int threads) {
  return {.memory_bytes = PhysicalMemoryBytes(),
          .cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency())),
          .threads = threads};
}

double PhysicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 0;
  return static_cast<double>(pages) * static_cast<double>(page);
}


void CheckSweepSize(const SweepSize& size, const SweepMachine& machine, const std::string& origin) {
  if (size.runs > kMaxSweepRuns) {
    throw ConfigError(origin + ": robots, runs, protocols, strategies, network: the sweep has " + Figure(size.runs) +
                      " runs (robot counts x runs x strategies x network variants), more than " +
                      Figure(kMaxSweepRuns) + " (days of computing); narrow it, or pass --allow-large to run it anyway");
  }
  const int cores = std::max(1, machine.cores);
  // Runs in flight at once: one per thread (ParallelFor), never more than there are runs.
  const double at_once = std::max(1.0, std::min(static_cast<double>(machine.threads > 0 ? machine.threads : cores), size.runs));
  CheckMemory(size, machine, at_once, origin);
  CheckTime(size, std::min(at_once, static_cast<double>(cores)), origin);
}

}  // namespace dvpr
