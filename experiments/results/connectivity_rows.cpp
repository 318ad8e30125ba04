#include "experiments/results/connectivity_rows.h"

#include "experiments/results/result_writers.h"

namespace dvpr {

namespace {

// One field: the robots' counts separated by spaces ("2 1 1"), so a row stays one line of CSV
// whatever the team size.
std::string RobotsInRange(const std::vector<int>& counts) {
  std::string out;
  for (std::size_t i = 0; i < counts.size(); ++i) out += (i ? " " : "") + std::to_string(counts[i]);
  return out;
}

}  // namespace

const char* const kConnectivityHeader =
    "protocol,strategy,robots,run,network_variant,time_s,pairs_in_range,components,largest_component,mean_hops,"
    "max_hops,robots_in_range";

std::string CsvRow(const ConnectivityRow& r) {
  const RunKey& k = r.key;
  // ns / 1e9 (not ns * 1e-9): a division of two exact numbers, so 0.3 s is written 0.3.
  return k.protocol + "," + k.strategy + "," + std::to_string(k.robots) + "," + std::to_string(k.run) + "," +
         std::to_string(k.network.variant) + "," + FormatDouble(static_cast<double>(r.time_ns) / 1e9) + "," +
         std::to_string(r.pairs_in_range) + "," + std::to_string(r.components) + "," +
         std::to_string(r.largest_component) + "," + FormatDouble(r.mean_hops) + "," + std::to_string(r.max_hops) +
         "," + RobotsInRange(r.robots_in_range);
}

RunConnectivity SummarizeConnectivity(std::span<const ConnectivityRow> rows) {
  RunConnectivity s;
  if (rows.empty()) return s;
  s.key = rows.front().key;
  long long connected = 0, with_pairs = 0;
  double hops = 0.0;
  for (const ConnectivityRow& r : rows) {
    connected += r.components == 1 ? 1 : 0;
    if (r.pairs_in_range > 0) {
      hops += r.mean_hops;
      ++with_pairs;
    }
  }
  s.connected_time_share = static_cast<double>(connected) / static_cast<double>(rows.size());
  if (with_pairs > 0) s.connected_pair_mean_hops = hops / static_cast<double>(with_pairs);
  return s;
}

void SummarizeConnectivityRuns(std::span<const ConnectivityRow> rows, std::vector<RunConnectivity>& out) {
  const auto same_run = [](const RunKey& a, const RunKey& b) {
    return a.protocol == b.protocol && a.strategy == b.strategy && a.robots == b.robots && a.run == b.run &&
           a.network.variant == b.network.variant;
  };
  std::size_t begin = 0;
  for (std::size_t i = 1; i <= rows.size(); ++i) {
    if (i == rows.size() || !same_run(rows[i].key, rows[begin].key)) {
      out.push_back(SummarizeConnectivity(rows.subspan(begin, i - begin)));
      begin = i;
    }
  }
}

}  // namespace dvpr
