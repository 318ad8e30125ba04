// Whole simulation runs (network and matching), as issue 5 asks:
//   build/release/bench/bench_simulation --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// - KITTI 00 (4541 frames, d = 128) with 100 robots, broadcast and decentralized, on
//   10 Mbit/s point-to-point links with 2 ms latency;
// - decentralized, 1000 robots on a 100 000-frame synthetic trajectory (KITTI 00 tiled 22
//   times, 3 km apart), one iteration; peak RSS reported as a counter.
#include <benchmark/benchmark.h>

#include "bench/bench_main.h"
#include "bench/sim_inputs.h"

#include <cstdint>
#include <cstring>
#include <memory>
#include <type_traits>

#include "agents/placement/decentralized_placement.h"

namespace dvpr {
namespace {

using bench::Csma;
using bench::Kitti00;
using bench::PeakRssMiB;
using bench::PointToPoint;
using bench::Radio;
using bench::Table;
using bench::Wifi;

// FNV-1a over every output of the run a change of speed must leave alone: each query record,
// each robot's load, each pair's counters and role bytes, the senders' medium, the role totals
// and the end time. Not the events: how many the simulator runs is its own business (a
// broadcast's copies that arrive together are one event since session 10), reported apart.
// 48 bits, so the counter (a double) holds it exactly; compare it between builds with
// --benchmark_format=json.
class Checksum {
 public:
  template <class T>
  void Add(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    for (const unsigned char b : bytes) h_ = (h_ ^ b) * 0x100000001b3ull;
  }
  double Value() const { return static_cast<double>(h_ >> 16); }

 private:
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

double OutputChecksum(const SimRunLog& log) {
  Checksum c;
  for (const QueryRecord& q : log.queries) {
    c.Add(q.robot.value), c.Add(q.frame.value), c.Add(q.sent.ns()), c.Add(q.expected_replies);
    c.Add(q.received_replies), c.Add(q.best.has_value()), c.Add(q.latency ? q.latency->ns() : -1);
    if (q.best) c.Add(q.best->robot.value), c.Add(q.best->frame.value), c.Add(q.best->distance);
    c.Add(q.verify_requested), c.Add(q.verify_accepted ? int{*q.verify_accepted} : -1);
  }
  for (const RobotLoad& l : log.loads) {
    c.Add(l.searches), c.Add(l.remote_queries), c.Add(l.comparisons), c.Add(l.stored);
    c.Add(l.verifications), c.Add(l.busy.ns()), c.Add(l.max_queue);
  }
  for (const PairTraffic& p : log.links) {
    c.Add(p.src), c.Add(p.dst), c.Add(p.counters.messages), c.Add(p.counters.payload_bytes);
    c.Add(p.counters.wire_bytes), c.Add(p.counters.delivered), c.Add(p.counters.dropped);
    c.Add(p.roles);
  }
  for (const NodeCounters& s : log.senders) c.Add(s.published), c.Add(s.transmissions), c.Add(s.medium_bytes);
  c.Add(log.roles), c.Add(log.verify_requested), c.Add(log.verify_accepted), c.Add(log.end.ns());
  return c.Value();
}

void Report(benchmark::State& state, const SimRunLog& log) {
  std::int64_t messages = 0;
  for (const auto& l : log.links) messages += static_cast<std::int64_t>(l.counters.messages);
  state.counters["messages"] = static_cast<double>(messages);
  state.counters["events"] = static_cast<double>(log.events);
  state.counters["peak_rss_MiB"] = PeakRssMiB();
  state.counters["checksum"] = OutputChecksum(log);
}

void BM_Kitti00_100Robots(benchmark::State& state, const char* strategy) {
  static const Dataset data = Kitti00();
  const int robots = 100;
  std::unique_ptr<PlacementStrategy> routing;
  if (std::string(strategy) == "broadcast") {
    routing = std::make_unique<BroadcastPlacement>(robots);
  } else {
    routing = std::make_unique<DecentralizedPlacement>(Table(robots, 30));
  }
  SimRunLog log;
  for (auto _ : state) {
    log = RunSimulation(data, *routing, PointToPoint(robots));
    benchmark::DoNotOptimize(log.queries.data());
  }
  Report(state, log);
}
BENCHMARK_CAPTURE(BM_Kitti00_100Robots, broadcast, "broadcast")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Kitti00_100Robots, decentralized, "decentralized")->Unit(benchmark::kMillisecond);

// The 100-robot broadcast on radios of 200 m with shortest-path relays: the cost of positions,
// propagation, routing and relays against the point-to-point run above (issue: within 3x). The
// link_state capture runs each robot's routing daemon and routes on what its beacons taught it.
void BM_Kitti00_100Robots_Radio200m(benchmark::State& state, NextHopKind kind) {
  static const Dataset data = Kitti00();
  const int robots = 100;
  const BroadcastPlacement routing(robots);
  SimRunParams params = Radio(robots, 200.0);
  params.scenario.network.routing = kind;
  SimRunLog log;
  for (auto _ : state) {
    log = RunSimulation(data, routing, params);
    benchmark::DoNotOptimize(log.queries.data());
  }
  Report(state, log);
}
BENCHMARK_CAPTURE(BM_Kitti00_100Robots_Radio200m, shortest_path, NextHopKind::kShortestPath)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Kitti00_100Robots_Radio200m, link_state, NextHopKind::kLinkState)->Unit(benchmark::kMillisecond);

// All of KITTI 00 for a team on one contending medium, both strategies (network and matching):
// the trace the ns-3 peers replay (bench/peers/README.md). Args: robots; wifi rate in Mbit/s
// (0: csma at 10 Mbit/s, 2 ms).
void BM_Kitti00_Contending(benchmark::State& state, const char* strategy) {
  static const Dataset data = Kitti00();
  const int robots = static_cast<int>(state.range(0));
  std::unique_ptr<PlacementStrategy> routing;
  if (std::string(strategy) == "broadcast") {
    routing = std::make_unique<BroadcastPlacement>(robots);
  } else {
    routing = std::make_unique<DecentralizedPlacement>(Table(robots, 30));
  }
  const SimRunParams params = state.range(1) == 0 ? Csma(robots) : Wifi(robots, state.range(1));
  SimRunLog log;
  for (auto _ : state) {
    log = RunSimulation(data, *routing, params);
    benchmark::DoNotOptimize(log.queries.data());
  }
  Report(state, log);
}
BENCHMARK_CAPTURE(BM_Kitti00_Contending, decentralized, "decentralized")
    ->Args({10, 6})->Args({10, 54})->Args({20, 0})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Kitti00_Contending, broadcast, "broadcast")
    ->Args({10, 6})->Args({10, 54})->Args({20, 0})->Unit(benchmark::kMillisecond);

void BM_Decentralized_1000Robots_100kFrames(benchmark::State& state) {
  static const Dataset data = bench::Tiled(23 * 4541);  // 23 copies: 104 443 frames
  const auto table = Table(1000, 10);  // training is not what this measures
  const DecentralizedPlacement routing(table);
  SimRunLog log;
  for (auto _ : state) {
    log = RunSimulation(data, routing, PointToPoint(1000));
    benchmark::DoNotOptimize(log.queries.data());
  }
  Report(state, log);
  state.counters["frames"] = static_cast<double>(data.size());
}
BENCHMARK(BM_Decentralized_1000Robots_100kFrames)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace dvpr

DVPR_BENCHMARK_MAIN()
