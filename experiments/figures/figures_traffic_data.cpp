// The numbers of the traffic figures (figures_traffic.cpp): runs.csv's bytes by role, and the
// per_robot.csv and links.csv rows of one run, read by their header names.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "experiments/figures/figures_traffic.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/results/result_writers.h"
#include "experiments/results/spread.h"

namespace dvpr {

namespace {

bool IsSimWithRoles(const RunResult& r) { return RowTraits(r.key.protocol).simulated_network && r.roles.has_value(); }

double Role(const RunResult& r, MessageRole role) {
  return static_cast<double>(r.roles->copies[static_cast<std::size_t>(role)].wire);
}

// One cell's per-run values, in the rows' order, for their spread.
struct CellRuns {
  std::vector<double> pr_bytes, total_bytes, offered, delivered, latency;
};

double HalfWidth(const std::vector<double>& values) {
  const double ci95 = SpreadOf(values).ci95;
  return std::isnan(ci95) ? 0.0 : ci95;
}

}  // namespace

TrafficTable TabulateTraffic(const std::vector<RunResult>& rows) {
  TrafficTable t;
  std::map<int, NetworkLabel> variants;
  std::map<std::tuple<std::string, int, int>, CellRuns> runs;
  for (const RunResult& r : rows) {
    if (std::find(t.strategies.begin(), t.strategies.end(), r.key.strategy) == t.strategies.end()) {
      t.strategies.push_back(r.key.strategy);
    }
    if (!IsSimWithRoles(r)) continue;
    t.sim_rows = true;
    if (r.queries <= 0) continue;
    variants.emplace(r.key.network.variant, r.key.network);
    if (std::find(t.robots.begin(), t.robots.end(), r.key.robots) == t.robots.end()) t.robots.push_back(r.key.robots);
    const std::tuple<std::string, int, int> key{r.key.strategy, r.key.network.variant, r.key.robots};
    TrafficCell& c = t.cells[key];
    CellRuns& v = runs[key];
    const double q = static_cast<double>(r.queries);
    ++c.runs;
    const double pr = PlaceRecognitionBytesPerQuery(r);
    c.pr_bytes_per_query += pr;
    v.pr_bytes.push_back(pr);
    c.pr_bytes_by_run[r.key.run] = pr;
    double all = 0;
    for (int i = 0; i < kMessageRoles; ++i) {
      const double b = Role(r, MessageRole(i)) / q;
      c.role_bytes_per_query[static_cast<std::size_t>(i)] += b;
      all += b;
    }
    v.total_bytes.push_back(all);
    CopyBytes total;
    for (const CopyBytes& b : r.roles->copies) total += b;
    v.offered.push_back(static_cast<double>(total.wire) * 8e-6 / r.duration_s);
    v.delivered.push_back(static_cast<double>(total.delivered_wire) * 8e-6 / r.duration_s);
    v.latency.push_back(std::isnan(r.mean_latency_ms) ? 0.0 : r.mean_latency_ms);
    c.offered_mbps += v.offered.back();
    c.delivered_mbps += v.delivered.back();
    c.latency_ms += v.latency.back();
    c.longest_drive_s = std::max(c.longest_drive_s, r.duration_s);
  }
  for (auto& [key, c] : t.cells) {
    const double n = c.runs;
    c.pr_bytes_per_query /= n;
    for (double& b : c.role_bytes_per_query) b /= n;
    c.offered_mbps /= n;
    c.delivered_mbps /= n;
    c.latency_ms /= n;
    const CellRuns& v = runs.at(key);
    c.pr_bytes_ci95 = HalfWidth(v.pr_bytes);
    c.total_bytes_ci95 = HalfWidth(v.total_bytes);
    c.offered_ci95 = HalfWidth(v.offered);
    c.delivered_ci95 = HalfWidth(v.delivered);
    c.latency_ci95 = HalfWidth(v.latency);
  }
  for (const auto& [index, label] : variants) t.networks.push_back(label);
  std::sort(t.robots.begin(), t.robots.end());
  return t;
}

std::string NoSimTraffic(const TrafficTable& t) {
  return t.sim_rows ? "no run of protocol sim sent a query" : "needs protocol sim";
}

const TrafficCell* TrafficTable::Find(const std::string& strategy, int variant, int robots) const {
  const auto it = cells.find({strategy, variant, robots});
  return it == cells.end() ? nullptr : &it->second;
}

std::size_t TrafficTable::StrategyIndex(const std::string& strategy) const {
  return static_cast<std::size_t>(std::find(strategies.begin(), strategies.end(), strategy) - strategies.begin());
}

// The network the n - 1 law is shown on: point-to-point links at the largest bandwidth (every
// copy its own transmission, the least queueing), else the largest bandwidth of any model.
int TrafficTable::ShownVariant() const {
  const NetworkLabel* best = nullptr;
  for (const NetworkLabel& n : networks) {
    const bool p2p = n.model == "point_to_point";
    const bool best_p2p = best != nullptr && best->model == "point_to_point";
    if (best == nullptr || (p2p && !best_p2p) ||
        (p2p == best_p2p && n.bandwidth_bps > best->bandwidth_bps)) {
      best = &n;
    }
  }
  return best == nullptr ? -1 : best->variant;
}

const NetworkLabel* TrafficTable::Network(int variant) const {
  for (const NetworkLabel& n : networks) {
    if (n.variant == variant) return &n;
  }
  return nullptr;
}

std::string NetworkSlug(const NetworkLabel& network) {
  std::string slug;
  for (const char c : NetworkName(network)) {
    const char l = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if ((l >= 'a' && l <= 'z') || (l >= '0' && l <= '9') || l == '.') {
      slug += l;
    } else if (!slug.empty() && slug.back() != '-') {
      slug += '-';
    }
  }
  if (slug.size() > 48) slug.resize(48);
  while (!slug.empty() && (slug.back() == '-' || slug.back() == '.')) slug.pop_back();
  return slug;
}

std::vector<VariantFigure> VariantFigures(const TrafficTable& t) {
  if (t.networks.size() <= 1) return {VariantFigure{t.ShownVariant(), "", ""}};
  // The index as wide as the largest (net00 .. net10): the files list in variant order.
  const std::size_t width = std::to_string(t.networks.back().variant).size();
  std::vector<VariantFigure> out;
  for (const NetworkLabel& n : t.networks) {
    std::string index = std::to_string(n.variant);
    index.insert(0, width - index.size(), '0');
    const std::string net = "net" + index;
    const std::string slug = NetworkSlug(n);
    out.push_back(VariantFigure{n.variant, "-" + net + (slug.empty() ? "" : "-" + slug), net + "_"});
  }
  return out;
}

CsvTable ReadCsvTable(const std::filesystem::path& path) {
  std::ifstream in(path);
  CsvTable t;
  if (!in) return t;
  std::string line;
  auto split = [](const std::string& l) {
    std::vector<std::string> f;
    std::string field;
    std::istringstream s(l);
    while (std::getline(s, field, ',')) f.push_back(field);
    if (!l.empty() && l.back() == ',') f.emplace_back();
    return f;
  };
  t.path = path;
  if (!std::getline(in, line)) return t;
  t.header = split(line);
  while (std::getline(in, line)) t.rows.push_back(split(line));
  return t;
}

std::size_t CsvTable::Column(const std::string& name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end()) throw std::runtime_error(path.string() + ": no column " + name);
  return static_cast<std::size_t>(it - header.begin());
}

namespace {

[[noreturn]] void BadField(const CsvTable& t, std::size_t row, std::size_t column, const std::string& expected) {
  throw std::runtime_error(t.path.string() + ": line " + std::to_string(row + 2) + ": " + t.header[column] +
                           ": expected " + expected + ", got '" + t.rows[row][column] + "'");
}

}  // namespace

int CsvTable::Integer(std::size_t row, std::size_t column, int lo, int hi) const {
  const std::string& s = rows[row][column];
  int v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || s.empty() || v < lo || v > hi) {
    BadField(*this, row, column, "an integer from " + std::to_string(lo) + " to " + std::to_string(hi));
  }
  return v;
}

double CsvTable::Count(std::size_t row, std::size_t column) const {
  const std::string& s = rows[row][column];
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || s.empty() || !std::isfinite(v) || v < 0) {
    BadField(*this, row, column, "a number >= 0");
  }
  return v;
}

}  // namespace dvpr
