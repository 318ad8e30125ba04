// summary.json (means per group) and reading runs.csv back for `dvpr plot`.
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/results/protocol_traits.h"
#include "experiments/results/result_writers.h"
#include "experiments/results/spread.h"

namespace dvpr {

namespace {

// One metric of a group: its runs' values (a run without it adds none), whose mean and spread
// summary.json gives (spread.h sums them in this order, as the mean always was).
struct Mean {
  std::vector<double> values;
  void Add(double v) {
    if (!std::isnan(v)) values.push_back(v);
  }
};

std::string JsonNumber(double v) { return std::isnan(v) ? "null" : FormatDouble(v); }

struct Group {
  RunKey key;
  int runs = 0;
  std::map<std::string, Mean> means;  // keyed by column; printed in kMetricOrder
};

// From connectivity.csv's rows (SummarizeConnectivity), for the groups that have them.
const char* const kConnectivityMetrics[] = {"connected_time_share", "connected_pair_mean_hops"};

const char* const kMetricOrder[] = {
    "auc", "auc_reference", "relative_auc", "worst_balance_ratio", "queries", "messages",
    "payload_bytes", "wire_bytes", "bytes_per_query", "mean_latency_ms", "p99_latency_ms",
    "dropped_messages"};

// The by-role metrics, in runs.csv's order; the runs without a network's counts are skipped.
const char* const kRoleSuffixes[] = {"payload_bytes", "wire_bytes", "copy_wire_bytes",
                                     "delivered_payload_bytes", "delivered_wire_bytes"};

std::vector<std::string> RoleMetricNames() {
  std::vector<std::string> names = {"duration_s", "copy_wire_bytes", "delivered_payload_bytes", "delivered_wire_bytes",
                                    "place_recognition_bytes_per_query"};
  for (const char* role : kMessageRoleNames) {
    for (const char* suffix : kRoleSuffixes) names.push_back(std::string(role) + "_" + suffix);
  }
  return names;
}

// runs.csv's closure columns (RunClosures), for the runs of a team.
const char* const kClosureMetrics[] = {"inter_queries",   "intra_queries",   "inter_recall",     "intra_recall",
                                       "inter_auc",       "intra_auc",       "inter_candidates", "inter_closures",
                                       "closure_precision", "pairs_closed", "median_first_closure_s"};

std::vector<double> ClosureMetricValues(const RunResult& r) {
  if (!r.closures) return std::vector<double>(std::size(kClosureMetrics), kNotApplicable);
  const RunClosures& c = *r.closures;
  return {double(c.inter_queries), double(c.intra_queries), c.inter_recall(),       c.intra_recall(),
          c.inter_auc,              c.intra_auc,              double(c.inter_candidates), double(c.inter_closures),
          c.closure_precision(),    double(c.pairs_closed),   c.median_first_closure_s()};
}

std::vector<double> RoleMetricValues(const RunResult& r) {
  const std::size_t count = 5 + std::size(kRoleSuffixes) * kMessageRoles;
  if (!r.roles) return std::vector<double>(count, kNotApplicable);
  CopyBytes total;
  for (const CopyBytes& c : r.roles->copies) total += c;
  std::vector<double> v = {r.duration_s, double(total.wire), double(total.delivered_payload), double(total.delivered_wire),
                           PlaceRecognitionBytesPerQuery(r)};
  for (int i = 0; i < kMessageRoles; ++i) {
    const CopyBytes& c = r.roles->copies[static_cast<std::size_t>(i)];
    for (double x : {double(c.payload), double(r.roles->medium[static_cast<std::size_t>(i)]), double(c.wire),
                     double(c.delivered_payload), double(c.delivered_wire)}) {
      v.push_back(x);
    }
  }
  return v;
}

void AddRun(Group& g, const RunResult& r) {
  ++g.runs;
  const double values[] = {r.auc, r.auc_reference, r.relative_auc, r.worst_balance_ratio,
                           double(r.queries), double(r.messages), double(r.payload_bytes),
                           double(r.wire_bytes), r.bytes_per_query, r.mean_latency_ms,
                           r.p99_latency_ms, double(r.dropped_messages)};
  for (std::size_t i = 0; i < std::size(kMetricOrder); ++i) g.means[kMetricOrder[i]].Add(values[i]);
  const std::vector<std::string> names = RoleMetricNames();
  const std::vector<double> role_values = RoleMetricValues(r);
  for (std::size_t i = 0; i < names.size(); ++i) g.means[names[i]].Add(role_values[i]);
  const std::vector<double> closure_values = ClosureMetricValues(r);
  for (std::size_t i = 0; i < std::size(kClosureMetrics); ++i) g.means[kClosureMetrics[i]].Add(closure_values[i]);
}

std::string JsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

double PlaceRecognitionBytesPerQuery(const RunResult& r) {
  if (!r.roles || r.queries <= 0) return kNotApplicable;
  const auto& c = r.roles->copies;
  const std::int64_t bytes = c[static_cast<std::size_t>(MessageRole::kQuery)].wire +
                             c[static_cast<std::size_t>(MessageRole::kReply)].wire;
  return static_cast<double>(bytes) / static_cast<double>(r.queries);
}

namespace {

std::string GroupId(const RunKey& k, const std::string& strategy) {
  return k.protocol + "|" + strategy + "|" + std::to_string(k.robots) + "|" + k.network.model + "|" +
         std::to_string(k.network.variant);
}

void WriteGroup(std::ostringstream& s, const Group& g) {
  const NetworkLabel& n = g.key.network;
  s << "\n    {\"protocol\": " << JsonString(g.key.protocol) << ", \"strategy\": " << JsonString(g.key.strategy)
    << ", \"robots\": " << g.key.robots;
  if (!n.model.empty()) {
    s << ", \"network_variant\": " << n.variant << ", \"network_model\": " << JsonString(n.model)
      << ", \"bandwidth_bps\": " << (std::isnan(n.bandwidth_bps) ? "null" : FormatDouble(n.bandwidth_bps))
      << ", \"latency_ms\": " << (std::isnan(n.latency_ms) ? "null" : FormatDouble(n.latency_ms))
      << ", \"loss\": " << JsonString(n.loss) << ", \"network_name\": " << JsonString(NetworkName(n));
  }
  s << ", \"runs\": " << g.runs;
  // The metrics written, in order: those of kMetricOrder, the bytes by role only where a network
  // counted them, the closures only where a team ran, the connectivity ones only where it was tracked; each one's spread worked out once.
  std::vector<std::pair<std::string, Spread>> metrics;
  for (const char* m : kMetricOrder) metrics.emplace_back(m, SpreadOf(g.means.at(m).values));
  if (!g.means.at("copy_wire_bytes").values.empty()) {
    for (const std::string& m : RoleMetricNames()) metrics.emplace_back(m, SpreadOf(g.means.at(m).values));
  }
  if (!g.means.at("inter_queries").values.empty()) {
    for (const char* m : kClosureMetrics) metrics.emplace_back(m, SpreadOf(g.means.at(m).values));
  }
  for (const char* m : kConnectivityMetrics) {
    if (const auto it = g.means.find(m); it != g.means.end()) metrics.emplace_back(m, SpreadOf(it->second.values));
  }
  // The means, then beside them (issue 35) the runs' standard deviation and the 95 % confidence
  // interval's half-width, with the same keys; null below two runs (no value: null everywhere).
  for (const auto& [object, field] : {std::pair{"mean", &Spread::mean}, std::pair{"std", &Spread::std},
                                      std::pair{"ci95", &Spread::ci95}}) {
    s << ",\n     " << JsonString(object) << ": {";
    for (std::size_t i = 0; i < metrics.size(); ++i) {
      s << (i ? ", " : "") << JsonString(metrics[i].first) << ": " << JsonNumber(metrics[i].second.*field);
    }
    s << "}";
  }
  s << "}";
}

// Broadcast over decentralized place-recognition bytes per query (query and reply copies), per
// (protocol, n, network variant) that has both: the paper's n - 1 law, measured.
void WriteRatios(std::ostringstream& s, const std::vector<Group>& groups, const std::map<std::string, std::size_t>& index) {
  s << ",\n  \"place_recognition_ratio\": [";
  bool first = true;
  for (const Group& d : groups) {
    if (d.key.strategy != "decentralized") continue;
    const auto b = index.find(GroupId(d.key, "broadcast"));
    if (b == index.end()) continue;
    const double dec = SpreadOf(d.means.at("place_recognition_bytes_per_query").values).mean;
    const double bro = SpreadOf(groups[b->second].means.at("place_recognition_bytes_per_query").values).mean;
    if (std::isnan(dec) || std::isnan(bro) || dec == 0) continue;
    s << (first ? "" : ",") << "\n    {\"protocol\": " << JsonString(d.key.protocol) << ", \"robots\": "
      << d.key.robots << ", \"network_variant\": " << d.key.network.variant << ", \"network_name\": "
      << JsonString(NetworkName(d.key.network)) << ", \"broadcast_bytes_per_query\": " << FormatDouble(bro)
      << ", \"decentralized_bytes_per_query\": " << FormatDouble(dec) << ", \"ratio\": " << FormatDouble(bro / dec)
      << ", \"n_minus_1\": " << d.key.robots - 1 << "}";
    first = false;
  }
  s << "\n  ]";
}

}  // namespace

std::string SummaryJson(const std::vector<RunResult>& rows, const std::vector<RunConnectivity>& connectivity) {
  std::vector<Group> groups;
  std::map<std::string, std::size_t> index;
  for (const auto& r : rows) {
    auto [it, added] = index.emplace(GroupId(r.key, r.key.strategy), groups.size());
    if (added) groups.push_back(Group{r.key, 0, {}});
    AddRun(groups[it->second], r);
  }
  for (const RunConnectivity& c : connectivity) {
    const auto it = index.find(GroupId(c.key, c.key.strategy));
    if (it == index.end()) continue;  // a run without its runs.csv row: nothing to stand beside
    Group& g = groups[it->second];
    g.means[kConnectivityMetrics[0]].Add(c.connected_time_share);
    g.means[kConnectivityMetrics[1]].Add(c.connected_pair_mean_hops);
  }
  std::ostringstream s;
  s << "{\n  \"groups\": [";
  for (std::size_t i = 0; i < groups.size(); ++i) {
    s << (i ? "," : "");
    WriteGroup(s, groups[i]);
  }
  s << "\n  ]";
  WriteRatios(s, groups, index);
  s << "\n}\n";
  return s.str();
}

namespace {

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

// The name of runs.csv column i, for errors.
const std::string& ColumnName(std::size_t i) {
  static const std::vector<std::string> names = SplitCsv(kRunsHeader);
  return names.at(i);
}

// Field i of a runs.csv row as a number; empty is "not applicable" (NaN) for a floating column.
template <typename T>
T Parse(const std::vector<std::string>& f, std::size_t i, const std::string& where) {
  const std::string& s = f[i];
  if (s.empty()) {
    if constexpr (std::is_floating_point_v<T>) return kNotApplicable;
  }
  T v{};
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) {
    throw std::runtime_error(where + ": " + ColumnName(i) + ": expected " +
                             (std::is_floating_point_v<T> ? "a number" : "an integer") + ", got '" + s + "'");
  }
  return v;
}

// runs.csv fields 24..: copy_wire_bytes and the delivered totals (sums of the roles', not
// kept), then five per role: payload, medium (wire), copy wire, delivered payload, delivered wire.
RunRoleBytes ParseRunRoles(const std::vector<std::string>& f, const std::string& where) {
  RunRoleBytes roles;
  for (std::size_t i = 0; i < static_cast<std::size_t>(kMessageRoles); ++i) {
    const std::size_t at = 27 + 5 * i;
    CopyBytes& c = roles.copies[i];
    c.payload = Parse<std::int64_t>(f, at, where);
    roles.medium[i] = Parse<std::int64_t>(f, at + 1, where);
    c.wire = Parse<std::int64_t>(f, at + 2, where);
    c.delivered_payload = Parse<std::int64_t>(f, at + 3, where);
    c.delivered_wire = Parse<std::int64_t>(f, at + 4, where);
  }
  return roles;
}

// runs.csv's closure columns, after the roles' (RunClosures). The recalls and the median are
// written in seconds and shares: the counts and nanoseconds they came from are the nearest.
constexpr std::size_t kClosureFields = 27 + 5 * kMessageRoles;

RunClosures ParseRunClosures(const std::vector<std::string>& f, const std::string& where) {
  const std::size_t at = kClosureFields;
  RunClosures c;
  c.inter_queries = Parse<std::int64_t>(f, at, where);
  c.intra_queries = Parse<std::int64_t>(f, at + 1, where);
  const auto count = [&](std::size_t i, std::int64_t of) {
    const double share = Parse<double>(f, i, where);
    return std::isnan(share) ? 0 : static_cast<std::int64_t>(std::llround(share * static_cast<double>(of)));
  };
  c.inter_recognised = count(at + 2, c.inter_queries);
  c.intra_recognised = count(at + 3, c.intra_queries);
  c.inter_auc = Parse<double>(f, at + 4, where);
  c.intra_auc = Parse<double>(f, at + 5, where);
  c.inter_candidates = Parse<std::int64_t>(f, at + 6, where);
  c.inter_closures = Parse<std::int64_t>(f, at + 7, where);
  c.pairs_closed = Parse<std::int64_t>(f, at + 9, where);
  const double median_s = Parse<double>(f, at + 10, where);
  if (!std::isnan(median_s)) c.median_first_closure_ns = std::llround(median_s * 1e9);
  return c;
}

RunResult ParseRunRow(const std::vector<std::string>& f, const std::string& where) {
  RunResult r;
  r.key.protocol = f[0];
  r.key.strategy = f[1];
  r.key.robots = Parse<int>(f, 2, where);
  r.key.run = Parse<int>(f, 3, where);
  r.seed = Parse<std::uint64_t>(f, 4, where);
  double* doubles[] = {&r.auc, &r.auc_reference, &r.relative_auc, &r.worst_balance_ratio};
  for (std::size_t i = 0; i < 4; ++i) *doubles[i] = Parse<double>(f, 5 + i, where);
  r.queries = Parse<std::int64_t>(f, 9, where);
  r.messages = Parse<std::int64_t>(f, 10, where);
  r.payload_bytes = Parse<std::int64_t>(f, 11, where);
  r.wire_bytes = Parse<std::int64_t>(f, 12, where);
  r.bytes_per_query = Parse<double>(f, 13, where);
  r.mean_latency_ms = Parse<double>(f, 14, where);
  r.p99_latency_ms = Parse<double>(f, 15, where);
  r.dropped_messages = Parse<std::int64_t>(f, 16, where);
  if (!f[18].empty()) {
    r.key.network.variant = Parse<int>(f, 17, where);
    r.key.network.model = f[18];
    r.key.network.bandwidth_bps = Parse<double>(f, 19, where);
    r.key.network.latency_ms = Parse<double>(f, 20, where);
    r.key.network.loss = f[21];
    // The propagation, next hop, swept queue and MTU have no column of their own:
    // LabelNetworks gives them from the config's variants.
  }
  // f[22] is the network's name, made from the label.
  r.duration_s = Parse<double>(f, 23, where);
  if (!f[24].empty()) r.roles = ParseRunRoles(f, where);
  if (!f[kClosureFields].empty()) r.closures = ParseRunClosures(f, where);
  return r;
}

}  // namespace

constexpr std::size_t kRunsFields = kClosureFields + std::size(kClosureMetrics);

std::vector<RunResult> ReadRunsCsv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot read");
  std::string line;
  if (!std::getline(in, line) || line != kRunsHeader) {
    throw std::runtime_error(path.string() + ": not a dvpr runs.csv (unexpected header)");
  }
  std::vector<RunResult> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    const std::string where = path.string() + ":" + std::to_string(number);
    // dvpr ends every line; a last one without its end was cut off (its last number may be too).
    if (in.eof()) throw std::runtime_error(where + ": the file ends inside this line (no line end: a cut file?)");
    const auto fields = SplitCsv(line);
    if (fields.size() != kRunsFields) {
      throw std::runtime_error(where + ": expected " + std::to_string(kRunsFields) + " fields, got " +
                               std::to_string(fields.size()) + " (a cut or edited file?)");
    }
    rows.push_back(ParseRunRow(fields, where));
  }
  return rows;
}

bool SameNetworkColumns(const NetworkLabel& a, const NetworkLabel& b) {
  const auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  return a.model == b.model && same(a.bandwidth_bps, b.bandwidth_bps) && same(a.latency_ms, b.latency_ms) &&
         a.loss == b.loss;
}

void LabelNetworks(std::vector<RunResult>& rows, std::span<const NetworkLabel> networks,
                   const std::filesystem::path& runs_csv) {
  for (std::size_t i = 0; i < rows.size(); ++i) {
    NetworkLabel& row = rows[i].key.network;
    // The paper protocol has no network, dvpr launch's (lcm) a real one no config describes.
    if (row.model.empty() || !RowTraits(rows[i].key.protocol).simulated_network) continue;
    const std::string where = runs_csv.string() + ":" + std::to_string(i + 2);
    if (row.variant < 0 || static_cast<std::size_t>(row.variant) >= networks.size()) {
      throw std::runtime_error(where + ": network variant " + std::to_string(row.variant) + ", but the config has " +
                               std::to_string(networks.size()) + " (is config.yaml the one of this run?)");
    }
    const NetworkLabel& label = networks[static_cast<std::size_t>(row.variant)];
    if (!SameNetworkColumns(row, label)) {
      throw std::runtime_error(where + ": network variant " + std::to_string(row.variant) + " is '" +
                               NetworkName(row) + "' here but '" + NetworkName(label) +
                               "' in the config (is config.yaml the one of this run?)");
    }
    row = label;
  }
}

}  // namespace dvpr
