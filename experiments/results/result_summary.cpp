// summary.json (means per group) and reading runs.csv back for `dvpr plot`.
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "experiments/results/result_writers.h"

namespace dvpr {

namespace {

struct Mean {
  double sum = 0;
  int count = 0;
  void Add(double v) {
    if (!std::isnan(v)) { sum += v; ++count; }
  }
  std::string Json() const { return count == 0 ? "null" : FormatDouble(sum / count); }
};

struct Group {
  RunKey key;
  int runs = 0;
  std::map<std::string, Mean> means;  // keyed by column; printed in kMetricOrder
};

const char* const kMetricOrder[] = {
    "auc", "auc_reference", "relative_auc", "worst_balance_ratio", "queries", "messages",
    "payload_bytes", "wire_bytes", "bytes_per_query", "mean_latency_ms", "p99_latency_ms",
    "dropped_messages"};

void AddRun(Group& g, const RunResult& r) {
  ++g.runs;
  const double values[] = {r.auc, r.auc_reference, r.relative_auc, r.worst_balance_ratio,
                           double(r.queries), double(r.messages), double(r.payload_bytes),
                           double(r.wire_bytes), r.bytes_per_query, r.mean_latency_ms,
                           r.p99_latency_ms, double(r.dropped_messages)};
  for (std::size_t i = 0; i < std::size(kMetricOrder); ++i) g.means[kMetricOrder[i]].Add(values[i]);
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

std::string SummaryJson(const std::vector<RunResult>& rows) {
  std::vector<Group> groups;
  std::map<std::string, std::size_t> index;
  for (const auto& r : rows) {
    const std::string id = r.key.protocol + "|" + r.key.strategy + "|" +
                           std::to_string(r.key.robots) + "|" + r.key.network.model + "|" +
                           std::to_string(r.key.network.variant);
    auto [it, added] = index.emplace(id, groups.size());
    if (added) groups.push_back(Group{r.key, 0, {}});
    AddRun(groups[it->second], r);
  }
  std::ostringstream s;
  s << "{\n  \"groups\": [";
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const Group& g = groups[i];
    const NetworkLabel& n = g.key.network;
    s << (i ? "," : "") << "\n    {\"protocol\": " << JsonString(g.key.protocol)
      << ", \"strategy\": " << JsonString(g.key.strategy) << ", \"robots\": " << g.key.robots;
    if (!n.model.empty()) {
      s << ", \"network_variant\": " << n.variant << ", \"network_model\": "
        << JsonString(n.model) << ", \"bandwidth_bps\": "
        << (std::isnan(n.bandwidth_bps) ? "null" : FormatDouble(n.bandwidth_bps))
        << ", \"latency_ms\": " << (std::isnan(n.latency_ms) ? "null" : FormatDouble(n.latency_ms))
        << ", \"loss\": " << JsonString(n.loss);
    }
    s << ", \"runs\": " << g.runs << ",\n     \"mean\": {";
    for (std::size_t m = 0; m < std::size(kMetricOrder); ++m) {
      s << (m ? ", " : "") << JsonString(kMetricOrder[m]) << ": "
        << g.means.at(kMetricOrder[m]).Json();
    }
    s << "}}";
  }
  s << "\n  ]\n}\n";
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

template <typename T>
T Parse(const std::string& s, const std::string& where) {
  if (s.empty()) {
    if constexpr (std::is_floating_point_v<T>) return kNotApplicable;
  }
  T v{};
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) {
    throw std::runtime_error(where + ": not a number: '" + s + "'");
  }
  return v;
}

RunResult ParseRunRow(const std::vector<std::string>& f, const std::string& where) {
  RunResult r;
  r.key.protocol = f[0];
  r.key.strategy = f[1];
  r.key.robots = Parse<int>(f[2], where);
  r.key.run = Parse<int>(f[3], where);
  r.seed = Parse<std::uint64_t>(f[4], where);
  double* doubles[] = {&r.auc, &r.auc_reference, &r.relative_auc, &r.worst_balance_ratio};
  for (int i = 0; i < 4; ++i) *doubles[i] = Parse<double>(f[5 + i], where);
  r.queries = Parse<std::int64_t>(f[9], where);
  r.messages = Parse<std::int64_t>(f[10], where);
  r.payload_bytes = Parse<std::int64_t>(f[11], where);
  r.wire_bytes = Parse<std::int64_t>(f[12], where);
  r.bytes_per_query = Parse<double>(f[13], where);
  r.mean_latency_ms = Parse<double>(f[14], where);
  r.p99_latency_ms = Parse<double>(f[15], where);
  r.dropped_messages = Parse<std::int64_t>(f[16], where);
  if (!f[18].empty()) {
    r.key.network.variant = Parse<int>(f[17], where);
    r.key.network.model = f[18];
    r.key.network.bandwidth_bps = Parse<double>(f[19], where);
    r.key.network.latency_ms = Parse<double>(f[20], where);
    r.key.network.loss = f[21];
  }
  return r;
}

}  // namespace

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
    const auto fields = SplitCsv(line);
    if (fields.size() != 22) throw std::runtime_error(where + ": expected 22 fields");
    rows.push_back(ParseRunRow(fields, where));
  }
  return rows;
}

}  // namespace dvpr
