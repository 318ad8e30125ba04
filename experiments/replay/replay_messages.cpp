#include "experiments/replay/replay_messages.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>
#include <tuple>

#include "experiments/results/protocol_traits.h"
#include "experiments/results/result_writers.h"
#include "experiments/results/results.h"

namespace dvpr::replay {

namespace {

// The columns the replay reads; others are skipped. Those from kHops on may be missing: hops is
// written only by a sweep with a radio.
enum Column { kProtocol, kStrategy, kRobots, kRun, kSent, kDelivered, kSrc, kDst, kChannel, kWireBytes,
              kDropped, kVariant, kModel, kBandwidth, kLatency, kLoss, kRequiredColumns,
              kHops = kRequiredColumns, kColumns };
constexpr std::array<const char*, kColumns> kNames = {
    "protocol", "strategy", "robots",  "run",           "sent_ns",       "delivered_ns",
    "src",      "dst",      "channel", "wire_bytes",    "dropped",       "network_variant",
    "network_model", "bandwidth_bps", "latency_ms", "loss", "hops"};
constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);
// Network::kMaxHops: a relay drops a copy that has made this many transmissions (hop_limit).
constexpr int kMaxHops = 64;

std::vector<std::string_view> Split(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

std::string Join(const std::set<int>& values) {
  std::string s;
  for (int v : values) s += (s.empty() ? "" : ", ") + std::to_string(v);
  return s.empty() ? "none" : s;
}

// One data line of messages.csv: its fields by Column, with errors naming file, line and column.
class Row {
 public:
  Row(const std::filesystem::path& file, long line, const std::array<std::size_t, kColumns>& index,
      std::string_view text)
      : file_(file), line_(line), fields_(Split(text)), index_(index) {}
  std::string_view Text(Column c) const {
    if (index_[c] >= fields_.size()) Fail(c, "a value", "a short row");
    return fields_[index_[c]];
  }
  template <typename T>
  T Number(Column c) const {
    const std::string_view t = Text(c);
    T v{};
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size() || t.empty()) Fail(c, "a number", "'" + std::string(t) + "'");
    return v;
  }
  bool Empty(Column c) const { return Text(c).empty(); }
  // A number, or NaN (kNotApplicable) when empty: wifi has no latency, ideal neither bandwidth.
  double NumberOrNotApplicable(Column c) const { return Empty(c) ? kNotApplicable : Number<double>(c); }
  bool Has(Column c) const { return index_[c] != kAbsent; }
  std::size_t size() const { return fields_.size(); }
  // A copy's hops: at least 0 (1 when it was delivered) and at most `max`, which `why` explains.
  int Hops(Column c, bool delivered, int max, const std::string& why) const {
    const int n = Number<int>(c);
    if (n < 0) Fail(c, "a count of at least 0", std::to_string(n));
    if (delivered && n == 0) Fail(c, "at least 1 for a delivered copy", "0");
    if (n > max) Fail(c, "at most " + std::to_string(max) + " " + why, std::to_string(n));
    return n;
  }
  // A robot of a team of `robots`: the page draws it at that index.
  int Robot(Column c, int robots) const {
    const int id = Number<int>(c);
    if (id < 0 || id >= robots) {
      Fail(c, "a robot of the team of " + std::to_string(robots) + " (0 to " + std::to_string(robots - 1) + ")",
           std::to_string(id));
    }
    return id;
  }

  [[noreturn]] void Fail(Column c, const std::string& expected, const std::string& got) const {
    throw std::runtime_error(file_.string() + ": line " + std::to_string(line_) + ": " + kNames[c] +
                             ": expected " + expected + ", got " + got);
  }
 private:
  const std::filesystem::path& file_;
  long line_;
  std::vector<std::string_view> fields_;
  const std::array<std::size_t, kColumns>& index_;
};

std::array<std::size_t, kColumns> HeaderIndex(std::string_view header, const std::filesystem::path& file) {
  const std::vector<std::string_view> names = Split(header);
  std::array<std::size_t, kColumns> index{};
  for (int c = 0; c < kColumns; ++c) {
    const auto it = std::find(names.begin(), names.end(), kNames[static_cast<std::size_t>(c)]);
    if (it == names.end() && c >= kRequiredColumns) {
      index[static_cast<std::size_t>(c)] = kAbsent;
      continue;
    }
    if (it == names.end()) {
      throw std::runtime_error(file.string() + ": no column '" + kNames[static_cast<std::size_t>(c)] +
                               "' in its header (is this a dvpr messages.csv?)");
    }
    index[static_cast<std::size_t>(c)] = static_cast<std::size_t>(it - names.begin());
  }
  return index;
}

// What the run's network can do to a copy: how many transmissions a copy can have made (and why,
// for the error), and whether one transmission reaches every robot (a broadcast's bytes count once).
struct NetworkTraits {
  int max_hops = 1;
  std::string why;
  bool one_transmission = false;
};

// Only a radio with shortest_path or link_state as its next hop relays. Relays may hand a copy
// back while the graph changes, so a copy can make more than robots - 1 transmissions, never more
// than kMaxHops; in a team of 2 there is no robot but the destination to relay.
NetworkTraits TraitsOf(const ReplayRun& run) {
  NetworkTraits t;
  const std::string& model = run.network.model;
  const bool radio = model == "radio";
  const bool relays = radio && !run.network.next_hop.empty();
  if (!relays) {
    t.why = "(one transmission: network " + model + " has no relays)";
  } else if (run.robots <= 2) {
    t.why = "(one transmission: a team of " + std::to_string(run.robots) + " has no robot to relay)";
  } else {
    t.max_hops = kMaxHops;
    t.why = "(a relay drops a copy after " + std::to_string(kMaxHops) + " transmissions, hop_limit)";
  }
  // A sender's transmission reaches every receiver on the shared media and on a radio that does
  // not relay; with relays each relay adds transmissions that messages.csv does not list.
  t.one_transmission = model == "shared_medium" || model == "csma" || model == "wifi" || (radio && !relays);
  return t;
}

Message MessageOf(const Row& row, int robots, const NetworkTraits& network) {
  Message m;
  m.sent_ns = row.Number<std::int64_t>(kSent);
  if (!row.Empty(kDelivered)) m.delivered_ns = row.Number<std::int64_t>(kDelivered);
  m.src = row.Robot(kSrc, robots);
  m.dst = row.Robot(kDst, robots);
  const std::string_view channel = row.Text(kChannel);
  m.role = channels::RoleOf(channel);
  m.queue = QueueEffectOfChannel(channel);
  m.counted_bytes = row.Number<std::int64_t>(kWireBytes);
  m.dropped = row.Number<int>(kDropped) != 0;
  if (row.Has(kHops)) m.hops = row.Hops(kHops, m.delivered_ns >= 0, network.max_hops, network.why);
  return m;
}

// The label of the selected run's variant, `variant` of `networks`, which must be the network
// that messages.csv's row names (else the config.yaml is not this folder's).
NetworkLabel LabelOf(const Row& row, int variant, std::span<const NetworkLabel> networks) {
  if (variant < 0 || static_cast<std::size_t>(variant) >= networks.size()) {
    row.Fail(kVariant, "a network variant of the folder's config.yaml (it has " + std::to_string(networks.size()) + ")",
             std::to_string(variant));
  }
  const NetworkLabel& label = networks[static_cast<std::size_t>(variant)];
  NetworkLabel named;
  named.model = row.Text(kModel);
  named.bandwidth_bps = row.NumberOrNotApplicable(kBandwidth);
  named.latency_ms = row.NumberOrNotApplicable(kLatency);
  named.loss = row.Text(kLoss);
  if (!SameNetworkColumns(named, label)) {
    row.Fail(kModel, "network variant " + std::to_string(variant) + " of the folder's config.yaml ('" +
                         NetworkName(label) + "')", "'" + NetworkName(named) + "'");
  }
  return label;
}

using RunId = std::tuple<int, int, int>;  // robots, run, network variant

// What one pass over the file collects: the selected run's rows per strategy, and what else the
// file holds, for the error messages.
struct Scan {
  std::optional<RunId> chosen;
  ReplayRun run;
  NetworkTraits network;
  std::vector<std::string> order;                      // strategies, first appearance
  std::map<std::string, std::vector<Message>> by_strategy;
  std::map<std::string, std::string> last_channel;     // shared medium: the previous copy's channel
  std::set<int> robots, runs, variants;
  long sim_rows = 0;
};

bool Selected(const Selection& s, const RunId& id) {
  return (!s.robots || *s.robots == std::get<0>(id)) && (!s.run || *s.run == std::get<1>(id)) &&
         (!s.network || *s.network == std::get<2>(id));
}

void Take(Scan& scan, const Row& row, const RunId& id, std::span<const NetworkLabel> networks) {
  if (!scan.chosen) {
    scan.chosen = id;
    std::tie(scan.run.robots, scan.run.run, scan.run.network_variant) = id;
    scan.run.network = LabelOf(row, scan.run.network_variant, networks);
    scan.network = TraitsOf(scan.run);
  }
  if (id != *scan.chosen) return;
  const std::string strategy(row.Text(kStrategy));
  auto [it, added] = scan.by_strategy.try_emplace(strategy);
  if (added) scan.order.push_back(strategy);
  Message m = MessageOf(row, std::get<0>(id), scan.network);
  // A broadcast on a medium that one transmission crosses (runs.csv's wire_bytes counts it once,
  // docs/design.md section 4): its copies follow each other in the file.
  std::string& last = scan.last_channel[strategy];
  const std::string channel(row.Text(kChannel));
  if (scan.network.one_transmission && !it->second.empty() && last == channel &&
      it->second.back().src == m.src && it->second.back().sent_ns == m.sent_ns) {
    m.counted_bytes = 0;
  }
  last = channel;
  it->second.push_back(m);
}

Scan ScanFile(const std::filesystem::path& file, const Selection& selection, std::span<const NetworkLabel> networks) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open it");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(file.string() + ": empty file (no header)");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const std::array<std::size_t, kColumns> index = HeaderIndex(line, file);
  const std::size_t columns = Split(line).size();
  Scan scan;
  for (long number = 2; std::getline(in, line); ++number) {
    // dvpr ends every line; one without its end is where a copy or a write was cut off.
    if (in.eof()) {
      throw std::runtime_error(file.string() + ": line " + std::to_string(number) +
                               ": the file ends inside it (no line end: a cut file?)");
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const Row row(file, number, index, line);
    // A row cut short (a file copied while written, or edited) is refused, not read in part.
    if (row.size() != columns) {
      throw std::runtime_error(file.string() + ": line " + std::to_string(number) + ": expected " +
                               std::to_string(columns) + " fields as in the header, got " +
                               std::to_string(row.size()) + " (a cut or edited file?)");
    }
    if (!RowTraits(row.Text(kProtocol)).simulated_network) continue;
    ++scan.sim_rows;
    const RunId id{row.Number<int>(kRobots), row.Number<int>(kRun), row.Number<int>(kVariant)};
    scan.robots.insert(std::get<0>(id));
    scan.runs.insert(std::get<1>(id));
    scan.variants.insert(std::get<2>(id));
    if (Selected(selection, id)) Take(scan, row, id, networks);
  }
  return scan;
}

std::string Describe(const Selection& s) {
  std::string d;
  if (s.robots) d += " robots=" + std::to_string(*s.robots);
  if (s.run) d += " run=" + std::to_string(*s.run);
  if (s.network) d += " network=" + std::to_string(*s.network);
  return d;
}

std::vector<std::string> ChosenStrategies(const Scan& scan, const Selection& s, const std::filesystem::path& file) {
  if (s.strategies.empty()) {
    const auto has = [&](const char* name) { return scan.by_strategy.contains(name); };
    if (has("decentralized") && has("broadcast")) return {"decentralized", "broadcast"};
    return scan.order;
  }
  for (const std::string& name : s.strategies) {
    if (scan.by_strategy.contains(name)) continue;
    std::string have;
    for (const auto& o : scan.order) have += (have.empty() ? "" : ", ") + o;
    throw std::runtime_error(file.string() + ": no messages of strategy '" + name + "' in robots=" +
                             std::to_string(scan.run.robots) + " run=" + std::to_string(scan.run.run) +
                             " (it has: " + have + ")");
  }
  return s.strategies;
}

}  // namespace

ReplayRun ReadReplayRun(const std::filesystem::path& file, const Selection& selection,
                        std::span<const NetworkLabel> networks) {
  Scan scan = ScanFile(file, selection, networks);
  if (scan.sim_rows == 0) {
    throw std::runtime_error(file.string() + ": no messages of protocol sim (a replay needs a simulated run "
                             "with outputs.messages: true)");
  }
  if (!scan.chosen) {
    throw std::runtime_error(file.string() + ": no messages of" + Describe(selection) + " (it has robots " +
                             Join(scan.robots) + "; runs " + Join(scan.runs) + "; network variants " +
                             Join(scan.variants) + ")");
  }
  const std::vector<std::string> strategies = ChosenStrategies(scan, selection, file);
  ReplayRun run = std::move(scan.run);
  for (const std::string& name : strategies) {
    run.strategies.push_back(StrategyMessages{name, std::move(scan.by_strategy[name])});
  }
  return run;
}

}  // namespace dvpr::replay
