// Bare scheduler throughput: events executed per second.
//   build/netA-rel/bench/bench_scheduler --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "bench/bench_main.h"

#include <cstdint>
#include <vector>

#include "sim/event_heap.h"
#include "sim/radix_event_queue.h"
#include "sim/random.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

// Pseudo-random delays in [1, 1'000'000] ns, drawn before timing starts.
std::vector<std::int64_t> Delays(std::size_t n) {
  RandomStream rng(1, ComponentId("bench"));
  std::vector<std::int64_t> d(n);
  for (auto& x : d) x = 1 + static_cast<std::int64_t>(rng.UniformInt(1'000'000));
  return d;
}

// The classic "hold" model: `pending` events in the queue; each one, when it
// runs, schedules one more at a random delay until `budget` events have run.
struct Hold {
  Simulator* sim;
  const std::vector<std::int64_t>* delays;
  std::uint64_t* remaining;
  void operator()() const {
    if (*remaining == 0) return;
    --*remaining;
    const std::int64_t d = (*delays)[*remaining & (delays->size() - 1)];
    sim->Schedule(SimTime::Nanos(d), *this);
  }
};

void BM_HoldModel(benchmark::State& state) {
  const auto pending = static_cast<std::size_t>(state.range(0));
  const auto delays = Delays(1 << 16);
  constexpr std::uint64_t kEvents = 2'000'000;
  std::uint64_t executed = 0;
  for (auto _ : state) {
    Simulator sim;
    std::uint64_t remaining = kEvents;
    for (std::size_t i = 0; i < pending; ++i) sim.Schedule(SimTime::Nanos(delays[i % delays.size()]), Hold{&sim, &delays, &remaining});
    sim.Run();
    executed += sim.EventsExecuted();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(executed));
}
BENCHMARK(BM_HoldModel)->Arg(16)->Arg(1024)->Arg(65536)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

// The hold model in its steady state, as the classic queue studies time it: one Simulator is
// filled with `pending` events and run through `pending` more before timing starts; then every
// iteration runs 2 000 000 events and every one of them schedules its successor, so exactly
// `pending` events wait throughout. BM_HoldModel above also times the filling from an empty
// queue, the draining to none and the kernel clearing each new Simulator's memory.
struct SteadyHold {
  Simulator* sim;
  const std::vector<std::int64_t>* delays;
  std::uint64_t* remaining;
  void operator()() const {
    const std::int64_t d = (*delays)[*remaining & (delays->size() - 1)];
    sim->Schedule(SimTime::Nanos(d), *this);
    if (--*remaining == 0) sim->Stop();
  }
};

void BM_HoldSteady(benchmark::State& state) {
  const auto pending = static_cast<std::size_t>(state.range(0));
  const auto delays = Delays(1 << 16);
  constexpr std::uint64_t kEvents = 2'000'000;
  Simulator sim;
  std::uint64_t remaining = pending;  // the warm-up: every event once
  for (std::size_t i = 0; i < pending; ++i) {
    sim.Schedule(SimTime::Nanos(delays[i % delays.size()]), SteadyHold{&sim, &delays, &remaining});
  }
  sim.Run();
  std::uint64_t executed = 0;
  for (auto _ : state) {
    remaining = kEvents;
    const std::uint64_t before = sim.EventsExecuted();
    sim.Run();
    executed += sim.EventsExecuted() - before;
  }
  if (sim.PendingEvents() != pending) state.SkipWithError("the pending count drifted");
  state.SetItemsProcessed(static_cast<std::int64_t>(executed));
}
BENCHMARK(BM_HoldSteady)->Arg(16)->Arg(1024)->Arg(65536)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

// The hold model on a bare queue, to choose the Simulator's queue (issue 15): pop the earliest
// (time, key) entry, push one at a random delay after it, `pending` entries throughout.
template <typename Queue>
void BM_QueueHold(benchmark::State& state) {
  const auto pending = static_cast<std::size_t>(state.range(0));
  const auto delays = Delays(1 << 16);
  constexpr std::uint64_t kOps = 4'000'000;
  std::uint64_t done = 0;
  for (auto _ : state) {
    Queue q;
    std::uint64_t key = 1;
    for (std::size_t i = 0; i < pending; ++i) q.Push({delays[i & 0xFFFF], key++});
    for (std::uint64_t i = 0; i < kOps; ++i) {
      const auto e = q.Pop();
      q.Push({e.time + delays[i & 0xFFFF], key++});
    }
    benchmark::DoNotOptimize(q.size());
    done += kOps;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(done));
}
BENCHMARK(BM_QueueHold<EventHeap>)->Arg(16)->Arg(1024)->Arg(65536)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_QueueHold<RadixEventQueue>)->Arg(16)->Arg(1024)->Arg(65536)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

// Schedule a batch of events at random times, then run them all.
void BM_ScheduleThenRun(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto delays = Delays(1 << 16);
  std::uint64_t executed = 0;
  std::uint64_t sink = 0;
  for (auto _ : state) {
    Simulator sim;
    for (std::size_t i = 0; i < n; ++i) {
      sim.Schedule(SimTime::Nanos(delays[i & (delays.size() - 1)]), [&sink, i] { sink += i; });
    }
    sim.Run();
    executed += sim.EventsExecuted();
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(static_cast<std::int64_t>(executed));
}
BENCHMARK(BM_ScheduleThenRun)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

// Half the scheduled events are cancelled before they run (timers re-armed).
void BM_ScheduleCancelRun(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto delays = Delays(1 << 16);
  std::uint64_t handled = 0;
  for (auto _ : state) {
    Simulator sim;
    std::vector<EventId> ids;
    ids.reserve(n);
    for (std::size_t i = 0; i < n; ++i) ids.push_back(sim.Schedule(SimTime::Nanos(delays[i & 0xFFFF]), [] {}));
    for (std::size_t i = 0; i < n; i += 2) sim.Cancel(ids[i]);
    sim.Run();
    handled += n;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(handled));
}
BENCHMARK(BM_ScheduleCancelRun)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace dvpr

DVPR_BENCHMARK_MAIN()
