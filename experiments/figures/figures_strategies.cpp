// Figures 7 and 8 (see figures.h): every routing strategy side by side (issue 8). The data
// (aggregation over runs, the n compared, where the scatter labels go) and the gnuplot scripts
// live together because the scripts' panel geometry decides where a label fits.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "experiments/figures/figure_style.h"
#include "experiments/figures/figures.h"
#include "experiments/figures/gnuplot_text.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/results/result_writers.h"

namespace dvpr {

namespace {

namespace fs = std::filesystem;

// Figure 7's canvas and its two scatter panels (screen fractions), shared by the label placement
// and the script. Label sizes are DejaVu Sans 10 at pngcairo's 72 dpi, measured on its output.
constexpr int kTradeoffWidth = 1600;
constexpr int kTradeoffHeight = 1400;
constexpr double kScatterLeft[2] = {0.07, 0.57};
constexpr double kScatterWidth = 0.41;
constexpr double kScatterBottom = 0.05;
constexpr double kScatterTop = 0.43;
constexpr double kCharWidth = 7.3;    // px, average of a strategy name
constexpr double kCharHeight = 14.0;  // px
constexpr double kTargetBalance = 1.5;
constexpr double kTargetAuc = 0.95;

const auto& kColours = figure_style::kStrategyColours;  // the colours of every figure

void Accumulate(RunSpread& s, double v) {
  if (std::isnan(v)) return;
  if (s.runs == 0) {
    s.mean = 0;
    s.min = v;
    s.max = v;
  }
  ++s.runs;
  s.mean += v;  // a sum until Finish
  s.min = std::min(s.min, v);
  s.max = std::max(s.max, v);
}

void Finish(RunSpread& s) {
  if (s.runs > 0) s.mean /= s.runs;
}

// The static evaluation's rows (exact accuracy), else the simulation's.
std::string ChooseAccuracyProtocol(const std::vector<RunResult>& rows) {
  for (bool ProtocolTraits::*trait : {&ProtocolTraits::static_evaluation, &ProtocolTraits::simulated_network}) {
    for (const auto& r : rows) {
      if (RowTraits(r.key.protocol).*trait && !std::isnan(r.relative_auc)) return r.key.protocol;
    }
  }
  return "";
}

std::string Num(double v) {
  return std::isnan(v) ? std::string("NaN") : FormatDouble(v);
}

// Smallest value of `nice` (ascending) that is >= v, else v.
double NiceCeil(double v, std::initializer_list<double> nice) {
  for (double x : nice) {
    if (x >= v) return x;
  }
  return v;
}

// Every value of one metric at the given n (for axis ranges).
template <typename Get>
std::vector<double> Values(const StrategyTable& t, const std::vector<int>& ns, Get get) {
  std::vector<double> out;
  for (const auto& s : t.stats) {
    if (std::find(ns.begin(), ns.end(), s.robots) == ns.end()) continue;
    const RunSpread& sp = get(s);
    if (sp.runs > 0) out.insert(out.end(), {sp.min, sp.max});
  }
  return out;
}

int MaxRuns(const StrategyTable& t) {
  int runs = 0;
  for (const auto& s : t.stats) {
    runs = std::max({runs, s.relative_auc.runs, s.worst_balance.runs, s.bytes_per_query.runs});
  }
  return runs;
}

// " i j ...": the strategies (row numbers) without the metric at any of the n.
template <typename Get>
std::string MissingRows(const StrategyTable& t, const std::vector<int>& ns, Get get) {
  std::string out;
  for (std::size_t i = 0; i < t.strategies.size(); ++i) {
    const bool none = std::none_of(ns.begin(), ns.end(), [&](int n) {
      const StrategyStats* s = t.Find(t.strategies[i], n);
      return s != nullptr && get(*s).runs > 0;
    });
    if (none) out += " " + std::to_string(i);
  }
  return out;
}

// Axis ranges of figure 7, the same for both n so the panels compare.
struct TradeoffAxes {
  double auc_lo = 0.5;
  double balance_hi = 10;
  double kb_hi = 40;
};

TradeoffAxes ChooseAxes(const StrategyTable& t, const std::vector<int>& ns) {
  TradeoffAxes a;
  const auto auc = Values(t, ns, [](const StrategyStats& s) -> const RunSpread& { return s.relative_auc; });
  const auto bal = Values(t, ns, [](const StrategyStats& s) -> const RunSpread& { return s.worst_balance; });
  const auto kb = Values(t, ns, [](const StrategyStats& s) -> const RunSpread& { return s.bytes_per_query; });
  if (!auc.empty()) {
    a.auc_lo = std::max(0.0, std::min(0.9, std::floor((*std::min_element(auc.begin(), auc.end()) - 0.02) * 20) / 20));
  }
  if (!bal.empty()) {
    a.balance_hi = NiceCeil(*std::max_element(bal.begin(), bal.end()) * 1.15, {2, 3, 5, 10, 20, 30, 50, 100});
  }
  if (!kb.empty()) a.kb_hi = std::ceil(*std::max_element(kb.begin(), kb.end()) / 1000 * 1.08 / 5) * 5;
  return a;
}

// --- Label placement for the scatter panels -----------------------------------------------

struct Box {
  double x0, y0, x1, y1;
  double Overlap(const Box& o) const {
    const double w = std::min(x1, o.x1) - std::max(x0, o.x0);
    const double h = std::min(y1, o.y1) - std::max(y0, o.y0);
    return w > 0 && h > 0 ? w * h : 0;
  }
};

struct ScatterPoint {
  double x = 0, y = 0;    // data coordinates
  double px = 0, py = 0;  // pixels inside the plot area
  std::string text;
};

struct Candidate {
  double dx, dy;
  int align;  // -1 right-aligned (label left of the point), 0 centred, 1 left-aligned
};

// Right, left, above, below, the diagonals; then further out, up or down, with a leader line.
std::vector<Candidate> Candidates() {
  const double r = 8, v = kCharHeight;
  std::vector<Candidate> c = {{r, 0, 1},          {-r, 0, -1},          {0, v, 0},
                              {0, -v, 0},         {r, 0.8 * v, 1},      {r, -0.8 * v, 1},
                              {-r, 0.8 * v, -1},  {-r, -0.8 * v, -1}};
  for (int k = 1; k <= 8; ++k) {
    for (int sign : {1, -1}) {
      c.push_back({3 * r, sign * (0.8 + k) * v, 1});
      c.push_back({-3 * r, sign * (0.8 + k) * v, -1});
    }
  }
  return c;
}

Box LabelBox(const ScatterPoint& p, const Candidate& c) {
  const double w = static_cast<double>(p.text.size()) * kCharWidth;
  const double x = p.px + c.dx, y = p.py + c.dy;
  const double x0 = c.align == 1 ? x : c.align == -1 ? x - w : x - w / 2;
  return {x0, y - kCharHeight / 2, x0 + w, y + kCharHeight / 2};
}

struct PlacedLabel {
  ScatterPoint point;
  Candidate where;
};

// Greedy: each point takes the first candidate inside the panel that overlaps no label placed
// so far and no other point; if none is free, the one with the least overlap.
std::vector<PlacedLabel> PlaceLabels(const std::vector<ScatterPoint>& points, double pw,
                                     double ph) {
  std::vector<Box> taken;
  std::vector<PlacedLabel> placed;
  const std::vector<Candidate> candidates = Candidates();
  for (const auto& p : points) {
    double best_cost = 1e300;
    Candidate best = candidates[0];
    for (const auto& c : candidates) {
      const Box b = LabelBox(p, c);
      double cost = (b.x0 < 0 || b.x1 > pw || b.y0 < 0 || b.y1 > ph) ? 1e9 : 0;
      for (const auto& t : taken) cost += t.Overlap(b);
      for (const auto& q : points) {
        if (&q != &p) cost += Box{q.px - 7, q.py - 7, q.px + 7, q.py + 7}.Overlap(b) * 4;
      }
      if (cost < best_cost) {
        best_cost = cost;
        best = c;
      }
      if (cost == 0) break;
    }
    taken.push_back(LabelBox(p, best));
    placed.push_back({p, best});
  }
  return placed;
}

// Strategies at one n as scatter points (balance, relative AUC) in pixels of a scatter panel;
// points closer than 4 px share one label.
std::vector<ScatterPoint> ScatterPoints(const StrategyTable& t, int n, const TradeoffAxes& a,
                                        double pw, double ph) {
  std::vector<ScatterPoint> out;
  for (const auto& name : t.strategies) {
    const StrategyStats* s = t.Find(name, n);
    if (s == nullptr || s->worst_balance.runs == 0 || s->relative_auc.runs == 0) continue;
    ScatterPoint p{s->worst_balance.mean, s->relative_auc.mean, 0, 0, name};
    p.px = pw * std::log(p.x / 0.9) / std::log(a.balance_hi / 0.9);
    p.py = ph * (p.y - a.auc_lo) / (1.02 - a.auc_lo);
    auto near = std::find_if(out.begin(), out.end(), [&](const ScatterPoint& q) {
      return std::hypot(q.px - p.px, q.py - p.py) < 4;
    });
    if (near != out.end()) {
      near->text += ", " + name;
    } else {
      out.push_back(p);
    }
  }
  return out;
}

// One line per label: graph-x graph-y align leader x y text.
std::string LabelLines(const StrategyTable& t, int n, const TradeoffAxes& a) {
  const double pw = kScatterWidth * kTradeoffWidth;
  const double ph = (kScatterTop - kScatterBottom) * kTradeoffHeight;
  std::ostringstream out;
  for (const auto& l : PlaceLabels(ScatterPoints(t, n, a, pw, ph), pw, ph)) {
    const bool leader = std::abs(l.where.dy) > 1.5 * kCharHeight;
    out << FormatDouble((l.point.px + l.where.dx) / pw, 4) << ' '
        << FormatDouble((l.point.py + l.where.dy) / ph, 4) << ' '
        << (l.where.align == 1 ? "left" : l.where.align == -1 ? "right" : "center") << ' '
        << (leader ? 1 : 0) << ' ' << Num(l.point.x) << ' ' << Num(l.point.y) << ' '
        << OneLineText(l.point.text) << '\n';
  }
  return out.str();
}

// --- Reading the data back in the scripts -------------------------------------------------

std::vector<std::string> Lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// "key value..." lines.
std::map<std::string, std::string> ReadMeta(const fs::path& path) {
  std::map<std::string, std::string> meta;
  for (const auto& line : Lines(path)) {
    const auto space = line.find(' ');
    meta[line.substr(0, space)] = space == std::string::npos ? "" : line.substr(space + 1);
  }
  return meta;
}

// Names from runs.csv reach the scripts only single-quoted (gnuplot_text.h).

std::string Margins(double l, double r, double b, double t) {
  std::ostringstream s;
  s << "set lmargin at screen " << l << "; set rmargin at screen " << r
    << "\nset bmargin at screen " << b << "; set tmargin at screen " << t << "\n";
  return s.str();
}

std::string Terminal(const fs::path& png, int width, int height) {
  return "set terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
         " font 'DejaVu Sans,11' noenhanced\nset encoding utf8\n"
         "set output (exists('dvpr_output') ? dvpr_output : " +  // as Preamble (figures.cpp)
         GnuplotQuote("../" + png.filename().string()) + ")\nset datafile missing 'NaN'\nset border lw 1\n";
}

std::string RunsText(const std::string& runs) {
  return runs == "1" ? "1 run" : "mean of " + runs + " runs, bars min–max";
}

}  // namespace

const StrategyStats* StrategyTable::Find(const std::string& strategy, int n) const {
  for (const auto& s : stats) {
    if (s.strategy == strategy && s.robots == n) return &s;
  }
  return nullptr;
}

StrategyTable TabulateStrategies(const std::vector<RunResult>& rows) {
  StrategyTable t;
  t.accuracy_protocol = ChooseAccuracyProtocol(rows);
  for (const auto& r : rows) {
    if (RowTraits(r.key.protocol).simulated_network && !std::isnan(r.bytes_per_query) &&
        (t.bytes_variant < 0 || r.key.network.variant < t.bytes_variant)) {
      t.bytes_variant = r.key.network.variant;
      t.bytes_network = NetworkText(r.key.network);
    }
  }
  const int first_sim_variant = t.bytes_variant < 0 ? 0 : t.bytes_variant;
  std::map<std::pair<std::size_t, int>, StrategyStats> acc;
  std::set<int> robots;
  for (const auto& r : rows) {
    auto it = std::find(t.strategies.begin(), t.strategies.end(), r.key.strategy);
    if (it == t.strategies.end()) it = t.strategies.insert(it, r.key.strategy);
    robots.insert(r.key.robots);
    StrategyStats& s = acc[{static_cast<std::size_t>(it - t.strategies.begin()), r.key.robots}];
    s.strategy = r.key.strategy;
    s.robots = r.key.robots;
    if (r.key.protocol == t.accuracy_protocol &&
        (!RowTraits(r.key.protocol).simulated_network || r.key.network.variant == first_sim_variant)) {
      Accumulate(s.relative_auc, r.relative_auc);
      Accumulate(s.worst_balance, r.worst_balance_ratio);
    }
    if (RowTraits(r.key.protocol).simulated_network && r.key.network.variant == t.bytes_variant) {
      Accumulate(s.bytes_per_query, r.bytes_per_query);
    }
  }
  for (auto& [key, s] : acc) {
    Finish(s.relative_auc);
    Finish(s.worst_balance);
    Finish(s.bytes_per_query);
    t.stats.push_back(s);
  }
  t.robots.assign(robots.begin(), robots.end());
  return t;
}

std::vector<int> ComparedRobots(const std::vector<int>& robots) {
  const bool both = std::find(robots.begin(), robots.end(), 10) != robots.end() &&
                    std::find(robots.begin(), robots.end(), 20) != robots.end();
  if (both) return {10, 20};
  std::vector<int> sorted = robots;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  if (sorted.size() > 2) sorted.erase(sorted.begin(), sorted.end() - 2);
  return sorted;
}

bool WriteStrategyTradeoffData(const fs::path& data_dir, const std::vector<RunResult>& rows) {
  const StrategyTable t = TabulateStrategies(rows);
  if (t.accuracy_protocol.empty()) return false;
  const std::vector<int> ns = ComparedRobots(t.robots);
  const TradeoffAxes axes = ChooseAxes(t, ns);
  // Row i: i, then per compared n: relative AUC, worst balance, kB per query (mean min max each).
  std::ostringstream dat, names, meta;
  for (std::size_t i = 0; i < t.strategies.size(); ++i) {
    dat << i;
    for (int n : ns) {
      const StrategyStats* found = t.Find(t.strategies[i], n);
      const StrategyStats s = found ? *found : StrategyStats{};
      for (const RunSpread& sp : {s.relative_auc, s.worst_balance}) {
        dat << ' ' << Num(sp.mean) << ' ' << Num(sp.min) << ' ' << Num(sp.max);
      }
      const RunSpread& b = s.bytes_per_query;
      dat << ' ' << Num(b.mean / 1000) << ' ' << Num(b.min / 1000) << ' ' << Num(b.max / 1000);
    }
    dat << '\n';
    names << OneLineText(t.strategies[i]) << '\n';
  }
  meta << "robots";
  for (int n : ns) meta << ' ' << n;
  meta << "\nmissing_0" << MissingRows(t, ns, [](const StrategyStats& s) { return s.relative_auc; })
       << "\nmissing_3" << MissingRows(t, ns, [](const StrategyStats& s) { return s.worst_balance; })
       << "\nmissing_6" << MissingRows(t, ns, [](const StrategyStats& s) { return s.bytes_per_query; })
       << "\nprotocol " << t.accuracy_protocol << "\nnetwork " << OneLineText(t.bytes_network)
       << "\nruns " << MaxRuns(t) << "\nauc_lo " << FormatDouble(axes.auc_lo, 2)
       << "\nbalance_hi " << FormatDouble(axes.balance_hi, 0) << "\nkb_hi "
       << FormatDouble(axes.kb_hi, 0) << "\n";
  WriteFileAtomic(data_dir / "strategy_tradeoff.dat", dat.str());
  WriteFileAtomic(data_dir / "strategy_tradeoff.names", names.str());
  WriteFileAtomic(data_dir / "strategy_tradeoff.meta", meta.str());
  for (std::size_t k = 0; k < ns.size(); ++k) {
    WriteFileAtomic(data_dir / ("strategy_tradeoff_labels_" + std::to_string(k) + ".txt"),
                    LabelLines(t, ns[k], axes));
  }
  return true;
}

namespace {

// Groups of strategies whose worst balance is the same at every n (their lines coincide in
// figure 8), one "a = b = c" per group; e.g. routings that only add stores keep their table's.
std::vector<std::string> CoincidingBalance(const StrategyTable& t) {
  auto series = [&](const std::string& name) {
    std::vector<double> v;
    for (int n : t.robots) {
      const StrategyStats* s = t.Find(name, n);
      v.push_back(s ? s->worst_balance.mean : kNotApplicable);
    }
    return v;
  };
  auto same = [](const std::vector<double>& a, const std::vector<double>& b) {
    bool any = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (std::isnan(a[i]) != std::isnan(b[i])) return false;
      if (!std::isnan(a[i]) && std::abs(a[i] - b[i]) > 1e-9 * std::abs(a[i])) return false;
      any = any || !std::isnan(a[i]);
    }
    return any;
  };
  std::vector<std::string> groups;
  std::vector<bool> used(t.strategies.size(), false);
  for (std::size_t i = 0; i < t.strategies.size(); ++i) {
    std::string group = t.strategies[i];
    for (std::size_t j = i + 1; j < t.strategies.size(); ++j) {
      if (used[i] || used[j] || !same(series(t.strategies[i]), series(t.strategies[j]))) continue;
      used[j] = true;
      group += " = " + t.strategies[j];
    }
    if (group != t.strategies[i]) groups.push_back(group);
  }
  return groups;
}

}  // namespace

bool WriteStrategySweepData(const fs::path& data_dir, const std::vector<RunResult>& rows) {
  const StrategyTable t = TabulateStrategies(rows);
  if (t.accuracy_protocol.empty() || t.robots.size() < 2) return false;
  // One gnuplot index block per strategy: n mean (a lone NaN line when it has no value).
  auto blocks = [&](auto get, double scale) {
    std::ostringstream dat;
    for (std::size_t i = 0; i < t.strategies.size(); ++i) {
      dat << (i ? "\n\n" : "") << "# " << t.strategies[i] << '\n';
      int written = 0;
      for (int n : t.robots) {
        const StrategyStats* s = t.Find(t.strategies[i], n);
        if (s == nullptr || get(*s).runs == 0) continue;
        dat << n << ' ' << Num(get(*s).mean / scale) << '\n';
        ++written;
      }
      if (written == 0) dat << "NaN NaN\n";
    }
    return dat.str();
  };
  WriteFileAtomic(data_dir / "strategy_sweep_auc.dat",
                  blocks([](const StrategyStats& s) { return s.relative_auc; }, 1));
  WriteFileAtomic(data_dir / "strategy_sweep_balance.dat",
                  blocks([](const StrategyStats& s) { return s.worst_balance; }, 1));
  const bool bytes = t.bytes_variant >= 0;
  if (bytes) {
    WriteFileAtomic(data_dir / "strategy_sweep_bytes.dat",
                    blocks([](const StrategyStats& s) { return s.bytes_per_query; }, 1000));
  }
  std::ostringstream names, meta;
  for (const auto& s : t.strategies) names << OneLineText(s) << '\n';
  meta << "robots";
  for (int n : t.robots) meta << ' ' << n;
  meta << "\nprotocol " << t.accuracy_protocol << "\nnetwork " << (bytes ? OneLineText(t.bytes_network) : "")
       << "\nruns " << MaxRuns(t) << "\nbalance_hi "
       << FormatDouble(ChooseAxes(t, t.robots).balance_hi, 0) << "\n";
  for (const auto& g : CoincidingBalance(t)) meta << "same_balance " << OneLineText(g) << '\n';
  WriteFileAtomic(data_dir / "strategy_sweep.titles", names.str());
  WriteFileAtomic(data_dir / "strategy_sweep.meta", meta.str());
  return true;
}

namespace {

std::vector<int> ParseInts(const std::string& s) {
  std::istringstream in(s);
  std::vector<int> out;
  for (int v; in >> v;) out.push_back(v);
  return out;
}

std::string ReferenceLine(char axis, double v) {
  std::ostringstream s;
  s << "set arrow from " << (axis == 'x' ? "first " + Num(v) + ", graph 0 to first " + Num(v) + ", graph 1"
                                         : "graph 0, first " + Num(v) + " to graph 1, first " + Num(v))
    << " nohead dt 2 lw 1.5 lc rgb '#c0392b' front\n";
  return s.str();
}

// Log-axis tics of a balance ratio up to hi.
std::string BalanceTics(char axis, double hi) {
  std::string tics = "set " + std::string(1, axis) + "tics (";
  bool first = true;
  for (double v : {1.0, 1.5, 2.0, 3.0, 5.0, 10.0, 20.0, 30.0, 50.0, 100.0}) {
    if (v > hi) break;
    tics += (first ? "" : ", ") + FormatDouble(v, v == 1.5 ? 1 : 0);
    first = false;
  }
  return tics + ")\n";
}

// One dot-plot panel of figure 7: strategies on y (top to bottom), one metric on x, a point per
// compared n with its min-max bar.
struct DotPanel {
  double left, right;
  int column;  // 0 relative AUC, 3 worst balance, 6 kB per query
  std::string title, xlabel, setup;
};

std::string DotPanelScript(const DotPanel& p, const std::vector<int>& ns, bool first,
                           const std::string& missing) {
  constexpr const char* kStyle[2] = {"pt 7 ps 1.3 lc rgb '#1f77b4'", "pt 5 ps 1.2 lc rgb '#d95f02'"};
  std::ostringstream s, not_measured;
  for (int row : ParseInts(missing)) {
    not_measured << "set label 'not measured' at graph 0.02, first " << row
                 << " left tc rgb '#888888' font ',9'\n";
  }
  s << Margins(p.left, p.right, 0.53, 0.915) << "set title " << GnuplotQuote(p.title)
    << "\nset xlabel " << GnuplotQuote(p.xlabel) << "\nunset logscale x\nset xtics auto\n"
    << "set format x '%g'\nunset arrow\nunset label\n" << p.setup << not_measured.str()
    << (first ? "set key at screen 0.015, 0.945 left top vertical box opaque samplen 1 font ',11'\n"
              : "unset key\nset ytics 1 scale 0\nset format y ''\n")
    << "plot ";
  for (std::size_t k = 0; k < ns.size(); ++k) {
    const int mean = 2 + 9 * static_cast<int>(k) + p.column;
    const std::string y = ns.size() == 1 ? "1" : (k == 0 ? "($1-0.17)" : "($1+0.17)");
    s << (k ? ", \\\n     " : "") << "'strategy_tradeoff.dat' using " << mean << ':' << y << ':'
      << mean + 1 << ':' << mean + 2 << " with xerrorbars lw 1.5 " << kStyle[k] << " title "
      << GnuplotQuote("n = " + std::to_string(ns[k]));
  }
  return s.str() + "\n";
}

std::string TradeoffDotPanels(const std::map<std::string, std::string>& meta,
                              const std::vector<std::string>& names, const std::vector<int>& ns) {
  std::ostringstream s;
  s << "set yrange [" << names.size() << "-0.5:-0.5]\nset ytics scale 0 font ',11' (";
  for (std::size_t i = 0; i < names.size(); ++i) s << (i ? ", " : "") << GnuplotQuote(names[i]) << ' ' << i;
  s << ")\nset grid xtics lc rgb '#dddddd'\n";
  for (std::size_t i = 0; i < names.size(); i += 2) {
    s << "set object rect from graph 0, first " << i << "-0.5 to graph 1, first " << i
      << "+0.5 fc rgb '#f2f2f2' fs solid noborder behind\n";
  }
  const std::string protocol = meta.at("protocol");
  const std::string network = meta.at("network");
  const double balance_hi = std::stod(meta.at("balance_hi"));
  auto target_at = [&](double v) {
    return ReferenceLine('x', v) + "set label 'target' at first " + Num(v) +
           ", graph 1 offset 0.4,-0.9 tc rgb '#c0392b' font ',9'\n";
  };
  s << DotPanelScript({0.19, 0.43, 0, "Relative AUC (higher is better)",
                       "AUC / AUC(" + std::string(RowTraits(protocol).relative_auc_reference) + ")",
                       "set xrange [" + meta.at("auc_lo") + ":1.02]\n" + target_at(kTargetAuc)},
                      ns, true, meta.at("missing_0"));
  s << DotPanelScript({0.47, 0.71, 3, "Worst balance ratio (lower is better)",
                       "busiest robot's load / fair share (log scale)",
                       "set logscale x\nset xrange [0.9:" + meta.at("balance_hi") + "]\n" +
                           BalanceTics('x', balance_hi) + target_at(kTargetBalance)},
                      ns, false, meta.at("missing_3"));
  if (network.empty()) {
    s << Margins(0.75, 0.985, 0.53, 0.915) << "set title 'Bytes per query'\nunset logscale x\n"
      << "set xrange [0:1]\nunset arrow\nunset label\nset format x ''\nset label "
         "'no simulation rows (protocol sim)' at graph 0.5, graph 0.5 center\nplot NaN notitle\n";
  } else {
    s << DotPanelScript({0.75, 0.985, 6, "Bytes per query (simulation, " + network + ")",
                         "wire kB per query (query, replies, verification)",
                         "set xrange [0:" + meta.at("kb_hi") + "]\n"},
                        ns, false, meta.at("missing_6"));
  }
  return s.str();
}

std::string TradeoffScatter(const fs::path& data_dir, const std::map<std::string, std::string>& meta,
                            const std::vector<int>& ns, std::size_t k) {
  constexpr const char* kStyle[2] = {"pt 7 ps 1.5 lc rgb '#1f77b4'", "pt 5 ps 1.4 lc rgb '#d95f02'"};
  const double left = kScatterLeft[k];
  const int mean = 2 + 9 * static_cast<int>(k);
  std::ostringstream s;
  s << "unset object\nunset arrow\nunset label\nunset key\nset grid xtics ytics lc rgb '#dddddd'\n"
    << Margins(left, left + kScatterWidth, kScatterBottom, kScatterTop)
    << "set title \"n = " << ns[k] << ": relative AUC vs worst balance, one point per strategy\\n"
    << "green: the issue-8 target (balance ≤ 1.5, relative AUC ≥ 0.95)\"\n"
    << "set xlabel 'worst balance ratio (log scale)'\nset ylabel 'relative AUC'\n"
    << "set logscale x\nset xrange [0.9:" << meta.at("balance_hi") << "]\n"
    << BalanceTics('x', std::stod(meta.at("balance_hi"))) << "set format x '%g'\n"
    << "set yrange [" << meta.at("auc_lo") << ":1.02]\nset ytics auto\nset format y '%.2f'\n"
    << "set object rect from 0.9, " << kTargetAuc << " to " << kTargetBalance
    << ", 1.02 fc rgb '#d9f0d3' fs solid noborder behind\n"
    << ReferenceLine('x', kTargetBalance) << ReferenceLine('y', kTargetAuc);
  for (const auto& line : Lines(data_dir / ("strategy_tradeoff_labels_" + std::to_string(k) + ".txt"))) {
    std::istringstream in(line);
    std::string gx, gy, align, x, y, text;
    int leader = 0;
    in >> gx >> gy >> align >> leader >> x >> y;
    std::getline(in >> std::ws, text);
    s << "set label " << GnuplotQuote(text) << " at graph " << gx << ", graph " << gy << ' ' << align
      << " front font ',10'\n";
    if (leader) {
      s << "set arrow from graph " << gx << ", graph " << gy << " to first " << x << ", first "
        << y << " nohead lw 0.8 lc rgb '#aaaaaa' back\n";
    }
  }
  s << "plot 'strategy_tradeoff.dat' using " << mean + 3 << ':' << mean << " with points "
    << kStyle[k] << " notitle\n";
  return s.str();
}

}  // namespace

std::string StrategyTradeoffScript(const fs::path& data_dir, const fs::path& png) {
  const auto meta = ReadMeta(data_dir / "strategy_tradeoff.meta");
  const auto names = Lines(data_dir / "strategy_tradeoff.names");
  const std::vector<int> ns = ParseInts(meta.at("robots"));
  std::string at = "n = " + std::to_string(ns.at(0));
  if (ns.size() > 1) at += " and n = " + std::to_string(ns[1]);
  const std::string protocol(RowTraits(meta.at("protocol")).title);
  std::ostringstream s;
  s << Terminal(png, kTradeoffWidth, kTradeoffHeight)
    << "set multiplot title \"Routing strategies at " << at << "\\n"
    << "relative AUC and worst balance: " << protocol << ", " << RunsText(meta.at("runs"))
    << "; red dashes: issue-8 target\" font ',15'\n"
    << TradeoffDotPanels(meta, names, ns) << "set format y '%g'\nset ytics auto font ',11'\n"
    << "set yrange [*:*]\n";
  for (std::size_t k = 0; k < ns.size(); ++k) s << TradeoffScatter(data_dir, meta, ns, k);
  return s.str() + "unset multiplot\n";
}

namespace {

// Colour, dash and point type of strategy i: ten colours, then the same dashed.
std::string SweepLinetypes(std::size_t count) {
  constexpr int kPoints[7] = {7, 5, 9, 11, 13, 15, 4};
  std::ostringstream s;
  for (std::size_t i = 0; i < count; ++i) {
    s << "set linetype " << i + 1 << " lc rgb '" << kColours[i % 10] << "' lw 2 pt "
      << kPoints[i % 7] << " ps 1.1 dt " << (i < 10 ? 1 : 2) << '\n';
  }
  return s.str();
}

std::string SweepPanel(const std::string& file, const std::vector<std::string>& names,
                       bool titles) {
  std::string cmd = "plot ";
  for (std::size_t i = 0; i < names.size(); ++i) {
    cmd += (i ? ", \\\n     " : "") + GnuplotQuote(file) + " index " + std::to_string(i) +
           " using 1:2 with linespoints lt " + std::to_string(i + 1) + " " +
           (titles ? "title " + GnuplotQuote(names[i]) : std::string("notitle"));
  }
  return cmd + "\n";
}

// The groups of equal balance (strategy_sweep.meta) as a note under the legend, one strategy per
// line since the legend column is narrow; "" when there are none.
std::string CoincidingNote(const fs::path& data_dir, double left) {
  std::vector<std::string> lines = {"Same worst balance at every n", "(their lines coincide):"};
  for (const auto& line : Lines(data_dir / "strategy_sweep.meta")) {
    if (line.rfind("same_balance ", 0) != 0) continue;
    const std::string group = line.substr(13);
    std::size_t from = 0;
    for (std::size_t at = group.find(" = "); at != std::string::npos; at = group.find(" = ", from)) {
      lines.push_back((from ? "    = " : "") + group.substr(from, at - from));
      from = at + 3;
    }
    lines.push_back((from ? "    = " : "") + group.substr(from));
  }
  if (lines.size() == 2) return "";
  std::ostringstream s;
  s << "set label " << GnuplotTitle(lines) << " at screen " << left << ", 0.40 left font ',10' tc rgb '#444444'\n";
  return s.str();
}

}  // namespace

std::string StrategySweepScript(const fs::path& data_dir, const fs::path& png) {
  const auto meta = ReadMeta(data_dir / "strategy_sweep.meta");
  const auto names = Lines(data_dir / "strategy_sweep.titles");
  const std::vector<int> ns = ParseInts(meta.at("robots"));
  const bool bytes = !meta.at("network").empty();
  const int panels = bytes ? 3 : 2;
  const double key_left = 0.80, width = (key_left - 0.02) / panels;
  std::ostringstream s, tics;
  for (std::size_t i = 0; i < ns.size(); ++i) tics << (i ? ", " : "") << ns[i];
  s << Terminal(png, 1750, 640) << SweepLinetypes(names.size())
    << "set multiplot title "
    << GnuplotTitle({std::string("Routing strategies vs team size: relative AUC and worst balance ") +
                    "from the " + std::string(RowTraits(meta.at("protocol")).title) +
                    (bytes ? ", bytes per query from the simulation (" + meta.at("network") + ")" : "") + "; " +
                    (meta.at("runs") == "1" ? "1 run" : "mean of " + meta.at("runs") + " runs")})
    << " font ',14'\nset grid lc rgb '#dddddd'\nset xlabel 'robots n'\nset xtics ("
    << tics.str() << ")\nset xrange [" << ns.front() - 1 << ':' << ns.back() + 1 << "]\nunset key\n";
  auto panel = [&](int i) {
    const double left = 0.02 + i * width + 0.045;
    return Margins(left, left + width - 0.06, 0.11, 0.86);
  };
  s << panel(0) << "set title 'Relative AUC (higher is better)'\nset ylabel 'relative AUC'\n"
    << "set yrange [*:1.02]\n" << ReferenceLine('y', kTargetAuc)
    << SweepPanel("strategy_sweep_auc.dat", names, false) << "unset arrow\n"
    << panel(1) << "set title 'Worst balance ratio (lower is better)'\n"
    << "set ylabel 'busiest robot / fair share (log scale)'\nset logscale y\nset yrange [0.9:"
    << meta.at("balance_hi") << "]\n" << BalanceTics('y', std::stod(meta.at("balance_hi"))) << ReferenceLine('y', kTargetBalance);
  if (bytes) {
    s << SweepPanel("strategy_sweep_balance.dat", names, false) << "unset arrow\nunset logscale y\n"
      << panel(2) << "set title 'Bytes per query (simulation)'\nset ylabel 'wire kB per query'\n"
      << "set yrange [0:*]\nset ytics auto\n";
  }
  s << CoincidingNote(data_dir, key_left + 0.005);
  s << "set key at screen " << key_left + 0.005 << ", 0.86 left top Left reverse samplen 2.5 "
    << "spacing 1.15 font ',11' box opaque\n"
    << SweepPanel(bytes ? "strategy_sweep_bytes.dat" : "strategy_sweep_balance.dat", names, true);
  return s.str() + "unset multiplot\n";
}

}  // namespace dvpr
