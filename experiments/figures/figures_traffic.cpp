// The traffic figures (figures_traffic.h): their data files and gnuplot commands.
#include "experiments/figures/figures_traffic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "experiments/figures/figure_style.h"
#include "experiments/figures/gnuplot_text.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/results/result_writers.h"

namespace dvpr {

namespace {

namespace fs = std::filesystem;
using figure_style::NetworkDash;
using figure_style::NetworkPoint;

// Names from runs.csv reach the scripts only single-quoted (gnuplot_text.h).

std::string Xtics(const std::vector<int>& robots) {
  std::string s = "set xtics (";
  for (std::size_t i = 0; i < robots.size(); ++i) s += (i ? ", " : "") + std::to_string(robots[i]);
  return s + ")\n";
}

std::string Colour(const TrafficTable& t, const std::string& strategy) {
  return "lc rgb '" + figure_style::StrategyColour(t.StrategyIndex(strategy)) + "'";
}

// The robot counts at which every strategy of `strategies` has a cell on variant v.
std::vector<int> CommonRobots(const TrafficTable& t, const std::vector<std::string>& strategies, int v) {
  std::vector<int> out;
  for (int n : t.robots) {
    if (std::all_of(strategies.begin(), strategies.end(), [&](const std::string& s) { return t.Find(s, v, n); })) {
      out.push_back(n);
    }
  }
  return out;
}

std::string Block(const std::string& title, const std::vector<std::pair<double, double>>& points) {
  std::string s = "# " + OneLineText(title) + "\n";
  for (const auto& [x, y] : points) s += FormatDouble(x) + " " + FormatDouble(y) + "\n";
  return s + "\n\n";
}

// A block whose lines carry more columns: a value and its spread (x y dy, x y dx dy, x y low high).
std::string Block(const std::string& title, const std::vector<std::vector<double>>& lines) {
  std::string s = "# " + OneLineText(title) + "\n";
  for (const std::vector<double>& line : lines) {
    for (std::size_t i = 0; i < line.size(); ++i) s += (i ? " " : "") + FormatDouble(line[i]);
    s += "\n";
  }
  return s + "\n\n";
}

// The lowest and highest broadcast / decentralized ratio of one run (the runs of one index share
// their seed). The ratio of the means lies between them: it is the runs' ratios weighted by
// decentralized's bytes.
std::pair<double, double> RatioRange(const TrafficCell& broadcast, const TrafficCell& decentralized) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& [run, b] : broadcast.pr_bytes_by_run) {
    const auto d = decentralized.pr_bytes_by_run.find(run);
    if (d == decentralized.pr_bytes_by_run.end()) continue;
    lo = std::min(lo, b / d->second);
    hi = std::max(hi, b / d->second);
  }
  return {lo, hi};
}

// Left panel of figure 1: bytes per query of both methods and the law, on network v.
std::string PrBytesPanel(const fs::path& dir, const TrafficTable& t, int v, const std::vector<int>& robots) {
  std::string dat;
  for (const char* s : {"decentralized", "broadcast"}) {
    std::vector<std::vector<double>> p;
    for (int n : robots) p.push_back({static_cast<double>(n), t.Find(s, v, n)->pr_bytes_per_query, t.Find(s, v, n)->pr_bytes_ci95});
    dat += Block(s, p);
  }
  std::vector<std::pair<double, double>> law;
  for (int n : robots) law.emplace_back(n, (n - 1) * t.Find("decentralized", v, n)->pr_bytes_per_query);
  dat += Block("n - 1 law", law);
  WriteFileAtomic(dir / "pr_bytes.dat", dat);
  const int n = robots.back();
  const double ratio = t.Find("broadcast", v, n)->pr_bytes_per_query / t.Find("decentralized", v, n)->pr_bytes_per_query;
  std::ostringstream s;
  s << "set title " << GnuplotTitle({"Place-recognition bytes per query (query + reply, every copy)",
                                    NetworkName(*t.Network(v)) + ", mean over runs, bars: its 95 % confidence interval"})
    << "\nset xlabel 'robots n'\nset ylabel 'wire bytes per query'\nset logscale y\n"
    << Xtics(t.robots) << "set key at graph 0.02, graph 0.84 left top\n"
    << "set label 1 " << GnuplotTitle({"measured at n = " + std::to_string(n) + ": broadcast / decentralized = " +
                                           FormatDouble(ratio, 1), "(n - 1 = " + std::to_string(n - 1) + ")"})
    << " at graph 0.03, graph 0.93 left front\n"
    << "plot 'pr_bytes.dat' index 0 using 1:2:3 with yerrorlines lw 2 pt 7 " << Colour(t, "decentralized")
    << " title 'decentralized (one owner)', \\\n     '' index 1 using 1:2:3 with yerrorlines lw 2 pt 5 "
    << Colour(t, "broadcast") << " title 'broadcast (n - 1 robots)', \\\n     '' index 2 using 1:2 with lines lw 1.5 dt 2 "
    << "lc rgb '#333333' title 'n - 1 law: (n - 1) x decentralized'\nunset label 1\nunset logscale y\n";
  return s.str();
}

// Right panel of figure 1: the measured ratio on every network, the band [n - 1, n + 1]. Its key
// goes below both panels, in key_rows rows (the lines of every network lie on one another: inside
// the plot a key would cover them).
std::string PrRatioPanel(const fs::path& dir, const TrafficTable& t, int key_rows) {
  std::string dat, band;
  std::ostringstream plot;
  plot << "plot 'pr_band.dat' using 1:2:3 with filledcurves fc rgb '#e6e6e6' title 'between n - 1 and n + 1'";
  int block = 0;
  for (std::size_t i = 0; i < t.networks.size(); ++i) {
    const int v = t.networks[i].variant;
    std::vector<std::vector<double>> p;
    for (int n : CommonRobots(t, {"decentralized", "broadcast"}, v)) {
      const TrafficCell& b = *t.Find("broadcast", v, n);
      const TrafficCell& d = *t.Find("decentralized", v, n);
      const auto [lo, hi] = RatioRange(b, d);
      const double ratio = b.pr_bytes_per_query / d.pr_bytes_per_query;
      // Without a run of one index in both strategies there is no per-run ratio: no bar.
      p.push_back({static_cast<double>(n), ratio, std::isfinite(lo) ? lo : ratio, std::isfinite(hi) ? hi : ratio});
    }
    if (p.empty()) continue;
    dat += Block(NetworkName(t.networks[i]), p);
    plot << ", \\\n     'pr_ratio.dat' index " << block++ << " using 1:2:3:4 with yerrorlines lw 1.5 lc rgb '#222222' dt "
         << NetworkDash(i) << " pt " << NetworkPoint(i) << " title " << GnuplotQuote(NetworkName(t.networks[i]));
  }
  for (int n : t.robots) band += std::to_string(n) + " " + std::to_string(n - 1) + " " + std::to_string(n + 1) + "\n";
  WriteFileAtomic(dir / "pr_ratio.dat", dat);
  WriteFileAtomic(dir / "pr_band.dat", band);
  return "set title " + GnuplotTitle({"Broadcast / decentralized place-recognition bytes, every network",
                                       "ratio of the means over runs, bars: lowest and highest run"}) +
         "\nset ylabel 'ratio'\nset key at screen 0.5, screen 0.01 center bottom vertical maxrows " +
         std::to_string(key_rows) + " font ',9'\n" + plot.str() + "\n";
}

}  // namespace

std::optional<FigureScript> WritePlaceRecognitionFigure(const fs::path& dir, const TrafficTable& t, std::string& why) {
  const int v = t.ShownVariant();
  const std::vector<int> robots = v < 0 ? std::vector<int>{} : CommonRobots(t, {"decentralized", "broadcast"}, v);
  if (robots.empty()) {
    why = t.cells.empty() ? NoSimTraffic(t) : "needs protocol sim with strategies decentralized and broadcast";
    return std::nullopt;
  }
  // The right panel's key: the band and every network, in up to three columns below the panels.
  const int key_rows = (static_cast<int>(t.networks.size()) + 1 + 2) / 3;
  FigureScript f;
  f.width = 1500;
  f.height = 650 + 18 * key_rows;
  f.body = "set multiplot layout 1,2 margins 0.07, 0.98, " + FormatDouble((70.0 + 18 * key_rows) / f.height, 3) +
           ", 0.88 spacing 0.1\nset grid\n" + PrBytesPanel(dir, t, v, robots) + "set yrange [0:*]\n" +
           PrRatioPanel(dir, t, key_rows) + "unset multiplot\n";
  return f;
}

namespace {

// The roles any strategy sent on network v (the others stay out of the legend).
std::vector<int> RolesSent(const TrafficTable& t, int v) {
  std::vector<int> roles;
  for (int r = 0; r < kMessageRoles; ++r) {
    for (const auto& [key, c] : t.cells) {
      if (std::get<1>(key) == v && c.role_bytes_per_query[static_cast<std::size_t>(r)] > 0) {
        roles.push_back(r);
        break;
      }
    }
  }
  return roles;
}

std::string RolePanel(const fs::path& dir, const TrafficTable& t, int v, std::size_t i, const std::vector<int>& roles,
                      bool key, const std::string& prefix) {
  const std::string& s = t.strategies[i];
  std::string dat;
  double pr = 0, verify = 0, total = 0;
  for (int n : t.robots) {
    const TrafficCell* c = t.Find(s, v, n);
    if (c == nullptr) continue;
    const auto& b = c->role_bytes_per_query;
    pr = b[0] + b[1];
    verify = b[2] + b[3];
    total = 0;
    for (double x : b) total += x;
    dat += std::to_string(n);
    for (int r : roles) dat += " " + FormatDouble(b[static_cast<std::size_t>(r)]);
    dat += " " + FormatDouble(total) + " " + FormatDouble(c->total_bytes_ci95) + "\n";
  }
  const std::string file = prefix + "roles_" + std::to_string(i) + ".dat";
  WriteFileAtomic(dir / file, dat);
  std::ostringstream p;
  p << "set title " << GnuplotQuote(s) << " tc rgb '" << figure_style::StrategyColour(t.StrategyIndex(s)) << "'\n"
    << "set label 1 " << GnuplotQuote("largest n: place recognition " + FormatDouble(100 * pr / total, 0) +
                                "%, verification " + FormatDouble(100 * verify / total, 0) + "%")
    << " at graph 0.02, graph 0.95 left front font ',10'\n";
  p << (key ? "set key at screen 0.5, screen 0.02 center bottom horizontal\n" : "unset key\n") << "plot ";
  for (std::size_t k = 0; k < roles.size(); ++k) {
    const auto r = static_cast<std::size_t>(roles[k]);
    p << (k ? ", \\\n     " : "") << GnuplotQuote(file) << " using " << k + 2 << (k == 0 ? ":xtic(1)" : "")
      << " lc rgb '" << figure_style::kRoleColours[r] << "' "
      << (key ? "title " + GnuplotQuote(kMessageRoleNames[r]) : std::string("notitle"));
  }
  // The total's confidence interval over the stack: the bars of a histogram stand at x = 0, 1, ...
  // (drawn as vectors: yerrorbars also put a point on each bar top in a histogram's fill style).
  p << ", \\\n     " << GnuplotQuote(file) << " using 0:($" << roles.size() + 2 << "-$" << roles.size() + 3 << "):(0):(2*$" << roles.size() + 3
    << ") with vectors heads size 0.1,90 lw 1.2 lc rgb '#000000' " << (key ? "title '95 % CI of the total'" : "notitle");
  return p.str() + "\nunset label 1\n";
}

}  // namespace

std::optional<FigureScript> WriteRoleFigure(const fs::path& dir, const TrafficTable& t, std::string& why,
                                            const VariantFigure& view) {
  const int v = view.variant >= 0 ? view.variant : t.ShownVariant();
  std::vector<std::size_t> shown;
  double ymax = 0;
  for (std::size_t i = 0; i < t.strategies.size(); ++i) {
    bool any = false;
    for (int n : t.robots) {
      if (const TrafficCell* c = t.Find(t.strategies[i], v, n)) {
        any = true;
        double sum = 0;
        for (double b : c->role_bytes_per_query) sum += b;
        ymax = std::max(ymax, sum + c->total_bytes_ci95);
      }
    }
    if (any) shown.push_back(i);
  }
  if (shown.empty()) {
    why = NoSimTraffic(t);
    return std::nullopt;
  }
  const std::vector<int> roles = RolesSent(t, v);
  std::ostringstream s;
  s << "set multiplot layout 1," << shown.size() << " margins 0.07,0.98,0.2,0.84 spacing 0.04 title "
    << GnuplotTitle({"All traffic per query by message role (offered wire bytes of every copy), " +
                         NetworkName(*t.Network(v)),
                     "mean over runs, bars: the total's 95 % confidence interval"}) << " font ',13'\n"
    << "set style data histograms\nset style histogram rowstacked\nset style fill solid 0.9 border rgb '#333333'\n"
    << "set boxwidth 0.75\nset grid ytics\nset xlabel 'robots n'\nset yrange [0:" << FormatDouble(ymax * 1.12) << "]\n";
  for (std::size_t k = 0; k < shown.size(); ++k) {
    s << (k == 0 ? "set ylabel 'wire bytes per query'\n" : "unset ylabel\n") << RolePanel(dir, t, v, shown[k], roles, k == 0, view.data_prefix);
  }
  return FigureScript{s.str() + "unset multiplot\n", static_cast<int>(std::max<std::size_t>(2, shown.size())) * 600, 620};
}

namespace {

// Rows of one run of `csv` (on the simulated network: protocol sim; variant v, n, run 0) for `strategy`, by index.
std::vector<std::size_t> RunRows(const CsvTable& csv, const std::string& strategy, int v, int n) {
  std::vector<std::size_t> out;
  if (csv.header.empty()) return out;
  const std::size_t p = csv.Column("protocol"), s = csv.Column("strategy"), r = csv.Column("robots"),
                    run = csv.Column("run"), net = csv.Column("network_variant");
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    const auto& row = csv.rows[i];
    if (row.size() != csv.header.size()) continue;
    if (RowTraits(row[p]).simulated_network && row[s] == strategy && row[r] == std::to_string(n) && row[run] == "0" &&
        row[net] == std::to_string(v)) {
      out.push_back(i);
    }
  }
  return out;
}

// The strategy shown beside the paper's method in figure 3: the first that is neither it nor
// broadcast (whose every robot searches every query, balanced by construction).
std::string BalancedStrategy(const TrafficTable& t, const CsvTable& per_robot, int v, int n) {
  for (const std::string& s : t.strategies) {
    if (s != "decentralized" && s != "broadcast" && !RunRows(per_robot, s, v, n).empty()) return s;
  }
  return "";
}

// The most searches any robot of `s` served in the shown run.
double MostServed(const CsvTable& per_robot, const std::string& s, int v, int n) {
  double most = 0;
  for (const std::size_t i : RunRows(per_robot, s, v, n)) most = std::max(most, per_robot.Count(i, per_robot.Column("queries_received")));
  return most;
}

// ymax: the top of the y axis, the same for every panel (their bars are compared).
std::string LoadPanel(const fs::path& dir, const TrafficTable& t, const CsvTable& per_robot, const std::string& s,
                      int v, int n, double ymax, const std::string& prefix) {
  const std::size_t robot = per_robot.Column("robot"), served = per_robot.Column("queries_received");
  std::string dat;
  double sum = 0, most = -1;
  std::string busiest;
  // Numbers only, parsed: the robot id is also the label's position in the script.
  for (const std::size_t i : RunRows(per_robot, s, v, n)) {
    const std::string id = std::to_string(per_robot.Integer(i, robot, 0, n - 1));
    const double q = per_robot.Count(i, served);
    dat += id + " " + FormatDouble(q) + "\n";
    sum += q;
    if (q > most) {
      most = q;
      busiest = id;
    }
  }
  const std::string file = prefix + "load_" + std::to_string(t.StrategyIndex(s)) + ".dat";
  WriteFileAtomic(dir / file, dat + "\n\n" + busiest + " " + FormatDouble(most) + "\n");
  const double fair = sum / n;
  std::ostringstream p;
  p << "set title " << GnuplotQuote(s) << " tc rgb '" << figure_style::StrategyColour(t.StrategyIndex(s)) << "'\n"
    << "set yrange [0:" << FormatDouble(ymax) << "]\nset label 1 "
    << GnuplotQuote("busiest: robot " + busiest + ", " + FormatDouble(most / fair, 1) + " x fair share") << " at "
    << busiest << ", " << FormatDouble(most) << " center offset 0,1 front\n"
    << "plot " << GnuplotQuote(file) << " index 0 using 1:2 with boxes " << Colour(t, s)
    << " fs solid 0.45 title 'searches served', '' index 1 using 1:2 with boxes " << Colour(t, s)
    << " fs solid 1.0 border lc rgb '#000000' title 'busiest robot', " << FormatDouble(fair)
    << " with lines dt 2 lw 2 lc rgb '#000000' title " << GnuplotQuote("fair share (all searches / n = " +
                                                                 FormatDouble(fair, 0) + ")")
    << "\nunset label 1\n";
  return p.str();
}

}  // namespace

std::optional<FigureScript> WriteRobotLoadFigure(const fs::path& dir, const TrafficTable& t, const CsvTable& per_robot,
                                                 std::string& why, const VariantFigure& view) {
  const int v = view.variant >= 0 ? view.variant : t.ShownVariant();
  const int n = t.robots.empty() ? 0 : t.robots.back();
  if (v < 0) {
    why = NoSimTraffic(t);
    return std::nullopt;
  }
  if (RunRows(per_robot, "decentralized", v, n).empty()) {
    why = per_robot.header.empty() ? "needs per_robot.csv"
                                   : "per_robot.csv has no row of strategy decentralized at n = " + std::to_string(n) +
                                         ", run 0";
    return std::nullopt;
  }
  std::vector<std::string> shown = {"decentralized"};
  if (const std::string b = BalancedStrategy(t, per_robot, v, n); !b.empty()) shown.push_back(b);
  std::ostringstream s;
  s << "set multiplot layout 1," << shown.size() << " margins 0.07,0.98,0.2,0.86 spacing 0.06 title "
    << GnuplotQuote("Searches served per robot, one run (n = " + std::to_string(n) + ", run 0, " +
             NetworkName(*t.Network(v)) + ")") << " font ',13'\n"
    << "set style fill solid 0.5\nset boxwidth 0.8\nset grid ytics\nset xlabel 'robot'\nset ylabel 'searches served'\n"
    << "set xrange [-0.7:" << n - 0.3 << "]\nset xtics 1\nset key below horizontal\n";
  // One y scale for all panels: a balanced strategy's bars are as short as they are.
  double most = 0;
  for (const std::string& st : shown) most = std::max(most, MostServed(per_robot, st, v, n));
  for (const std::string& st : shown) s << LoadPanel(dir, t, per_robot, st, v, n, std::max(most, 1.0) * 1.18, view.data_prefix);
  return FigureScript{s.str() + "unset multiplot\n", shown.size() == 1 ? 900 : 1500, 600};
}

namespace {

// The n x n matrix of kB that `strategy` offered per directed pair, as gnuplot's `matrix` rows.
double WriteMatrix(const fs::path& file, const CsvTable& links, const std::string& strategy, int v, int n) {
  std::vector<double> kb(static_cast<std::size_t>(n * n), 0.0);
  const std::size_t src = links.Column("src"), dst = links.Column("dst"), wire = links.Column("wire_bytes");
  for (const std::size_t i : RunRows(links, strategy, v, n)) {
    const int from = links.Integer(i, src, 0, n - 1), to = links.Integer(i, dst, 0, n - 1);
    kb[static_cast<std::size_t>(from * n + to)] = links.Count(i, wire) / 1e3;
  }
  std::string dat;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) dat += (c ? " " : "") + FormatDouble(kb[static_cast<std::size_t>(r * n + c)]);
    dat += "\n";
  }
  WriteFileAtomic(file, dat);
  return *std::max_element(kb.begin(), kb.end());
}

}  // namespace

std::optional<FigureScript> WriteMatrixFigure(const fs::path& dir, const TrafficTable& t, const CsvTable& links,
                                              std::string& why, const VariantFigure& view) {
  const int v = view.variant >= 0 ? view.variant : t.ShownVariant();
  const int n = t.robots.empty() ? 0 : t.robots.back();
  std::vector<std::string> shown;
  for (const char* s : {"decentralized", "broadcast"}) {
    if (v >= 0 && !RunRows(links, s, v, n).empty()) shown.emplace_back(s);
  }
  if (shown.empty()) {
    why = v < 0                  ? NoSimTraffic(t)
          : links.header.empty() ? std::string("needs links.csv")
                                 : "links.csv has no row of strategy decentralized or broadcast at n = " +
                                       std::to_string(n) + ", run 0";
    return std::nullopt;
  }
  double top = 0;
  for (std::size_t i = 0; i < shown.size(); ++i) {
    top = std::max(top, WriteMatrix(dir / (view.data_prefix + "matrix_" + std::to_string(i) + ".dat"), links, shown[i], v, n));
  }
  std::ostringstream s;
  s << "set multiplot layout 1," << shown.size() << " title "
    << GnuplotQuote("Wire kB sent, sender x receiver (colour bar in kB), one run (n = " + std::to_string(n) + ", run 0, " +
             NetworkName(*t.Network(v)) + ")") << " font ',13'\n"
    << "set size ratio -1\nunset grid\nunset key\nset xlabel 'receiver'\nset ylabel 'sender'\n"
    << "set xrange [-0.5:" << n - 0.5 << "]\nset yrange [" << n - 0.5 << ":-0.5]\nset cbrange [0:" << FormatDouble(top)
    << "]\nset palette defined (0 '#ffffff', 1 '#c6dbef', 2 '#6baed6', 3 '#2171b5', 4 '#08306b')\n"
    << "set tics out\nset xtics " << std::max(1, n / 10) << "\nset ytics " << std::max(1, n / 10) << "\n";
  for (std::size_t i = 0; i < shown.size(); ++i) {
    // One colour bar, beside the last panel: both panels share its range.
    s << (i + 1 == shown.size() ? "set colorbox\nset cblabel 'kB sent'\n" : "unset colorbox\n") << "set title "
      << GnuplotQuote(shown[i]) << " tc rgb '" << figure_style::StrategyColour(t.StrategyIndex(shown[i]))
      << "'\nplot " << GnuplotQuote(view.data_prefix + "matrix_" + std::to_string(i) + ".dat") << " matrix with image notitle\n";
  }
  return FigureScript{s.str() + "unset multiplot\n", shown.size() == 1 ? 800 : 1400, 650};
}

namespace {

std::vector<std::size_t> SharedMediumVariants(const TrafficTable& t) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < t.networks.size(); ++i) {
    if (t.networks[i].model == "shared_medium") out.push_back(i);
  }
  return out;
}

std::string OfferedPanel(const fs::path& dir, const TrafficTable& t, const std::vector<std::size_t>& shared) {
  std::string dat;
  std::ostringstream plot;
  int block = 0;
  double lowest = std::numeric_limits<double>::infinity(), highest = 0;  // offered Mbit/s
  for (const std::string& s : t.strategies) {
    for (std::size_t i : shared) {
      std::vector<std::vector<double>> p;
      for (int n : t.robots) {
        if (const TrafficCell* c = t.Find(s, t.networks[i].variant, n)) {
          p.push_back({c->offered_mbps, c->delivered_mbps, c->offered_ci95, c->delivered_ci95});
          if (c->offered_mbps > 0) {
            lowest = std::min(lowest, c->offered_mbps);
            highest = std::max(highest, c->offered_mbps);
          }
        }
      }
      if (p.empty()) continue;
      const std::string title = s + ", " + NetworkName(t.networks[i]);
      dat += Block(title, p);
      plot << (block ? ", \\\n     " : "plot ") << "'offered.dat' index " << block << " using 1:2:3:4 with xyerrorlines lw 2 "
           << Colour(t, s)
           << " dt " << NetworkDash(i) << " pt " << NetworkPoint(i) << " title " << GnuplotQuote(title);
      ++block;
    }
  }
  // The reference last, over the data and across the whole axis: where a line leaves it, the
  // medium saturates.
  plot << (block ? ", \\\n     " : "plot ") << "x with lines lw 1.5 dt 2 lc rgb '#000000' title 'delivered = offered'";
  WriteFileAtomic(dir / "offered.dat", dat);
  // Whole decades around the data: the reference line, a function, spans the whole axis.
  const std::string range = highest > 0 ? "set xrange [" + FormatDouble(std::pow(10.0, std::floor(std::log10(lowest)))) + ":" +
                                              FormatDouble(std::pow(10.0, std::ceil(std::log10(highest)))) + "]\n"
                                        : std::string();
  return range + "set title " + GnuplotTitle({"Offered vs delivered load (points: n = " + std::to_string(t.robots.front()) +
                                       " .. " + std::to_string(t.robots.back()) + ")",
                                       "mean over runs, bars: its 95 % confidence interval"}) +
         "\nset xlabel 'offered load, every copy sent [Mbit/s]'\n"
         "set ylabel 'delivered load [Mbit/s]'\nset logscale xy\nset key top left\n" +  // delivered <= offered: empty
         plot.str() + "\n";
}

std::string LatencyPanel(const fs::path& dir, const TrafficTable& t, const std::vector<std::size_t>& shared) {
  const int n = t.robots.back();
  std::string dat, saturated;
  std::ostringstream plot;
  plot << "plot ";
  int block = 0;
  for (const std::string& s : t.strategies) {
    std::vector<std::vector<double>> p;
    for (std::size_t i : shared) {
      const TrafficCell* c = t.Find(s, t.networks[i].variant, n);
      if (c == nullptr) continue;
      const double mbps = t.networks[i].bandwidth_bps / 1e6;
      p.push_back({mbps, c->latency_ms, c->latency_ci95});
      const double fraction = c->delivered_mbps / c->offered_mbps;
      if (fraction < 0.99) {
        saturated += FormatDouble(mbps) + " " + FormatDouble(c->latency_ms) + " \"" + FormatDouble(100 * fraction, 0) +
                     "% delivered\"\n";
      }
    }
    if (p.empty()) continue;
    dat += Block(s, p);
    plot << (block ? ", \\\n     " : "") << "'latency.dat' index " << block << " using 1:2:3 with yerrorlines lw 2 pt 7 "
         << Colour(t, s) << " title " << GnuplotQuote(s);
    ++block;
  }
  WriteFileAtomic(dir / "latency.dat", dat);
  WriteFileAtomic(dir / "saturated.dat", saturated.empty() ? "# none\n" : saturated);
  if (!saturated.empty()) {
    plot << ", \\\n     'saturated.dat' using 1:2 with points pt 6 ps 3 lw 2 lc rgb '#000000' title "
            "'saturated: under 99% of copies delivered', '' using 1:2:3 with labels left offset 1.5,0.6 font ',9' notitle";
  }
  return "set title " + GnuplotTitle({"Mean query latency vs bandwidth at n = " + std::to_string(n),
                                       "mean over runs, bars: its 95 % confidence interval"}) +
         "\nset xlabel 'bandwidth of the shared medium [Mbit/s]'\nset ylabel 'mean query latency [ms]'\n"
         "set autoscale x\nset logscale xy\nset key bottom left\n" + plot.str() + "\n";  // latency falls with bandwidth
}

}  // namespace

std::optional<FigureScript> WriteSaturationFigure(const fs::path& dir, const TrafficTable& t, std::string& why) {
  const std::vector<std::size_t> shared = SharedMediumVariants(t);
  if (shared.empty()) {
    why = "needs protocol sim on a shared_medium network";
    return std::nullopt;
  }
  const std::string body = "set multiplot layout 1,2 spacing 0.1 title 'Shared medium: where saturation begins' "
                           "font ',13'\nset grid\n" + OfferedPanel(dir, t, shared) + LatencyPanel(dir, t, shared) +
                           "unset multiplot\n";
  return FigureScript{body, 1500, 680};
}

}  // namespace dvpr
