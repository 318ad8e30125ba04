// The network alone of dvpr's 100-robot KITTI 00 broadcast, in ns-3.37 (Debian's libns3-dev):
// the peer of dvpr's broadcast simulation (bench/bench_simulation.cpp); see bench/peers/README.md.
//   apt-get install libns3-dev
//   g++ -O2 -std=c++17 bench/peers/broadcast_ns3.cc -o /tmp/broadcast_ns3 -lns3-core \
//       -lns3-network -lns3-internet -lns3-point-to-point -lns3-traffic-control -lns3-bridge
//   /usr/bin/time -v /tmp/broadcast_ns3 [robots=100] [frames=4541]
//
// dvpr's default network (docs/network_model.md, docs/config.md): point_to_point, one full-duplex
// link per pair at 10 Mbit/s, 2 ms latency, drop-tail queue of 100 packets, MTU 1500, PPP framing.
// The sequence of N frames is split into n contiguous parts (robot r gets frames
// [floor(rN/n), floor((r+1)N/n))), each robot takes its frames at 10 fps from t = 0 and sends
// each frame's query (query_t on DVPR_QUERY_ALL: 567 bytes of UDP payload, 595 bytes of IP
// packet) to each of the n - 1 others, one UDP datagram per link, as dvpr's broadcast does on
// point_to_point. Only the network: no descriptors, no search, no replies.
#include <chrono>
#include <ctime>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "ns3/core-module.h"
#include "ns3/internet-module.h"
#include "ns3/network-module.h"
#include "ns3/point-to-point-module.h"

using namespace ns3;

namespace {

constexpr uint32_t kQueryUdpPayload = 567;  // 8 + 14 + 1 + 544: LCM header, channel, NUL, query_t
constexpr uint16_t kPort = 7667;
uint64_t g_received = 0;

void Receive(Ptr<Socket> socket) {
  while (socket->Recv()) ++g_received;
}

// Robot `from` sends one query to every other robot, over the link to each.
void SendQuery(Ptr<Socket> socket, const std::vector<InetSocketAddress>* peers) {
  for (const auto& peer : *peers) socket->SendTo(Create<Packet>(kQueryUdpPayload), 0, peer);
}

}  // namespace

int main(int argc, char** argv) {
  const int robots = argc > 1 ? std::atoi(argv[1]) : 100;
  const int frames = argc > 2 ? std::atoi(argv[2]) : 4541;
  const double fps = 10.0;
  // Wall and CPU clocks: on a shared machine the CPU time is the steadier figure.
  const auto setup_start = std::chrono::steady_clock::now();
  const std::clock_t setup_cpu = std::clock();

  NodeContainer nodes;
  nodes.Create(robots);
  InternetStackHelper internet;
  internet.Install(nodes);
  PointToPointHelper p2p;
  p2p.SetDeviceAttribute("DataRate", StringValue("10Mbps"));
  p2p.SetChannelAttribute("Delay", StringValue("2ms"));
  p2p.SetQueue("ns3::DropTailQueue<Packet>", "MaxSize", StringValue("100p"));
  Ipv4AddressHelper addresses("10.0.0.0", "255.255.255.252");
  // peers[i]: the address of every other robot on its link with i (a connected /30: no routing).
  std::vector<std::vector<InetSocketAddress>> peers(robots);
  for (int i = 0; i < robots; ++i) {
    for (int j = i + 1; j < robots; ++j) {
      NetDeviceContainer link = p2p.Install(nodes.Get(i), nodes.Get(j));
      Ipv4InterfaceContainer ifaces = addresses.Assign(link);
      addresses.NewNetwork();
      peers[i].emplace_back(ifaces.GetAddress(1), kPort);
      peers[j].emplace_back(ifaces.GetAddress(0), kPort);
    }
  }
  const TypeId udp = UdpSocketFactory::GetTypeId();
  std::vector<Ptr<Socket>> senders;
  for (int r = 0; r < robots; ++r) {
    Ptr<Socket> sink = Socket::CreateSocket(nodes.Get(r), udp);
    sink->Bind(InetSocketAddress(Ipv4Address::GetAny(), kPort));
    sink->SetRecvCallback(MakeCallback(&Receive));
    senders.push_back(Socket::CreateSocket(nodes.Get(r), udp));
    senders.back()->Bind();
    const int first = static_cast<int>(int64_t{r} * frames / robots);
    const int last = static_cast<int>(int64_t{r + 1} * frames / robots);
    for (int f = first; f < last; ++f) {
      Simulator::Schedule(Seconds((f - first) / fps), &SendQuery, senders.back(), &peers[r]);
    }
  }
  const auto run_start = std::chrono::steady_clock::now();
  const std::clock_t run_cpu = std::clock();
  Simulator::Run();
  const auto run_end = std::chrono::steady_clock::now();
  const std::clock_t end_cpu = std::clock();
  const double virtual_s = Simulator::Now().GetSeconds();
  Simulator::Destroy();

  const auto secs = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  const uint64_t sent = uint64_t(frames) * uint64_t(robots - 1);
  std::printf("ns-3 %d robots, %d queries, %llu datagrams sent, %llu received, virtual end %.3f s\n",
              robots, frames, static_cast<unsigned long long>(sent),
              static_cast<unsigned long long>(g_received), virtual_s);
  const auto cpu = [](std::clock_t a, std::clock_t b) { return double(b - a) / CLOCKS_PER_SEC; };
  std::printf("setup %.2f s wall %.2f s CPU; Simulator::Run %.2f s wall %.2f s CPU\n",
              secs(setup_start, run_start), cpu(setup_cpu, run_cpu), secs(run_start, run_end),
              cpu(run_cpu, end_cpu));
  return 0;
}
