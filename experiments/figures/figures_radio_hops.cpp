// radio_hops.png (figures_radio.h): the hop histogram of delivered copies, decentralized beside
// broadcast, from radio.csv's delivered_by_hops.
#include <algorithm>
#include <charconv>
#include <map>
#include <sstream>
#include <stdexcept>

#include "experiments/figures/figure_style.h"
#include "experiments/figures/figures_radio.h"
#include "experiments/figures/gnuplot_text.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/results/result_writers.h"

namespace dvpr {

namespace {

namespace fs = std::filesystem;

constexpr int kMaxHops = 64;  // Network::kMaxHops: no delivered copy took more

// radio.csv's delivered_by_hops field ("6 0 2"): counts >= 0, at most kMaxHops of them.
std::vector<double> ByHops(const CsvTable& t, std::size_t row, std::size_t column) {
  std::vector<double> out;
  std::istringstream in(t.rows[row][column]);
  for (std::string field; in >> field;) {
    long long v = -1;
    const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
    if (ec != std::errc() || end != field.data() + field.size() || v < 0 || out.size() >= kMaxHops) {
      throw std::runtime_error(t.path.string() + ": line " + std::to_string(row + 2) +
                               ": delivered_by_hops: expected at most " + std::to_string(kMaxHops) +
                               " counts >= 0, got '" + OneLineText(field) + "'");
    }
    out.push_back(static_cast<double>(v));
  }
  return out;
}

// The panel's name: the radio and its routing ("range 200m shortest_path").
std::string PanelName(const std::vector<RunResult>& rows, int variant) {
  for (const RunResult& r : rows) {
    if (r.key.network.variant == variant && !r.key.network.next_hop.empty()) {
      return RadioLabelOf(rows, variant) + " " + r.key.network.next_hop;
    }
  }
  return RadioLabelOf(rows, variant);
}

// The classes of the hop axis: one per hop count up to 8 hops, else 1 to 4 and then 5-9, 10-19,
// 20-64 (a routing loop's copies can make up to 64 transmissions: 64 classes would smear their
// labels). Only the classes up to the one of `longest` hops.
struct HopClass {
  std::size_t first;  // hops, from 1
  std::size_t last;
  std::string label;
};
std::vector<HopClass> HopClasses(std::size_t longest) {
  std::vector<HopClass> out;
  if (longest <= 8) {
    for (std::size_t h = 1; h <= longest; ++h) out.push_back({h, h, std::to_string(h)});
    return out;
  }
  const std::size_t bounds[][2] = {{1, 1}, {2, 2}, {3, 3}, {4, 4}, {5, 9}, {10, 19}, {20, 64}};
  for (const auto& b : bounds) {
    if (b[0] > longest) break;
    out.push_back({b[0], b[1], b[0] == b[1] ? std::to_string(b[0]) : std::to_string(b[0]) + "-" + std::to_string(b[1])});
  }
  return out;
}

}  // namespace

std::optional<FigureScript> WriteRadioHopsFigure(const fs::path& dir, const CsvTable& t, const std::vector<RunResult>& rows,
                                                 std::string& why) {
  if (t.rows.empty() || std::find(t.header.begin(), t.header.end(), "delivered_by_hops") == t.header.end()) {
    why = "no radio.csv rows with delivered_by_hops";
    return std::nullopt;
  }
  const std::size_t c_protocol = t.Column("protocol"), c_strategy = t.Column("strategy"), c_robots = t.Column("robots"),
                    c_variant = t.Column("network_variant"), c_hops = t.Column("delivered_by_hops");
  int n = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) n = std::max(n, t.Integer(i, c_robots, 2, 1 << 20));
  // variant -> strategy (0 decentralized, 1 broadcast) -> copies by hops, summed over runs.
  std::map<int, std::array<std::vector<double>, 2>> counts;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const std::string& s = t.rows[i][c_strategy];
    if (!RowTraits(t.rows[i][c_protocol]).simulated_network || t.Integer(i, c_robots, 2, 1 << 20) != n ||
        (s != "decentralized" && s != "broadcast")) {
      continue;
    }
    std::vector<double>& sum = counts[t.Integer(i, c_variant, 0, 1 << 20)][s == "decentralized" ? 0 : 1];
    const std::vector<double> by_hops = ByHops(t, i, c_hops);
    if (sum.size() < by_hops.size()) sum.resize(by_hops.size(), 0.0);
    for (std::size_t h = 0; h < by_hops.size(); ++h) sum[h] += by_hops[h];
  }
  if (counts.empty()) {
    why = "no decentralized or broadcast row in radio.csv";
    return std::nullopt;
  }
  const int panels = static_cast<int>(counts.size());
  const int columns = std::min(panels, 4);
  const int panel_rows = (panels + columns - 1) / columns;
  const int width = 420 * columns + 100;
  const int height = 400 * panel_rows + 130;
  // The one legend sits under the title, above the panels (it covers no bar).
  std::ostringstream body;
  body << "set multiplot layout " << panel_rows << "," << columns << " margins 0.05, 0.98, " << FormatDouble(70.0 / height, 3)
       << ", " << FormatDouble(1.0 - 105.0 / height, 3) << " spacing 0.06, " << FormatDouble(110.0 / height, 3) << " title "
       << GnuplotQuote("Hops of the delivered copies, n = " + std::to_string(n) +
                       " (radio.csv delivered_by_hops, all runs: every delivered copy of every message)")
       << " font ',13'\n"
       << "set style data histograms\nset style histogram clustered gap 1\nset style fill solid 0.85 border -1\n"
       << "set boxwidth 0.9\nset grid ytics\nset yrange [0:100]\nset ytics 0, 20, 100\nset xlabel 'hops'\nset ylabel '% of delivered copies'\n"
       << "set key at screen 0.5, screen " << FormatDouble(1.0 - 45.0 / height, 3) << " center top horizontal box\n";
  int p = 0;
  for (const auto& [variant, by_strategy] : counts) {
    const std::string file = "hops_" + std::to_string(p) + ".dat";
    const std::size_t longest = std::max(by_strategy[0].size(), by_strategy[1].size());
    std::array<double, 2> total{};
    for (int s = 0; s < 2; ++s) {
      for (const double c : by_strategy[static_cast<std::size_t>(s)]) total[static_cast<std::size_t>(s)] += c;
    }
    std::string dat = "# " + OneLineText(PanelName(rows, variant)) + ": hops decentralized_percent broadcast_percent\n";
    for (const HopClass& k : HopClasses(longest)) {
      dat += k.label;
      for (std::size_t s = 0; s < 2; ++s) {
        double c = 0;
        for (std::size_t h = k.first; h <= k.last && h <= by_strategy[s].size(); ++h) c += by_strategy[s][h - 1];
        dat += " " + (total[s] > 0 ? FormatDouble(100.0 * c / total[s]) : std::string("NaN"));
      }
      dat += "\n";
    }
    WriteFileAtomic(dir / file, dat);
    body << "set title " << GnuplotQuote(PanelName(rows, variant)) << "\n"
         << "plot " << GnuplotQuote(file) << " using 2:xtic(1) lc rgb '" << figure_style::StrategyColour(0)
         << "' title 'decentralized', '' using 3 lc rgb '" << figure_style::StrategyColour(1) << "' title 'broadcast'\n"
         << (p == 0 ? "unset key\n" : "");
    ++p;
  }
  body << "unset multiplot\n";
  FigureScript f;
  f.width = width;
  f.height = height;
  f.body = body.str();
  return f;
}

}  // namespace dvpr
