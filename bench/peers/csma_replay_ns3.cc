// Replays one run of a dvpr messages.csv, open-loop, over ns-3.37's CSMA (Debian's libns3-dev):
// the peer of dvpr's `csma` link model (net_models/csma_link.h); see bench/peers/README.md,
// section 4.
//   apt-get install libns3-dev
//   g++ -O2 -std=c++17 bench/peers/csma_replay_ns3.cc -o /tmp/csma_replay_ns3 -lns3-core \
//       -lns3-network -lns3-internet -lns3-csma -lns3-traffic-control -lns3-bridge
//   /tmp/csma_replay_ns3 --messages=messages.csv --out=ns3.csv [--rate=10Mbps] [--delay=2ms]
//       [--queue=100] [--mtu=1500] [--protocol=sim --strategy=broadcast --robots=4 --run=0 --variant=0]
//
// n nodes on one CsmaChannel (DataRate, Delay), each a CsmaNetDevice (DIX framing, MTU 1500) with
// a DropTail queue of `queue` packets, IPv4 only (10.1.0.0/16). dvpr has neither ARP nor a
// traffic-control queue disc: the ARP caches are filled before the run (NeighborCacheHelper), so
// no ARP frame is sent, and the root queue disc the address helper installs is removed, so IP
// hands each packet straight to the device queue. IPv6 is not installed (its DAD and MLD
// messages would be traffic dvpr does not have). Every message is sent at its sent_ns as
// replay_common.h describes; the output has one line per row with the ns-3 arrival time.
#include <cstdio>
#include <map>
#include <string>

#include "ns3/core-module.h"
#include "ns3/csma-module.h"
#include "ns3/internet-module.h"
#include "ns3/network-module.h"
#include "ns3/traffic-control-module.h"
#include "replay_common.h"

using namespace ns3;

namespace {

struct CsmaCounters {
  std::map<uint16_t, uint64_t> frames_by_ethertype;  // PhyTxBegin, by EtherType
  uint64_t not_udp = 0;                              // IPv4 frames of another protocol (ICMP)
  uint64_t backoffs = 0;                             // MacTxBackoff
  uint64_t queue_drops = 0;                          // MacTxDrop (device queue full)
  uint64_t tc_drops = 0;  // TcDrop: the device queue was full, so flow control had stopped it
  uint64_t retry_drops = 0;                          // PhyTxDrop (backoff retries exhausted)
};
CsmaCounters g_counters;

void OnPhyTxBegin(Ptr<const Packet> p) {
  EthernetHeader eth(false);
  Ptr<Packet> copy = p->Copy();
  copy->RemoveHeader(eth);
  ++g_counters.frames_by_ethertype[eth.GetLengthType()];
  Ipv4Header ip;
  if (eth.GetLengthType() == 0x0800 && copy->PeekHeader(ip) && ip.GetProtocol() != UdpL4Protocol::PROT_NUMBER) {
    ++g_counters.not_udp;
  }
}
void OnBackoff(Ptr<const Packet>) { ++g_counters.backoffs; }
void OnQueueDrop(Ptr<const Packet>) { ++g_counters.queue_drops; }
void OnRetryDrop(Ptr<const Packet>) { ++g_counters.retry_drops; }
void OnTcDrop(Ptr<const Packet>) { ++g_counters.tc_drops; }

}  // namespace

int main(int argc, char** argv) {
  std::string messages, out = "/tmp/peers/csma_replay.csv";
  std::string rate = "10Mbps", delay = "2ms";
  uint32_t queue = 100, mtu = 1500;
  replay::RunFilter filter;
  CommandLine cmd(__FILE__);
  cmd.AddValue("messages", "dvpr messages.csv to replay", messages);
  cmd.AddValue("out", "output CSV (one line per replayed row)", out);
  cmd.AddValue("rate", "CsmaChannel DataRate (dvpr network.bandwidth)", rate);
  cmd.AddValue("delay", "CsmaChannel Delay (dvpr network.latency)", delay);
  cmd.AddValue("queue", "DropTail device queue in packets (dvpr network.queue_packets)", queue);
  cmd.AddValue("mtu", "device MTU (dvpr network.mtu)", mtu);
  replay::AddRunFilter(cmd, filter);
  cmd.Parse(argc, argv);
  if (messages.empty()) {
    std::fprintf(stderr, "csma_replay_ns3: --messages=FILE is required\n");
    return 2;
  }
  const auto setup_wall = std::chrono::steady_clock::now();
  replay::Trace trace;
  try {
    trace = replay::ReadMessages(messages, filter);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "csma_replay_ns3: %s\n", e.what());
    return 1;
  }

  NodeContainer nodes;
  nodes.Create(uint32_t(trace.nodes));
  CsmaHelper csma;
  csma.SetChannelAttribute("DataRate", DataRateValue(DataRate(rate)));
  csma.SetChannelAttribute("Delay", TimeValue(Time(delay)));
  csma.SetDeviceAttribute("Mtu", UintegerValue(mtu));
  csma.SetQueue("ns3::DropTailQueue<Packet>", "MaxSize",
                QueueSizeValue(QueueSize(QueueSizeUnit::PACKETS, queue)));
  NetDeviceContainer devices = csma.Install(nodes);

  const std::unique_ptr<replay::Replayer> replayer = replay::Prepare(trace, nodes, devices);
  for (uint32_t i = 0; i < devices.GetN(); ++i) {
    Ptr<NetDevice> d = devices.Get(i);
    d->TraceConnectWithoutContext("PhyTxBegin", MakeCallback(&OnPhyTxBegin));
    d->TraceConnectWithoutContext("MacTxBackoff", MakeCallback(&OnBackoff));
    d->TraceConnectWithoutContext("MacTxDrop", MakeCallback(&OnQueueDrop));
    d->TraceConnectWithoutContext("PhyTxDrop", MakeCallback(&OnRetryDrop));
    nodes.Get(i)->GetObject<TrafficControlLayer>()->TraceConnectWithoutContext("TcDrop", MakeCallback(&OnTcDrop));
  }
  const double setup_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_wall).count();

  replay::RunTimes times;
  if (!replay::RunAndWrite("csma_replay_ns3", trace, *replayer, out, times)) return 1;
  std::printf("ns-3.37 csma %s %s, queue %u packets, MTU %u; %s -> %s\n", rate.c_str(), delay.c_str(),
              queue, mtu, messages.c_str(), out.c_str());
  replay::PrintSummary(trace, *replayer, times);
  uint64_t frames = 0;
  for (const auto& [type, n] : g_counters.frames_by_ethertype) frames += n;
  std::printf("frames %llu (IPv4 %llu of which not UDP %llu, ARP %llu), backoffs %llu, queue-full drops %llu (device %llu, "
              "traffic control %llu), retry-limit drops %llu; setup %.3f s wall\n",
              static_cast<unsigned long long>(frames),
              static_cast<unsigned long long>(g_counters.frames_by_ethertype[0x0800]),
              static_cast<unsigned long long>(g_counters.not_udp),
              static_cast<unsigned long long>(g_counters.frames_by_ethertype[0x0806]),
              static_cast<unsigned long long>(g_counters.backoffs),
              static_cast<unsigned long long>(g_counters.queue_drops + g_counters.tc_drops),
              static_cast<unsigned long long>(g_counters.queue_drops),
              static_cast<unsigned long long>(g_counters.tc_drops),
              static_cast<unsigned long long>(g_counters.retry_drops), setup_s);
  Simulator::Destroy();
  return 0;
}
