// The radio's figures (figures_radio.h): their data files and gnuplot commands.
#include "experiments/figures/figures_radio.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "experiments/figures/figure_style.h"
#include "experiments/figures/gnuplot_text.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/results/result_writers.h"

namespace dvpr {

namespace {

namespace fs = std::filesystem;

// A number for a data file; gnuplot skips the point of a NaN.
std::string Num(double v) { return std::isnan(v) ? "NaN" : FormatDouble(v); }

// One colour per radio variant, in variant order (light to dark: short to long ranges).
constexpr const char* kVariantColours[6] = {"#fdae61", "#f46d43", "#d73027", "#74add1", "#4575b4", "#313695"};

std::string VariantName(const std::vector<RunResult>& rows, int v) { return RadioLabelOf(rows, v); }

struct Step {
  double time_s = 0;
  int pairs = 0;
  int components = 0;
};

}  // namespace

std::string RadioLabelOf(const std::vector<RunResult>& rows, int variant) {
  for (const RunResult& r : rows) {
    if (r.key.network.variant != variant || r.key.network.model.empty()) continue;
    return r.key.network.propagation.empty() ? NetworkName(r.key.network) : r.key.network.propagation;
  }
  return "network variant " + std::to_string(variant);
}

std::optional<FigureScript> WriteConnectivityFigure(const fs::path& dir, const CsvTable& t, const std::vector<RunResult>& rows,
                                                    std::string& why) {
  if (t.rows.empty()) {
    why = "no connectivity.csv rows";
    return std::nullopt;
  }
  const std::size_t c_strategy = t.Column("strategy"), c_robots = t.Column("robots"), c_run = t.Column("run"),
                    c_variant = t.Column("network_variant"), c_time = t.Column("time_s"),
                    c_pairs = t.Column("pairs_in_range"), c_components = t.Column("components");
  const std::string strategy = t.rows.front()[c_strategy];
  int first_run = t.Integer(0, c_run, 0, 1 << 30);
  for (std::size_t i = 0; i < t.rows.size(); ++i) first_run = std::min(first_run, t.Integer(i, c_run, 0, 1 << 30));
  // (n, variant) -> steps of the first run, first strategy.
  std::map<std::pair<int, int>, std::vector<Step>> series;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    if (t.rows[i][c_strategy] != strategy || t.Integer(i, c_run, 0, 1 << 30) != first_run) continue;
    const int n = t.Integer(i, c_robots, 2, 1 << 20);
    series[{n, t.Integer(i, c_variant, 0, 1 << 20)}].push_back(
        Step{t.Count(i, c_time), t.Integer(i, c_pairs, 0, n * (n - 1) / 2), t.Integer(i, c_components, 1, n)});
  }
  std::set<int> all_n;
  for (const auto& [key, steps] : series) all_n.insert(key.first);
  std::vector<int> shown(all_n.begin(), all_n.end());
  if (shown.size() > 3) shown = {shown.back()};
  // Who reaches whom is the propagation's: variants that differ only in their routing (or rate)
  // have the same lines, drawn once, each propagation in a colour of its own.
  std::vector<std::string> names;
  for (const auto& [key, steps] : series) {
    const std::string name = VariantName(rows, key.second);
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  const auto colour = [&](const std::string& name) {
    const auto i = static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
    return names.size() <= 6 ? std::string(kVariantColours[i]) : figure_style::StrategyColour(i);
  };
  // One legend for all panels, right of them (it covers no data).
  const double right = 1.0 - 200.0 / (600 + 500 * static_cast<double>(shown.size()));
  const std::string key = "set key at screen " + FormatDouble(right + 0.01, 3) + ", screen 0.88 left top box\n";
  std::ostringstream top, bottom;
  for (std::size_t col = 0; col < shown.size(); ++col) {
    const int n = shown[col];
    const std::string file = "conn_" + std::to_string(n) + ".dat";
    std::string dat;
    std::ostringstream plot_share, plot_comp;
    int block = 0;
    std::set<std::string> drawn;
    for (const auto& [key, steps] : series) {
      if (key.first != n) continue;
      const std::string name = VariantName(rows, key.second);
      if (!drawn.insert(name).second) continue;
      dat += "# " + OneLineText(name) + "\n";
      for (const Step& s : steps) {
        dat += FormatDouble(s.time_s) + " " + std::to_string(s.pairs) + " " +
               FormatDouble(100.0 * s.pairs / (n * (n - 1) / 2.0)) + " " + std::to_string(s.components) + "\n";
      }
      dat += "\n\n";
      const std::string style = " with steps lw 2 lc rgb '" + colour(name) + "' title " + GnuplotQuote(name);
      plot_share << (block ? ", \\\n     " : "plot ") << GnuplotQuote(file) << " index " << block << " using 1:3" << style;
      plot_comp << (block ? ", \\\n     " : "plot ") << GnuplotQuote(file) << " index " << block << " using 1:4" << style;
      ++block;
    }
    WriteFileAtomic(dir / file, dat);
    top << "set title " << GnuplotQuote("n = " + std::to_string(n) + ": robot pairs in range of each other") << "\n"
        << "set ylabel '% of the " << n * (n - 1) / 2 << " pairs'\nset yrange [0:100]\n"
        << (col == 0 ? key : "unset key\n") << plot_share.str() << "\n";
    bottom << "set title " << GnuplotQuote("n = " + std::to_string(n) + ": separate networks (1 = the team is one network)")
           << "\nset ylabel 'connected components'\nset yrange [0:" << n + 1 << "]\n"
           << "unset key\n" << plot_comp.str() << "\n";
  }
  FigureScript f;
  f.width = 600 + 500 * static_cast<int>(shown.size());
  f.height = 900;
  // gnuplot's multiplot fills row by row: the top row (pairs) is drawn first for every column.
  f.body = "set multiplot layout 2," + std::to_string(shown.size()) + " margins 0.05, " + FormatDouble(right, 3) +
           ", 0.08, 0.9 spacing 0.06, 0.12 title " +
           GnuplotQuote("Who reaches whom over time (connectivity.csv: run " + std::to_string(first_run) +
                        ", one line per propagation: the routings share it)") +
           " font ',13'\nset xlabel 'virtual time (s)'\nset grid\n" + top.str() + bottom.str() + "unset multiplot\n";
  return f;
}

namespace {

struct Acc {
  double sum = 0;
  int count = 0;
  void Add(double v) {
    if (!std::isnan(v)) sum += v, ++count;
  }
  double Mean() const { return count ? sum / count : kNotApplicable; }
};

// Share of queries answered (every reply in: latency_ns written) per (strategy, n, variant),
// mean over runs; empty without queries.csv rows.
std::map<std::tuple<std::string, int, int>, Acc> AnsweredShares(const CsvTable& q) {
  std::map<std::tuple<std::string, int, int>, Acc> out;
  if (q.rows.empty()) return out;
  const std::size_t c_protocol = q.Column("protocol"), c_strategy = q.Column("strategy"), c_robots = q.Column("robots"),
                    c_run = q.Column("run"), c_variant = q.Column("network_variant"), c_latency = q.Column("latency_ns");
  std::map<std::tuple<std::string, int, int, int>, std::pair<long long, long long>> runs;  // answered, queries
  for (std::size_t i = 0; i < q.rows.size(); ++i) {
    if (!RowTraits(q.rows[i][c_protocol]).simulated_network) continue;
    auto& [answered, total] = runs[{q.rows[i][c_strategy], q.Integer(i, c_robots, 2, 1 << 20), q.Integer(i, c_run, 0, 1 << 30),
                                    q.Integer(i, c_variant, 0, 1 << 20)}];
    answered += q.rows[i][c_latency].empty() ? 0 : 1;
    ++total;
  }
  for (const auto& [k, v] : runs) {
    out[{std::get<0>(k), std::get<1>(k), std::get<3>(k)}].Add(100.0 * static_cast<double>(v.first) / static_cast<double>(v.second));
  }
  return out;
}

}  // namespace

std::optional<FigureScript> WriteRadioRangeFigure(const fs::path& dir, const std::vector<RunResult>& rows, const CsvTable& queries,
                                                  std::string& why, const std::optional<std::string>& routing,
                                                  const std::string& name) {
  struct Cell {
    Acc bytes, latency, delivered;
  };
  std::map<std::tuple<std::string, int, double>, Cell> cells;  // (strategy, n, range)
  std::map<std::tuple<std::string, int, double>, int> variant_of;
  std::set<double> ranges;
  for (const RunResult& r : rows) {
    if (!RowTraits(r.key.protocol).simulated_network || r.key.network.model != "radio") continue;
    if (r.key.strategy != "decentralized" && r.key.strategy != "broadcast") continue;
    if (routing && r.key.network.next_hop != *routing) continue;
    const double range = r.key.network.range_m;
    if (std::isnan(range)) continue;  // log_distance: no one range
    ranges.insert(range);
    Cell& c = cells[{r.key.strategy, r.key.robots, range}];
    c.bytes.Add(r.bytes_per_query);
    c.latency.Add(r.mean_latency_ms);
    // The query copies that reached their robot (runs.csv, every run): where the team is split,
    // most never do, which is why its bytes are low.
    if (r.roles && r.roles->copies[0].wire > 0) {
      c.delivered.Add(100.0 * static_cast<double>(r.roles->copies[0].delivered_wire) /
                      static_cast<double>(r.roles->copies[0].wire));
    }
    variant_of[{r.key.strategy, r.key.robots, range}] = r.key.network.variant;
  }
  if (ranges.size() < 2) {
    why = "needs radio variants of two or more ranges";
    return std::nullopt;
  }
  const auto answered = AnsweredShares(queries);
  // The middle panel's share: queries answered (queries.csv) when written, else the query copies
  // delivered (runs.csv). Points under kSplit % of it are circled in the bytes panel.
  constexpr double kSplit = 90;
  const bool by_answer = !answered.empty();
  const std::string share_name = by_answer ? "answered" : "of query copies delivered";
  std::string dat, split;
  std::vector<std::pair<std::string, int>> blocks;  // (strategy, n)
  for (const char* s : {"decentralized", "broadcast"}) {
    std::set<int> robots;
    for (const auto& [k, c] : cells) if (std::get<0>(k) == s) robots.insert(std::get<1>(k));
    for (int n : robots) {
      dat += "# " + std::string(s) + " n = " + std::to_string(n) + "\n";
      for (const auto& [k, c] : cells) {
        if (std::get<0>(k) != s || std::get<1>(k) != n) continue;
        const auto a = answered.find({s, n, variant_of.at(k)});
        const double answered_share = a == answered.end() ? kNotApplicable : a->second.Mean();
        dat += FormatDouble(std::get<2>(k)) + " " + Num(c.bytes.Mean()) + " " + Num(answered_share) + " " +
               Num(c.latency.Mean()) + " " + Num(c.delivered.Mean()) + "\n";
        const double share = by_answer ? answered_share : c.delivered.Mean();
        if (share < kSplit) {  // false for NaN
          split += FormatDouble(std::get<2>(k)) + " " + Num(c.bytes.Mean()) + " \"" + FormatDouble(share, 0) + "%\"\n";
        }
      }
      dat += "\n\n";
      blocks.emplace_back(s, n);
    }
  }
  const std::string data_file = name + ".dat", split_file = name + "_split.dat";
  WriteFileAtomic(dir / data_file, dat);
  WriteFileAtomic(dir / split_file, split.empty() ? "# none\n" : split);
  const auto plot = [&](int column) {
    std::ostringstream p;
    std::set<int> all_n;
    for (const auto& b : blocks) all_n.insert(b.second);
    const std::vector<int> ns(all_n.begin(), all_n.end());
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      const auto& [s, n] = blocks[i];
      const auto ni = static_cast<std::size_t>(std::find(ns.begin(), ns.end(), n) - ns.begin());
      p << (i ? ", \\\n     " : "plot ") << "'" << data_file << "' index " << i << " using 1:" << column
        << " with linespoints lw 2 dt " << figure_style::NetworkDash(ni) << " pt " << figure_style::NetworkPoint(ni)
        << " ps 1.2 lc rgb '" << figure_style::StrategyColour(s == "decentralized" ? 0 : 1) << "' title "
        << GnuplotQuote(s + ", n = " + std::to_string(n));
    }
    return p.str() + "\n";
  };
  std::ostringstream xt;
  xt << "set xtics (";
  bool first = true;
  for (double r : ranges) xt << (first ? "" : ", ") << "'" << FormatDouble(r) << "' " << FormatDouble(r), first = false;
  xt << ")\n";
  std::ostringstream s;
  const std::string relays = !routing ? "shortest-path relays where configured"
                             : routing->empty() ? "direct: no relays"
                                                : *routing + " routing";
  // One key for the three panels, below them: inside, it would cover the lines.
  const std::string circled = "circled: under " + FormatDouble(kSplit, 0) + " % " + share_name;
  std::vector<std::string> title = {"The team on radios: what range costs (means over runs; " + relays + ")"};
  if (!split.empty()) {
    title.push_back(circled + ": few bytes because the team is split and most queries never reach a robot, not because "
                    "the range is cheap");
  }
  s << "set multiplot layout 1,3 margins 0.06, 0.98, 0.22, 0.83 spacing 0.07 title " << GnuplotTitle(title)
    << " font ',13'\n"
    << "set grid\nset xlabel 'radio range (m)'\n" << xt.str() << "set offsets graph 0.05, graph 0.05, 0, 0\n"
    << "set title 'Bytes on the air per query (every transmission, relays included)'\nset ylabel 'bytes per query'\n"
    << "set logscale y\nset key at screen 0.5, screen 0.01 center bottom vertical maxrows 3\n";
  std::string bytes_plot = plot(2);
  bytes_plot.pop_back();  // its newline: the circles join the same plot
  s << bytes_plot;
  if (split.empty()) {
    s << "\n";
  } else {
    // Fewer bytes where the team is split: most queries never reach a robot that could answer.
    // The share itself is in the middle panel, at the same range: a label here would crowd.
    s << ", \\\n     " << GnuplotQuote(split_file) << " using 1:2 with points pt 6 ps 2.6 lw 1.5 lc rgb '#000000' title "
      << GnuplotQuote("circled: under " + FormatDouble(kSplit, 0) + " % " + (by_answer ? "answered" : "delivered")) << "\n";
  }
  s << "unset logscale y\nunset key\n";
  if (by_answer) {
    s << "set title 'Queries answered (every reply in; queries.csv)'\nset ylabel '% of queries'\nset yrange [0:100]\n"
      << plot(3);
  } else {
    s << "set title " << GnuplotTitle({"Query copies delivered to their robot", "(runs.csv: query_delivered_wire_bytes / query_copy_wire_bytes)"})
      << "\nset ylabel '% of query copies'\nset yrange [0:100]\n" << plot(5);
  }
  s << "set yrange [0:*]\nset title 'Mean latency of the answered queries'\nset ylabel 'ms'\n" << plot(4)
    << "unset multiplot\n";
  FigureScript f;
  f.width = 1800;
  f.height = 660;
  f.body = s.str();
  return f;
}

std::vector<std::pair<std::string, FigureScript>> RadioFigures(const fs::path& out_dir, const fs::path& data_dir,
                                                               const std::vector<RunResult>& rows) {
  std::vector<std::pair<std::string, FigureScript>> out;
  std::string why;
  const CsvTable connectivity = ReadCsvTable(out_dir / "connectivity.csv");
  if (auto f = WriteConnectivityFigure(data_dir, connectivity, rows, why)) out.emplace_back("connectivity", std::move(*f));
  if (auto f = WriteRobotsInRangeFigure(data_dir, connectivity, rows, why)) {
    out.emplace_back("robots_in_range", std::move(*f));
  }
  if (auto f = WriteRadioHopsFigure(data_dir, ReadCsvTable(out_dir / "radio.csv"), rows, why)) {
    out.emplace_back("radio_hops", std::move(*f));
  }
  // One figure per routing of the radio variants (the first is radio_range, the others
  // radio_range_<routing>): lines of two routings in one plot would be twelve.
  std::vector<std::string> routings;
  for (const RunResult& r : rows) {
    if (r.key.network.model == "radio" &&
        std::find(routings.begin(), routings.end(), r.key.network.next_hop) == routings.end()) {
      routings.push_back(r.key.network.next_hop);
    }
  }
  const CsvTable queries = ReadCsvTable(out_dir / "queries.csv");
  if (routings.size() <= 1) {
    if (auto f = WriteRadioRangeFigure(data_dir, rows, queries, why)) out.emplace_back("radio_range", std::move(*f));
  } else {
    for (std::size_t i = 0; i < routings.size(); ++i) {
      const std::string name = i == 0 ? "radio_range" : "radio_range_" + (routings[i].empty() ? "direct" : routings[i]);
      if (auto f = WriteRadioRangeFigure(data_dir, rows, queries, why, routings[i], name)) {
        out.emplace_back(name, std::move(*f));
      }
    }
  }
  return out;
}

}  // namespace dvpr
