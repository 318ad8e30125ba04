// Replays one run of a dvpr messages.csv, open-loop, over ns-3.37's 802.11a ad hoc Wi-Fi (Debian's
// libns3-dev): the peer of dvpr's `wifi` link model (net_models/wifi_link.h); see
// bench/peers/README.md, section 4.
//   apt-get install libns3-dev
//   g++ -O2 -std=c++17 bench/peers/wifi_replay_ns3.cc -o /tmp/wifi_replay_ns3 -lns3-core \
//       -lns3-network -lns3-internet -lns3-wifi -lns3-mobility -lns3-propagation \
//       -lns3-traffic-control -lns3-bridge
//   /tmp/wifi_replay_ns3 --messages=messages.csv --out=ns3.csv [--rate=54] [--queue=100]
//       [--ack6=0|1] [--positions=pos.csv --range=100] [--run filters as csma_replay_ns3]
//
// n stations, 802.11a (WIFI_STANDARD_80211a), AdhocWifiMac without QoS (DCF: slot 9 us, SIFS
// 16 us, DIFS 34 us, CWmin 15, CWmax 1023), ConstantRateWifiManager (DataMode OfdmRate<rate>Mbps,
// ControlMode OfdmRate6Mbps, broadcast frames at OfdmRate6Mbps), RTS/CTS and 802.11
// fragmentation off (thresholds above any frame; IP fragments at MTU 1500), a YansWifiChannel
// with ConstantSpeedPropagationDelayModel. Propagation loss: by default every station stands at
// the origin and hears every other at -30 dBm (FixedRssLossModel): dvpr's full mesh, no
// propagation delay. With --positions (a CSV node,x,y) and --range the stations stand still
// there and RangePropagationLossModel (MaxRange = --range) decides who hears whom. A moving team
// (dvpr's wifi over the radio follows the trajectories) is not replayed.
//
// Queue: dvpr's queue_packets counts the frames waiting behind the one contending or on the air;
// ns-3's WifiMacQueue keeps that one in the queue until it is acknowledged (a broadcast until it
// is sent), so MaxSize is set to queue + 1 packets. WifiMacQueue's MaxDelay (500 ms by default)
// drops frames that waited longer; dvpr has no lifetime, so it is set to 10^6 s.
//
// ACK rate: ns-3 answers a frame at the highest rate of the BSS basic rate set no faster than
// the frame; an ad hoc station puts every mandatory 802.11a rate (6, 12, 24 Mbit/s) in that set,
// so at 24 Mbit/s and above ns-3 sends its ACKs at 24 Mbit/s, as dvpr's AckRate does.
// --ack6=1 makes ns-3 send them at 6 Mbit/s instead: the basic rate set is 6 Mbit/s alone (every
// station knows the others before the run, so none adds the mandatory rates to it).
// ARP, IPv6 and the queue disc are handled as in csma_replay_ns3.cc.
#include <cstdio>
#include <fstream>
#include <map>
#include <string>

#include "ns3/core-module.h"
#include "ns3/internet-module.h"
#include "ns3/mobility-module.h"
#include "ns3/network-module.h"
#include "ns3/propagation-module.h"
#include "ns3/traffic-control-module.h"
#include "ns3/wifi-module.h"
#include "replay_common.h"

using namespace ns3;

namespace {

struct WifiCounters {
  uint64_t data_unicast = 0, data_broadcast = 0, acks = 0, other = 0, arp = 0;  // PhyTxBegin
  uint64_t not_udp = 0;                                                          // IPv4, not UDP (ICMP)
  uint64_t data_failed = 0;                                                      // MacTxDataFailed
  std::map<int, uint64_t> dropped;                                               // DroppedMpdu, by reason
  uint64_t tc_drops = 0;                                                         // TcDrop
  uint64_t rx_errors = 0;                                                        // PhyRxDrop
};
WifiCounters g_counters;

void OnPhyTxBegin(Ptr<const Packet> p, double) {
  WifiMacHeader hdr;
  Ptr<Packet> copy = p->Copy();
  copy->RemoveHeader(hdr);
  if (hdr.IsAck()) {
    ++g_counters.acks;
  } else if (hdr.IsData()) {
    LlcSnapHeader llc;
    copy->RemoveHeader(llc);
    if (llc.GetType() == 0x0806) ++g_counters.arp;
    Ipv4Header ip;
    if (llc.GetType() == 0x0800 && copy->PeekHeader(ip) && ip.GetProtocol() != UdpL4Protocol::PROT_NUMBER) {
      ++g_counters.not_udp;
    }
    ++(hdr.GetAddr1().IsGroup() ? g_counters.data_broadcast : g_counters.data_unicast);
  } else {
    ++g_counters.other;
  }
}
void OnDataFailed(Mac48Address) { ++g_counters.data_failed; }
void OnDropped(WifiMacDropReason reason, Ptr<const WifiMpdu>) { ++g_counters.dropped[int(reason)]; }
void OnTcDrop(Ptr<const Packet>) { ++g_counters.tc_drops; }
void OnRxDrop(Ptr<const Packet>, WifiPhyRxfailureReason) { ++g_counters.rx_errors; }

}  // namespace

int main(int argc, char** argv) {
  std::string messages, out = "/tmp/peers/wifi_replay.csv", positions;
  uint32_t rate_mbps = 54, queue = 100, mtu = 1500;
  double range = 0;
  bool ack6 = false;
  replay::RunFilter filter;
  CommandLine cmd(__FILE__);
  cmd.AddValue("messages", "dvpr messages.csv to replay", messages);
  cmd.AddValue("out", "output CSV (one line per replayed row)", out);
  cmd.AddValue("rate", "data rate in Mbit/s: 6, 9, 12, 18, 24, 36, 48 or 54 (dvpr network.wifi.rate)", rate_mbps);
  cmd.AddValue("queue", "frames waiting behind the current one (dvpr network.queue_packets)", queue);
  cmd.AddValue("mtu", "WifiNetDevice MTU (dvpr network.mtu)", mtu);
  cmd.AddValue("ack6", "1: ACKs at 6 Mbit/s as dvpr (basic rate set {6 Mbit/s}); 0: ns-3's own choice", ack6);
  cmd.AddValue("positions", "CSV node,x,y (metres): static positions, with --range", positions);
  cmd.AddValue("range", "RangePropagationLossModel MaxRange in metres (with --positions)", range);
  replay::AddRunFilter(cmd, filter);
  cmd.Parse(argc, argv);
  static const uint32_t kRates[] = {6, 9, 12, 18, 24, 36, 48, 54};
  if (messages.empty() || std::find(std::begin(kRates), std::end(kRates), rate_mbps) == std::end(kRates) ||
      positions.empty() != (range <= 0)) {
    std::fprintf(stderr, "wifi_replay_ns3: needs --messages=FILE, --rate one of 6 9 12 18 24 36 48 54, "
                         "and --positions with --range > 0 or neither\n");
    return 2;
  }
  const auto setup_wall = std::chrono::steady_clock::now();
  replay::Trace trace;
  std::map<int, Vector> placed;
  try {
    trace = replay::ReadMessages(messages, filter);
    if (!positions.empty()) {
      std::ifstream in(positions);
      if (!in) throw std::runtime_error(positions + ": cannot open");
      std::string line;
      while (std::getline(in, line)) {
        const std::vector<std::string> f = replay::SplitCsv(line);
        if (f.size() < 3 || f[0].empty() || !std::isdigit(static_cast<unsigned char>(f[0][0]))) continue;
        placed[std::stoi(f[0])] = Vector(std::stod(f[1]), std::stod(f[2]), 0.0);
      }
      for (int i = 0; i < trace.nodes; ++i) {
        if (!placed.count(i)) throw std::runtime_error(positions + ": no position for node " + std::to_string(i));
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wifi_replay_ns3: %s\n", e.what());
    return 1;
  }

  Config::SetDefault("ns3::WifiMacQueue::MaxSize", QueueSizeValue(QueueSize(QueueSizeUnit::PACKETS, queue + 1)));
  Config::SetDefault("ns3::WifiMacQueue::MaxDelay", TimeValue(Seconds(1e6)));
  Config::SetDefault("ns3::WifiRemoteStationManager::RtsCtsThreshold", UintegerValue(65535));
  Config::SetDefault("ns3::WifiRemoteStationManager::FragmentationThreshold", UintegerValue(65535));

  NodeContainer nodes;
  nodes.Create(uint32_t(trace.nodes));
  MobilityHelper mobility;
  Ptr<ListPositionAllocator> where = CreateObject<ListPositionAllocator>();
  for (int i = 0; i < trace.nodes; ++i) where->Add(positions.empty() ? Vector(0, 0, 0) : placed[i]);
  mobility.SetPositionAllocator(where);
  mobility.SetMobilityModel("ns3::ConstantPositionMobilityModel");
  mobility.Install(nodes);

  YansWifiChannelHelper channel;
  channel.SetPropagationDelay("ns3::ConstantSpeedPropagationDelayModel");
  if (positions.empty()) {
    channel.AddPropagationLoss("ns3::FixedRssLossModel", "Rss", DoubleValue(-30.0));
  } else {
    channel.AddPropagationLoss("ns3::RangePropagationLossModel", "MaxRange", DoubleValue(range));
  }
  YansWifiPhyHelper phy;
  phy.SetChannel(channel.Create());
  WifiHelper wifi;
  wifi.SetStandard(WIFI_STANDARD_80211a);
  const std::string data_mode = "OfdmRate" + std::to_string(rate_mbps) + "Mbps";
  wifi.SetRemoteStationManager("ns3::ConstantRateWifiManager", "DataMode", StringValue(data_mode),
                               "ControlMode", StringValue("OfdmRate6Mbps"), "NonUnicastMode",
                               WifiModeValue(WifiMode("OfdmRate6Mbps")));
  WifiMacHelper mac;
  mac.SetType("ns3::AdhocWifiMac", "QosSupported", BooleanValue(false));
  NetDeviceContainer devices = wifi.Install(phy, mac, nodes);
  for (uint32_t i = 0; i < devices.GetN(); ++i) devices.Get(i)->SetMtu(uint16_t(mtu));
  if (ack6) {
    for (uint32_t i = 0; i < devices.GetN(); ++i) {
      Ptr<WifiNetDevice> dev = DynamicCast<WifiNetDevice>(devices.Get(i));
      Ptr<WifiRemoteStationManager> manager = dev->GetRemoteStationManager();
      manager->AddBasicMode(WifiMode("OfdmRate6Mbps"));
      for (uint32_t j = 0; j < devices.GetN(); ++j) {
        if (j == i) continue;
        const Mac48Address peer = Mac48Address::ConvertFrom(devices.Get(j)->GetAddress());
        for (const WifiMode& mode : dev->GetPhy()->GetModeList()) manager->AddSupportedMode(peer, mode);
        manager->RecordDisassociated(peer);  // no longer "brand new": AdhocWifiMac leaves it alone
      }
    }
  }

  const std::unique_ptr<replay::Replayer> replayer = replay::Prepare(trace, nodes, devices);
  for (uint32_t i = 0; i < devices.GetN(); ++i) {
    Ptr<WifiNetDevice> dev = DynamicCast<WifiNetDevice>(devices.Get(i));
    dev->GetPhy()->TraceConnectWithoutContext("PhyTxBegin", MakeCallback(&OnPhyTxBegin));
    dev->GetPhy()->TraceConnectWithoutContext("PhyRxDrop", MakeCallback(&OnRxDrop));
    dev->GetRemoteStationManager()->TraceConnectWithoutContext("MacTxDataFailed", MakeCallback(&OnDataFailed));
    dev->GetMac()->TraceConnectWithoutContext("DroppedMpdu", MakeCallback(&OnDropped));
    nodes.Get(i)->GetObject<TrafficControlLayer>()->TraceConnectWithoutContext("TcDrop", MakeCallback(&OnTcDrop));
  }
  const double setup_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_wall).count();

  replay::RunTimes times;
  if (!replay::RunAndWrite("wifi_replay_ns3", trace, *replayer, out, times)) return 1;
  std::printf("ns-3.37 wifi 802.11a %u Mbit/s, ACKs %s, queue %u + 1 packets, MTU %u, %s; %s -> %s\n", rate_mbps,
              ack6 ? "at 6 Mbit/s (--ack6)" : "at ns-3's rate", queue, mtu,
              positions.empty() ? "full mesh" : ("range " + std::to_string(range) + " m").c_str(), messages.c_str(),
              out.c_str());
  replay::PrintSummary(trace, *replayer, times);
  std::printf("PHY frames: data unicast %llu, data broadcast %llu, ACK %llu, other %llu, ARP %llu, IPv4 not UDP %llu; "
              "data failures (no ACK) %llu, RX drops %llu\n",
              (unsigned long long)g_counters.data_unicast, (unsigned long long)g_counters.data_broadcast,
              (unsigned long long)g_counters.acks, (unsigned long long)g_counters.other,
              (unsigned long long)g_counters.arp, (unsigned long long)g_counters.not_udp,
              (unsigned long long)g_counters.data_failed,
              (unsigned long long)g_counters.rx_errors);
  std::printf("queue-full drops %llu (traffic control, the queue stopped by flow control, %llu; MAC %llu), "
              "MPDUs dropped for lifetime %llu, for the retry limit %llu; setup %.3f s wall\n",
              (unsigned long long)(g_counters.tc_drops + g_counters.dropped[WIFI_MAC_DROP_FAILED_ENQUEUE]),
              (unsigned long long)g_counters.tc_drops,
              (unsigned long long)g_counters.dropped[WIFI_MAC_DROP_FAILED_ENQUEUE],
              (unsigned long long)g_counters.dropped[WIFI_MAC_DROP_EXPIRED_LIFETIME],
              (unsigned long long)g_counters.dropped[WIFI_MAC_DROP_REACHED_RETRY_LIMIT], setup_s);
  Simulator::Destroy();
  return 0;
}
