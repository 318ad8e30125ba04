// What csma_replay_ns3.cc and wifi_replay_ns3.cc share: reading one run of a dvpr messages.csv,
// grouping its rows into transmissions, the LCM datagrams of each message, sending them open-loop
// from the nodes' UDP sockets at their sent_ns, recording when each complete message reaches each
// of its listed destinations, and the output CSV and summary. See bench/peers/README.md, section 4.
//
// The replay model (docs/network_model.md, "Bytes on the wire"):
// - One message is one LCM datagram of 8 (magic, sequence number) + strlen(channel) + 1 +
//   payload_bytes, sent as one UDP datagram; ns-3 fragments it at the MTU. A message whose
//   channel, NUL and payload exceed 65499 bytes is cut, as lcm_udpm.c does, into LCM fragments of
//   at most 65487 bytes with a 20-byte header each (the first carries the channel): one UDP
//   datagram per fragment, and the message arrives when its last datagram does.
// - Rows that share (sent_ns, src, channel, type, payload_bytes) are one message with several
//   destinations: one UDP datagram to the subnet's broadcast address. A row alone is unicast.
//   If a destination repeats within such a group, each repetition is another message.
// - The first 8 bytes of each datagram hold the transmission's index and the datagram's index, so
//   the receiver knows what arrived; the datagram keeps its size.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "ns3/core-module.h"
#include "ns3/internet-module.h"
#include "ns3/network-module.h"
#include "ns3/traffic-control-module.h"

namespace replay {

constexpr uint16_t kPort = 7667;                 // LCM's default port
constexpr int64_t kLcmShortMax = 65499;          // channel + NUL + payload in one datagram
constexpr int64_t kLcmFragmentData = 65487;      // bytes of the stream per LCM fragment
constexpr int64_t kLcmFragmentHeader = 20;

struct Row {
  int64_t sent_ns = 0;
  int src = 0;
  int dst = 0;
  std::string channel;
  std::string type;
  int64_t payload_bytes = 0;
  std::optional<int64_t> delivered_ns;  // the side this row came from (dvpr, or ns-3 below)
};

// Which run of the file to replay; an empty field takes the first data row's value.
struct RunFilter {
  std::string protocol, strategy, robots, run, variant;
};

struct Trace {
  RunFilter run;  // the values actually used
  std::vector<Row> rows;
  int nodes = 0;  // max(robots, highest src/dst + 1)
};

inline std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.push_back(field);
      field.clear();
    } else if (c != '\r') {
      field += c;
    }
  }
  out.push_back(field);
  return out;
}

inline Trace ReadMessages(const std::string& path, const RunFilter& want) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ": empty file");
  const std::vector<std::string> header = SplitCsv(line);
  std::map<std::string, std::size_t> col;
  for (std::size_t i = 0; i < header.size(); ++i) col[header[i]] = i;
  const auto need = [&](const std::string& name) {
    const auto it = col.find(name);
    if (it == col.end()) throw std::runtime_error(path + ": no column " + name);
    return it->second;
  };
  const auto optional_col = [&](const std::string& name) -> std::optional<std::size_t> {
    const auto it = col.find(name);
    if (it == col.end()) return std::nullopt;
    return it->second;
  };
  const std::size_t c_sent = need("sent_ns"), c_deliv = need("delivered_ns"), c_src = need("src"),
                    c_dst = need("dst"), c_chan = need("channel"), c_type = need("type"),
                    c_pay = need("payload_bytes");
  const auto c_protocol = optional_col("protocol"), c_strategy = optional_col("strategy"),
             c_robots = optional_col("robots"), c_run = optional_col("run"),
             c_variant = optional_col("network_variant");
  Trace t;
  bool first = true;
  int robots = 0;
  int64_t line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line == "\r") continue;
    const std::vector<std::string> f = SplitCsv(line);
    if (f.size() < header.size()) {
      throw std::runtime_error(path + ":" + std::to_string(line_no) + ": " + std::to_string(f.size()) +
                               " fields, the header has " + std::to_string(header.size()));
    }
    const auto get = [&](const std::optional<std::size_t>& c) { return c ? f[*c] : std::string(); };
    if (first) {
      t.run.protocol = want.protocol.empty() ? get(c_protocol) : want.protocol;
      t.run.strategy = want.strategy.empty() ? get(c_strategy) : want.strategy;
      t.run.robots = want.robots.empty() ? get(c_robots) : want.robots;
      t.run.run = want.run.empty() ? get(c_run) : want.run;
      t.run.variant = want.variant.empty() ? get(c_variant) : want.variant;
      first = false;
    }
    if (get(c_protocol) != t.run.protocol || get(c_strategy) != t.run.strategy ||
        get(c_robots) != t.run.robots || get(c_run) != t.run.run || get(c_variant) != t.run.variant) {
      continue;
    }
    Row r;
    r.sent_ns = std::stoll(f[c_sent]);
    r.src = std::stoi(f[c_src]);
    r.dst = std::stoi(f[c_dst]);
    r.channel = f[c_chan];
    r.type = f[c_type];
    r.payload_bytes = std::stoll(f[c_pay]);
    if (!f[c_deliv].empty()) r.delivered_ns = std::stoll(f[c_deliv]);
    t.nodes = std::max({t.nodes, r.src + 1, r.dst + 1});
    t.rows.push_back(std::move(r));
  }
  if (!t.run.robots.empty()) robots = std::stoi(t.run.robots);
  t.nodes = std::max(t.nodes, robots);
  if (t.rows.empty()) throw std::runtime_error(path + ": no rows for the chosen run");
  return t;
}

// The UDP payload sizes of one message (LCM's datagrams).
inline std::vector<uint32_t> LcmDatagrams(int64_t payload_bytes, std::size_t channel_chars) {
  const int64_t stream = int64_t(channel_chars) + 1 + payload_bytes;
  if (stream <= kLcmShortMax) return {uint32_t(8 + stream)};
  std::vector<uint32_t> out;
  for (int64_t at = 0; at < stream; at += kLcmFragmentData) {
    out.push_back(uint32_t(kLcmFragmentHeader + std::min(kLcmFragmentData, stream - at)));
  }
  return out;
}

struct Destination {
  int node = 0;
  std::size_t row = 0;
  uint32_t got = 0;  // datagrams of the message received there
};

struct Transmission {
  int64_t sent_ns = 0;
  int src = 0;
  bool broadcast = false;
  std::vector<uint32_t> datagrams;
  std::vector<Destination> dsts;
};

// Rows in file (send) order; a group's transmissions are ordered by their first row.
inline std::vector<Transmission> GroupTransmissions(const std::vector<Row>& rows) {
  using Key = std::tuple<int64_t, int, std::string, std::string, int64_t>;
  std::map<Key, std::vector<std::size_t>> open;  // key -> its transmissions (indices)
  std::vector<Transmission> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    std::vector<std::size_t>& mine = open[Key{r.sent_ns, r.src, r.channel, r.type, r.payload_bytes}];
    Transmission* target = nullptr;
    for (const std::size_t k : mine) {
      const auto& d = out[k].dsts;
      if (std::none_of(d.begin(), d.end(), [&](const Destination& x) { return x.node == r.dst; })) {
        target = &out[k];
        break;
      }
    }
    if (target == nullptr) {
      mine.push_back(out.size());
      out.emplace_back();
      target = &out.back();
      target->sent_ns = r.sent_ns;
      target->src = r.src;
      target->datagrams = LcmDatagrams(r.payload_bytes, r.channel.size());
    }
    target->dsts.push_back(Destination{r.dst, i, 0});
  }
  for (Transmission& t : out) t.broadcast = t.dsts.size() > 1;
  return out;
}

// Sends the transmissions from the nodes' sockets and records arrivals. Node i of `nodes` is
// robot i; addresses[i] its IPv4 address; broadcast the subnet's broadcast address.
class Replayer {
 public:
  Replayer(std::vector<Transmission> txs, std::size_t rows, ns3::NodeContainer nodes,
           std::vector<ns3::Ipv4Address> addresses, ns3::Ipv4Address broadcast)
      : txs_(std::move(txs)), delivered_(rows), nodes_(nodes), addresses_(std::move(addresses)),
        broadcast_(broadcast), buffer_(65536, 0) {
    instance_ = this;
  }

  void Install() {
    const ns3::TypeId udp = ns3::UdpSocketFactory::GetTypeId();
    for (uint32_t i = 0; i < nodes_.GetN(); ++i) {
      ns3::Ptr<ns3::Socket> sink = ns3::Socket::CreateSocket(nodes_.Get(i), udp);
      sink->Bind(ns3::InetSocketAddress(ns3::Ipv4Address::GetAny(), kPort));
      sink->SetRecvCallback(ns3::MakeCallback(&Replayer::OnReceive));
      node_of_socket_.emplace(ns3::PeekPointer(sink), int(i));
      sinks_.push_back(sink);
      ns3::Ptr<ns3::Socket> sender = ns3::Socket::CreateSocket(nodes_.Get(i), udp);
      sender->Bind();
      sender->SetAllowBroadcast(true);
      senders_.push_back(sender);
    }
    for (uint32_t k = 0; k < txs_.size(); ++k) {
      ns3::Simulator::Schedule(ns3::NanoSeconds(txs_[k].sent_ns), &Replayer::Send, this, k);
    }
  }

  uint64_t datagrams_sent() const { return datagrams_sent_; }
  uint64_t send_errors() const { return send_errors_; }
  const std::vector<Transmission>& transmissions() const { return txs_; }
  const std::vector<std::optional<int64_t>>& delivered() const { return delivered_; }

 private:
  void Send(uint32_t k) {
    const Transmission& t = txs_[k];
    const ns3::Ipv4Address to = t.broadcast ? broadcast_ : addresses_[std::size_t(t.dsts.front().node)];
    for (uint32_t d = 0; d < t.datagrams.size(); ++d) {
      std::memcpy(buffer_.data(), &k, 4);
      std::memcpy(buffer_.data() + 4, &d, 4);
      ns3::Ptr<ns3::Packet> p = ns3::Create<ns3::Packet>(buffer_.data(), t.datagrams[d]);
      if (senders_[std::size_t(t.src)]->SendTo(p, 0, ns3::InetSocketAddress(to, kPort)) < 0) {
        ++send_errors_;
      } else {
        ++datagrams_sent_;
      }
    }
  }

  static void OnReceive(ns3::Ptr<ns3::Socket> socket) {
    Replayer& self = *instance_;
    const int node = self.node_of_socket_.at(ns3::PeekPointer(socket));
    while (ns3::Ptr<ns3::Packet> p = socket->Recv()) {
      if (p->GetSize() < 8) continue;
      uint8_t head[8];
      p->CopyData(head, 8);
      uint32_t k = 0;
      std::memcpy(&k, head, 4);
      if (k >= self.txs_.size()) continue;
      Transmission& t = self.txs_[k];
      for (Destination& d : t.dsts) {
        if (d.node != node) continue;
        if (++d.got == t.datagrams.size()) {
          self.delivered_[d.row] = ns3::Simulator::Now().GetNanoSeconds();
        }
        break;
      }
    }
  }

  static inline Replayer* instance_ = nullptr;
  std::vector<Transmission> txs_;
  std::vector<std::optional<int64_t>> delivered_;
  ns3::NodeContainer nodes_;
  std::vector<ns3::Ipv4Address> addresses_;
  ns3::Ipv4Address broadcast_;
  std::vector<uint8_t> buffer_;
  std::vector<ns3::Ptr<ns3::Socket>> sinks_, senders_;
  std::map<const ns3::Socket*, int> node_of_socket_;
  uint64_t datagrams_sent_ = 0;
  uint64_t send_errors_ = 0;
};

// Writes sent_ns,src,dst,channel,type,payload_bytes,delivered_ns (empty if lost), one line per row.
inline void WriteOutput(const std::string& path, const std::vector<Row>& rows,
                        const std::vector<std::optional<int64_t>>& delivered) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write");
  out << "sent_ns,src,dst,channel,type,payload_bytes,delivered_ns\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    out << r.sent_ns << ',' << r.src << ',' << r.dst << ',' << r.channel << ',' << r.type << ','
        << r.payload_bytes << ',';
    if (delivered[i]) out << *delivered[i];
    out << '\n';
  }
  if (!out) throw std::runtime_error(path + ": write failed");
}

// Before the internet stack is installed. ns-3 keeps the fragments of an incomplete datagram for
// FragmentExpirationTimeout (30 s) and then sends an ICMP Time Exceeded to its sender when the
// first fragment had arrived: traffic dvpr does not have (a message with a lost fragment is simply
// lost there). The timeout is set beyond the end of the replay (TimedRun stops 10^5 s after the
// last send), so no ICMP message is ever sent.
inline void ConfigureIpv4() {
  ns3::Config::SetDefault("ns3::Ipv4L3Protocol::FragmentExpirationTimeout", ns3::TimeValue(ns3::Seconds(1e6)));
}

// The run filter's options, the same in every replay program.
inline void AddRunFilter(ns3::CommandLine& cmd, RunFilter& filter) {
  cmd.AddValue("protocol", "run filter: protocol (default: the first row's)", filter.protocol);
  cmd.AddValue("strategy", "run filter: strategy (default: the first row's)", filter.strategy);
  cmd.AddValue("robots", "run filter: robots (default: the first row's)", filter.robots);
  cmd.AddValue("run", "run filter: run (default: the first row's)", filter.run);
  cmd.AddValue("variant", "run filter: network_variant (default: the first row's)", filter.variant);
}

// IPv4 on 10.1.0.0/16 over `devices` as dvpr frames it: no IPv6 (its address detection and MLD
// would send frames dvpr does not), no root queue disc (IP hands each packet to the device
// queue), static ARP (no ARP frames). Returns each node's address.
inline std::vector<ns3::Ipv4Address> InstallIpv4(ns3::NodeContainer& nodes, ns3::NetDeviceContainer& devices) {
  ConfigureIpv4();
  ns3::InternetStackHelper internet;
  internet.SetIpv6StackInstall(false);
  internet.Install(nodes);
  ns3::Ipv4AddressHelper ipv4("10.1.0.0", "255.255.0.0");
  ns3::Ipv4InterfaceContainer ifaces = ipv4.Assign(devices);
  ns3::TrafficControlHelper().Uninstall(devices);
  ns3::NeighborCacheHelper().PopulateNeighborCache(ifaces);
  std::vector<ns3::Ipv4Address> addresses;
  for (uint32_t i = 0; i < nodes.GetN(); ++i) addresses.push_back(ifaces.GetAddress(i));
  return addresses;
}

struct RunTimes {
  double wall_s = 0;
  double cpu_s = 0;
};

// Simulator::Run, timed by the wall clock and the process CPU clock. The run stops 10^5 s after
// the last send: long after anything left of the replay has arrived.
inline RunTimes TimedRun(const std::vector<Row>& rows) {
  int64_t last = 0;
  for (const Row& r : rows) last = std::max(last, r.sent_ns);
  ns3::Simulator::Stop(ns3::NanoSeconds(last) + ns3::Seconds(1e5) - ns3::Simulator::Now());
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  ns3::Simulator::Run();
  const std::clock_t cpu1 = std::clock();
  const auto wall1 = std::chrono::steady_clock::now();
  return RunTimes{std::chrono::duration<double>(wall1 - wall0).count(), double(cpu1 - cpu0) / CLOCKS_PER_SEC};
}

// IPv4 over `devices` (InstallIpv4) and the trace's sockets and sends: the replay, ready to run.
inline std::unique_ptr<Replayer> Prepare(const Trace& trace, ns3::NodeContainer& nodes,
                                         ns3::NetDeviceContainer& devices) {
  auto replayer = std::make_unique<Replayer>(GroupTransmissions(trace.rows), trace.rows.size(), nodes,
                                             InstallIpv4(nodes, devices), ns3::Ipv4Address("10.1.255.255"));
  replayer->Install();
  return replayer;
}

// Runs the replay and writes `out`; false, with one line naming `program` on stderr, when the
// file cannot be written.
inline bool RunAndWrite(const char* program, const Trace& trace, const Replayer& replayer, const std::string& out,
                        RunTimes& times) {
  times = TimedRun(trace.rows);
  try {
    WriteOutput(out, trace.rows, replayer.delivered());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", program, e.what());
    return false;
  }
  return true;
}

inline void PrintSummary(const Trace& trace, const Replayer& r, const RunTimes& times) {
  const auto& rows = trace.rows;
  const auto& delivered = r.delivered();
  std::vector<int64_t> lat;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (delivered[i]) lat.push_back(*delivered[i] - rows[i].sent_ns);
  }
  std::sort(lat.begin(), lat.end());
  double mean_ms = NAN, p99_ms = NAN;
  if (!lat.empty()) {
    long double sum = 0;
    for (const int64_t l : lat) sum += l;
    mean_ms = double(sum / lat.size()) / 1e6;
    const std::size_t rank = std::size_t(std::ceil(0.99 * double(lat.size())));  // nearest rank
    p99_ms = double(lat[std::max<std::size_t>(rank, 1) - 1]) / 1e6;
  }
  int64_t last_arrival = 0;
  for (const auto& d : delivered) last_arrival = std::max(last_arrival, d.value_or(0));
  std::size_t broadcasts = 0;
  for (const Transmission& t : r.transmissions()) broadcasts += t.broadcast ? 1 : 0;
  std::printf("run: protocol=%s strategy=%s robots=%s run=%s network_variant=%s; %d nodes\n",
              trace.run.protocol.c_str(), trace.run.strategy.c_str(), trace.run.robots.c_str(),
              trace.run.run.c_str(), trace.run.variant.c_str(), trace.nodes);
  std::printf("transmissions %zu (broadcast %zu, unicast %zu), UDP datagrams sent %llu, send errors %llu\n",
              r.transmissions().size(), broadcasts, r.transmissions().size() - broadcasts,
              static_cast<unsigned long long>(r.datagrams_sent()),
              static_cast<unsigned long long>(r.send_errors()));
  std::printf("messages (rows) %zu, delivered %zu, dropped %zu, mean latency %.6f ms, p99 latency %.6f ms\n",
              rows.size(), lat.size(), rows.size() - lat.size(), mean_ms, p99_ms);
  std::printf("Simulator::Run %.3f s wall, %.3f s CPU; last arrival at %.6f s\n", times.wall_s, times.cpu_s,
              double(last_arrival) / 1e9);
}

}  // namespace replay
