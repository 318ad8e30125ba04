// Replays one run of a dvpr messages.csv open loop through dvpr's own network: each message sent
// at its sent_ns whatever arrived before, as bench/peers/csma_replay_ns3.cc and
// wifi_replay_ns3.cc replay it through ns-3. The replays of the two simulators are then the same
// experiment (the trace's send times are those of dvpr's closed-loop run, whose own medium they
// followed), and either can be compared with the closed-loop run to see what the open loop
// changes (bench/peers/README.md, section 4).
//
//   build/release/bench/replay_trace --messages=F --strategy=S --model=csma|wifi --rate=10Mbps
//       [--delay=5ms] [--wifi-rate=54Mbps] [--queue=100] [--seed=1] --out=O
//
// Output as the ns-3 replays': sent_ns,src,dst,channel,type,payload_bytes,delivered_ns (empty when
// lost), one line per replayed row in the file's order. Rows sharing (sent_ns, src, channel,
// type, payload_bytes) are one message to several robots.
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "net_models/core/units.h"
#include "net_models/helper/link_factory.h"
#include "net_models/helper/network_helper.h"
#include "net_models/network/network.h"
#include "net_models/network/network_observer.h"
#include "net_models/network/network_stack.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

struct Row {
  std::int64_t sent_ns = 0;
  int src = 0;
  int dst = 0;
  std::string channel, type;
  std::int64_t payload_bytes = 0;
};

std::vector<std::string> Split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string field;
  while (std::getline(s, field, ',')) out.push_back(field);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

std::vector<Row> ReadRows(const std::string& path, const std::string& strategy) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = Split(line);
  std::map<std::string, std::size_t> at;
  for (std::size_t i = 0; i < header.size(); ++i) at[header[i]] = i;
  for (const char* c : {"strategy", "sent_ns", "src", "dst", "channel", "type", "payload_bytes"}) {
    if (!at.count(c)) throw std::runtime_error(path + ": no column " + c);
  }
  std::vector<Row> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    const std::vector<std::string> f = Split(line);
    if (f.size() < header.size()) throw std::runtime_error(path + ":" + std::to_string(number) + ": short row");
    if (f[at["strategy"]] != strategy) continue;
    rows.push_back(Row{std::stoll(f[at["sent_ns"]]), std::stoi(f[at["src"]]), std::stoi(f[at["dst"]]),
                       f[at["channel"]], f[at["type"]], std::stoll(f[at["payload_bytes"]])});
  }
  if (rows.empty()) throw std::runtime_error(path + ": no row of strategy " + strategy);
  return rows;
}

// Records when each (message, destination) arrived.
class Arrivals : public NetworkObserver {
 public:
  void OnDelivered(const MessageCopy& c, SimTime at) override { arrived[{c.message, c.dst.value}] = at.ns(); }
  std::map<std::pair<std::uint64_t, int>, std::int64_t> arrived;
};

int Main(int argc, char** argv) {
  std::map<std::string, std::string> opt{{"model", "csma"}, {"rate", "10Mbps"}, {"delay", "2ms"},
                                         {"wifi-rate", "54Mbps"}, {"queue", "100"}, {"seed", "1"}};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto eq = a.find('=');
    if (a.rfind("--", 0) != 0 || eq == std::string::npos) throw std::invalid_argument("expected --key=value, got " + a);
    opt[a.substr(2, eq - 2)] = a.substr(eq + 1);
  }
  for (const char* k : {"messages", "strategy", "out"}) {
    if (!opt.count(k)) throw std::invalid_argument(std::string("--") + k + "= is required");
  }
  const std::vector<Row> rows = ReadRows(opt["messages"], opt["strategy"]);
  int nodes = 0;
  for (const Row& r : rows) nodes = std::max({nodes, r.src + 1, r.dst + 1});

  NetworkModelParams p;
  p.model = ParseLinkModelKind(opt["model"]);
  p.bandwidth = ParseDataRate(opt["rate"]);
  p.latency = ParseDuration(opt["delay"]);
  p.queue_packets = std::stoi(opt["queue"]);
  if (p.model == LinkModelKind::kWifi) p.wifi.rate = ParseDataRate(opt["wifi-rate"]);
  p.Validate(nodes);
  Simulator sim;
  Network net(sim, nodes, MakeNetworkStack(p, nodes, std::stoull(opt["seed"])), WireOf(p));
  Arrivals arrivals;
  const ObserverSubscription subscription = net.Subscribe(arrivals);

  // One message per (sent_ns, src, channel, type, payload_bytes); its rows' destinations.
  using Key = std::tuple<std::int64_t, int, std::string, std::string, std::int64_t>;
  std::map<Key, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    groups[Key{r.sent_ns, r.src, r.channel, r.type, r.payload_bytes}].push_back(i);
  }
  std::vector<std::uint64_t> message_of(rows.size());
  std::uint64_t next_message = 0;  // SendTo calls are numbered in the order they run: by time
  for (const auto& [key, members] : groups) {
    const Row& r = rows[members.front()];
    std::vector<NodeId> dsts;
    for (const std::size_t m : members) dsts.push_back(NodeId(rows[m].dst));
    const ChannelId channel = net.InternChannel(r.channel);
    const MessageTypeId type = net.InternType(r.type);
    for (const std::size_t m : members) message_of[m] = next_message;
    ++next_message;
    sim.ScheduleAt(SimTime::Nanos(r.sent_ns), [&net, src = r.src, dsts, channel, type, bytes = r.payload_bytes] {
      net.SendTo(NodeId(src), dsts, channel, type, std::vector<std::uint8_t>(static_cast<std::size_t>(bytes), 0));
    });
  }
  sim.Run();

  std::ofstream out(opt["out"]);
  out << "sent_ns,src,dst,channel,type,payload_bytes,delivered_ns\n";
  std::size_t delivered = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    out << r.sent_ns << ',' << r.src << ',' << r.dst << ',' << r.channel << ',' << r.type << ',' << r.payload_bytes << ',';
    if (const auto it = arrivals.arrived.find({message_of[i], r.dst}); it != arrivals.arrived.end()) {
      out << it->second;
      ++delivered;
    }
    out << '\n';
  }
  if (!out) throw std::runtime_error(opt["out"] + ": write failed");
  std::printf("replayed %zu rows (%zu messages) through dvpr %s: %zu delivered\n", rows.size(), groups.size(),
              opt["model"].c_str(), delivered);
  return 0;
}

}  // namespace
}  // namespace dvpr

int main(int argc, char** argv) {
  try {
    return dvpr::Main(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "replay_trace: %s\n", e.what());
    return 1;
  }
}
