// Messages through the simulated network.
//   build/netA-rel/bench/bench_network --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// items_per_second counts messages (one per destination) sent and delivered,
// including the simulator events that deliver them.
#include <benchmark/benchmark.h>

#include "bench/bench_main.h"

#include <memory>
#include <string>
#include <vector>

#include "agents/messages/channels.h"
#include "agents/messages/sim_transport.h"
#include "agents/messages/verification_payload.h"
#include "experiments/protocols/sim/message_rows.h"
#include "net_models/medium/point_to_point_link.h"
#include "net_models/network/network.h"
#include "sim/random.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

constexpr int kKittiFrames = 4541;  // KITTI 00 at 10 Hz, split among the robots
constexpr std::size_t kQueryBytes = 544;  // query_t with 128 floats and its capture time
constexpr std::size_t kMatchBytes = 35;   // match_t

std::unique_ptr<LinkModel> PointToPoint(int nodes) {
  return std::make_unique<PointToPointLink>(PointToPointParams{DataRate::Mbps(10), SimTime::Millis(2), 100, {}},
                                            nodes);
}

// Unicast messages between random pairs of 10 nodes, 1 per 10 us.
void BM_PointToPointUnicast(benchmark::State& state) {
  constexpr int kNodes = 10;
  constexpr int kMessages = 200000;
  std::uint64_t delivered = 0;
  for (auto _ : state) {
    Simulator sim;
    Network net(sim, kNodes, PointToPoint(kNodes));
    std::vector<ChannelId> inbox;
    for (int i = 0; i < kNodes; ++i) {
      inbox.push_back(net.InternChannel("IN_" + std::to_string(i)));
      net.Join(NodeId(i), inbox.back());
    }
    const MessageTypeId type = net.InternType("dvpr.query_t");
    RandomStream rng(1, 2);
    for (int m = 0; m < kMessages; ++m) {
      const auto src = static_cast<int>(rng.UniformInt(kNodes));
      const auto dst = static_cast<int>((src + 1 + rng.UniformInt(kNodes - 1)) % kNodes);
      sim.ScheduleAt(SimTime::Micros(10 * m), [&net, &inbox, type, src, dst] {
        net.Send(NodeId(src), inbox[dst], type, std::vector<std::uint8_t>(kQueryBytes));
      });
    }
    sim.Run();
    delivered += net.Totals().delivered;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(delivered));
}
BENCHMARK(BM_PointToPointUnicast)->Unit(benchmark::kMillisecond);

// Raw network level: every node replies to each broadcast query at once.
class Responder : public NetworkEndpoint {
 public:
  Responder(Network& net, NodeId self, ChannelId query, const std::vector<ChannelId>& match, MessageTypeId type)
      : net_(net), self_(self), query_(query), match_(match), type_(type) {}
  void OnReceive(const ReceivedMessage& m) override {
    if (m.channel == query_) net_.Send(self_, match_[static_cast<std::size_t>(m.src.value)], type_,
                                       std::vector<std::uint8_t>(kMatchBytes));
  }

 private:
  Network& net_;
  NodeId self_;
  ChannelId query_;
  const std::vector<ChannelId>& match_;
  MessageTypeId type_;
};

// Robot r takes frames [floor(rN/n), floor((r+1)N/n)) of KITTI 00, its k-th at k x 100 ms.
template <typename Publish>
void ScheduleFrames(Simulator& sim, int robots, Publish publish) {
  for (int r = 0; r < robots; ++r) {
    const int first = r * kKittiFrames / robots;
    const int last = (r + 1) * kKittiFrames / robots;
    for (int f = first; f < last; ++f) {
      sim.ScheduleAt(SimTime::Millis(100 * (f - first)), [publish, r, f] { publish(r, f); });
    }
  }
}

// 100 robots broadcasting 544-byte queries for the 4541 KITTI 00 frames; every
// other robot answers with a 35-byte match: 4541 x 99 x 2 = 899 118 messages.
void BM_Kitti100BroadcastNetwork(benchmark::State& state) {
  const int robots = static_cast<int>(state.range(0));
  const bool records = state.range(1) != 0;
  std::uint64_t delivered = 0;
  for (auto _ : state) {
    Simulator sim;
    Network net(sim, robots, PointToPoint(robots));
    // With records: the messages.csv rows a simulation keeps, through the network's hooks.
    MessageRowRecorder rows;
    ObserverSubscription subscription;
    if (records) subscription = net.Subscribe(rows);
    const ChannelId query = net.InternChannel(channels::kQueryAll);
    std::vector<ChannelId> match;
    for (int r = 0; r < robots; ++r) match.push_back(net.InternChannel(channels::Match(RobotId(r))));
    const MessageTypeId qt = net.InternType("dvpr.query_t");
    const MessageTypeId mt = net.InternType("dvpr.match_t");
    std::vector<std::unique_ptr<Responder>> nodes;
    for (int r = 0; r < robots; ++r) {
      nodes.push_back(std::make_unique<Responder>(net, NodeId(r), query, match, mt));
      net.Attach(NodeId(r), nodes.back().get());
      net.Join(NodeId(r), query);
      net.Join(NodeId(r), match[static_cast<std::size_t>(r)]);
    }
    Network* n = &net;
    ScheduleFrames(sim, robots, [n, query, qt](int r, int) {
      n->Send(NodeId(r), query, qt, std::vector<std::uint8_t>(kQueryBytes));
    });
    sim.Run();
    delivered += net.Totals().delivered;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(delivered));
}
BENCHMARK(BM_Kitti100BroadcastNetwork)->Args({100, 0})->Args({100, 1})->Unit(benchmark::kMillisecond);

// The same traffic through SimTransport with real LCM encoding and decoding.
void BM_Kitti100BroadcastTransport(benchmark::State& state) {
  const int robots = static_cast<int>(state.range(0));
  std::uint64_t delivered = 0;
  for (auto _ : state) {
    Simulator sim;
    Network net(sim, robots, PointToPoint(robots));
    std::vector<std::unique_ptr<SimTransport>> transports;
    std::vector<Subscription> subs;
    for (int r = 0; r < robots; ++r) {
      transports.push_back(std::make_unique<SimTransport>(net, NodeId(r)));
      SimTransport* t = transports.back().get();
      subs.push_back(t->Subscribe<query_t>(channels::kQueryAll, [t, r](const query_t& q) {
        match_t m{};
        m.utime = t->Now().us();
        m.query_robot = q.robot;
        m.query_frame = q.frame;
        m.responder = static_cast<std::int16_t>(r);
        t->Publish(channels::Match(RobotId(q.robot)), m);
      }));
      subs.push_back(t->Subscribe<match_t>(channels::Match(RobotId(r)), [](const match_t&) {}));
    }
    query_t proto{};
    proto.dim = 128;
    proto.descriptor.assign(128, 0.5f);
    ScheduleFrames(sim, robots, [&transports, &proto](int r, int f) {
      query_t q = proto;
      q.robot = static_cast<std::int16_t>(r);
      q.frame = f;
      transports[static_cast<std::size_t>(r)]->Publish(channels::kQueryAll, q);
    });
    sim.Run();
    delivered += net.Totals().delivered;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(delivered));
}
BENCHMARK(BM_Kitti100BroadcastTransport)->Arg(100)->Unit(benchmark::kMillisecond);

// The 25 000-byte payload of one verification request (10^6 frames x 1000 robots: 909 k of them).
void BM_VerificationPayload(benchmark::State& state) {
  std::vector<float> descriptor(128, 0.25f);
  std::vector<std::uint8_t> payload(25000);
  int frame = 0;
  for (auto _ : state) {
    FillVerificationPayload(FrameId(frame++), descriptor, payload);
    benchmark::DoNotOptimize(payload.data());
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(payload.size()));
}
BENCHMARK(BM_VerificationPayload)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace dvpr

DVPR_BENCHMARK_MAIN()
