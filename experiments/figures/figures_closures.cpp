// loop_closures.png (figures_traffic.h): when the robots of a team find their first inter-robot
// loop closure with each other, from closure_pairs.csv (docs/design.md section 3, "Inter-robot
// loop closures"): the share of pairs closed against time per strategy, and each pair's first
// closure as a matrix for the paper's two strategies.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "experiments/figures/figure_style.h"
#include "experiments/figures/figures_traffic.h"
#include "experiments/figures/gnuplot_text.h"
#include "experiments/results/one_line_text.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/results/result_writers.h"

namespace dvpr {

namespace {

namespace fs = std::filesystem;

// One row of closure_pairs.csv: robots a and b and their first closure (s), NaN when none.
struct PairFirst {
  int a = 0;
  int b = 0;
  double first = std::numeric_limits<double>::quiet_NaN();
};

// The pairs of each run of one (strategy, n, network variant), by run. The robots index the
// matrix: anything but a robot of the team is refused, naming file, line and column.
std::map<int, std::vector<PairFirst>> FirstClosures(const CsvTable& pairs, const std::string& strategy, int v,
                                                    int n) {
  std::map<int, std::vector<PairFirst>> by_run;
  if (pairs.header.empty()) return by_run;
  const std::size_t p = pairs.Column("protocol"), s = pairs.Column("strategy"), r = pairs.Column("robots"),
                    run = pairs.Column("run"), net = pairs.Column("network_variant"),
                    robot_a = pairs.Column("robot_a"), robot_b = pairs.Column("robot_b"),
                    first = pairs.Column("first_closure_ns");
  for (std::size_t i = 0; i < pairs.rows.size(); ++i) {
    const auto& row = pairs.rows[i];
    if (row.size() != pairs.header.size()) continue;
    if (!RowTraits(row[p]).simulated_network || row[s] != strategy || row[r] != std::to_string(n) ||
        row[net] != std::to_string(v)) {
      continue;
    }
    const int k = pairs.Integer(i, run, 0, std::numeric_limits<int>::max());
    PairFirst f{pairs.Integer(i, robot_a, 0, n - 1), pairs.Integer(i, robot_b, 0, n - 1)};
    if (!row[first].empty()) f.first = pairs.Count(i, first) / 1e9;
    by_run[k].push_back(f);
  }
  return by_run;
}

// The share of pairs closed by time t, for each run, as steps: at every time a run closes a
// pair, the mean over runs and the lowest and highest run's share, just before and from then on.
// Lines "t mean low high"; from 0 to `end`. `top`: the highest share drawn, if higher.
std::string ShareSteps(const std::map<int, std::vector<PairFirst>>& by_run, double end, double& top) {
  struct Run {
    std::vector<double> firsts;  // ascending, the pairs that found one
    double pairs = 1;
    std::size_t next = 0;        // firsts[0, next) are <= the current time
  };
  std::vector<Run> runs;
  std::vector<double> times;
  for (const auto& [index, pairs] : by_run) {
    Run r;
    for (const PairFirst& f : pairs) {
      if (!std::isnan(f.first)) r.firsts.push_back(f.first);
    }
    std::sort(r.firsts.begin(), r.firsts.end());
    r.pairs = static_cast<double>(std::max<std::size_t>(pairs.size(), 1));
    times.insert(times.end(), r.firsts.begin(), r.firsts.end());
    runs.push_back(std::move(r));
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  std::string out;
  const auto line = [&](double t) {
    double sum = 0, low = 1, high = 0;
    for (const Run& r : runs) {
      const double share = static_cast<double>(r.next) / r.pairs;
      sum += share;
      low = std::min(low, share);
      high = std::max(high, share);
    }
    top = std::max(top, high);
    out += FormatDouble(t) + " " + FormatDouble(sum / static_cast<double>(runs.size())) + " " + FormatDouble(low) +
           " " + FormatDouble(high) + "\n";
  };
  line(0.0);
  for (double t : times) {
    line(t);  // just before t
    for (Run& r : runs) {
      while (r.next < r.firsts.size() && r.firsts[r.next] <= t) ++r.next;
    }
    line(t);
  }
  line(std::max(end, times.empty() ? 0.0 : times.back()));
  return out;
}

// One run's first closures as a symmetric n x n matrix (s), NaN (drawn blank) on the diagonal
// and where a pair found none.
void WriteFirstMatrix(const fs::path& file, const std::vector<PairFirst>& pairs, int n) {
  std::vector<double> m(static_cast<std::size_t>(n * n), std::numeric_limits<double>::quiet_NaN());
  for (const PairFirst& f : pairs) {
    m[static_cast<std::size_t>(f.a * n + f.b)] = m[static_cast<std::size_t>(f.b * n + f.a)] = f.first;
  }
  std::string dat;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      const double x = m[static_cast<std::size_t>(r * n + c)];
      dat += (c ? " " : "") + (std::isnan(x) ? std::string("NaN") : FormatDouble(x));
    }
    dat += "\n";
  }
  WriteFileAtomic(file, dat);
}

}  // namespace

std::optional<FigureScript> WriteClosureFigure(const fs::path& dir, const TrafficTable& t, const CsvTable& pairs,
                                               std::string& why, const VariantFigure& view) {
  const int v = view.variant >= 0 ? view.variant : t.ShownVariant();
  const int n = t.robots.empty() ? 0 : t.robots.back();
  std::vector<std::pair<std::string, std::map<int, std::vector<PairFirst>>>> shown;
  for (const std::string& s : t.strategies) {
    auto by_run = FirstClosures(pairs, s, v, n);
    if (!by_run.empty()) shown.emplace_back(s, std::move(by_run));
  }
  if (v < 0 || n < 2 || shown.empty()) {
    why = v < 0                   ? NoSimTraffic(t)
          : n < 2                 ? std::string("needs two or more robots")
          : pairs.header.empty()  ? std::string("needs closure_pairs.csv")
                                  : "closure_pairs.csv has no row at n = " + std::to_string(n);
    return std::nullopt;
  }
  // A run without a closure is a line at 0 and a blank matrix: with none anywhere, no figure.
  const auto closed = [](const std::vector<PairFirst>& run) {
    return std::any_of(run.begin(), run.end(), [](const PairFirst& f) { return !std::isnan(f.first); });
  };
  const bool any = std::any_of(shown.begin(), shown.end(), [&](const auto& s) {
    return std::any_of(s.second.begin(), s.second.end(), [&](const auto& run) { return closed(run.second); });
  });
  if (!any) {
    why = "no run found an inter-robot loop closure at n = " + std::to_string(n);
    return std::nullopt;
  }
  double end = 0;  // the last frame's time: the runs' longest drive
  for (const std::string& s : t.strategies) {
    if (const TrafficCell* c = t.Find(s, v, n)) end = std::max(end, c->longest_drive_s);
  }
  const std::string closures_file = view.data_prefix + "closures.dat";
  std::string dat;
  std::ostringstream plot;
  plot << "plot ";
  int block = 0;
  double highest = 0;
  for (const auto& [s, by_run] : shown) {
    dat += "# " + OneLineText(s) + "\n" + ShareSteps(by_run, end, highest) + "\n\n";
    const std::string colour = "lc rgb '" + figure_style::StrategyColour(t.StrategyIndex(s)) + "'";
    plot << (block ? ", \\\n     " : "") << GnuplotQuote(closures_file) << " index " << block
         << " using 1:3:4 with filledcurves fs transparent solid 0.15 noborder " << colour << " notitle, \\\n"
         << "     " << GnuplotQuote(closures_file) << " index " << block << " using 1:2 with lines lw 2 " << colour << " title "
         << GnuplotQuote(s + " (" + std::to_string(by_run.size()) + (by_run.size() == 1 ? " run)" : " runs)"));
    ++block;
  }
  WriteFileAtomic(dir / closures_file, dat);
  // The matrices of the first two strategies whose lowest run (run 0) closed a pair: a blank
  // matrix would be an empty panel.
  std::vector<std::size_t> with_matrix;
  for (std::size_t i = 0; i < shown.size() && with_matrix.size() < 2; ++i) {
    if (closed(shown[i].second.begin()->second)) with_matrix.push_back(i);
  }
  const std::size_t matrices = with_matrix.size();
  double top = 0;
  for (std::size_t i = 0; i < matrices; ++i) {
    const std::vector<PairFirst>& pairs_of_run = shown[with_matrix[i]].second.begin()->second;
    for (const PairFirst& f : pairs_of_run) {
      if (!std::isnan(f.first)) top = std::max(top, f.first);
    }
    WriteFirstMatrix(dir / (view.data_prefix + "closure_matrix_" + std::to_string(i) + ".dat"), pairs_of_run, n);
  }
  std::ostringstream s;
  s << "set multiplot layout 1," << 1 + matrices << " title "
    << GnuplotTitle({"Inter-robot loop closures, n = " + std::to_string(n) + ", " + NetworkName(*t.Network(v))})
    << " font ',13'\n"
    << "set title "
    << GnuplotTitle({"Robot pairs with a loop closure between them", "line: mean over runs, band: lowest to highest run"})
    << "\nset xlabel 'time [s]'\nset ylabel 'share of the n (n - 1) / 2 pairs'\nset xrange [0:"
    << FormatDouble(std::max(end, 1.0)) << "]\nset yrange [0:" << FormatDouble(std::clamp(highest * 1.25, 0.1, 1.05))
    << "]\nset key top left\n"
    << plot.str() << "\n"
    << "set size ratio -1\nunset grid\nunset key\nset xlabel 'robot'\nset ylabel 'robot'\n"
    << "set xrange [-0.5:" << n - 0.5 << "]\nset yrange [" << n - 0.5 << ":-0.5]\nset cbrange [0:"
    << FormatDouble(std::max(top, 1.0)) << "]\nset palette defined (0 '#08306b', 1 '#2171b5', 2 '#6baed6', 3 '#c6dbef')\n"
    << "set tics out\nset xtics " << std::max(1, n / 10) << "\nset ytics " << std::max(1, n / 10) << "\n";
  for (std::size_t i = 0; i < matrices; ++i) {
    const std::size_t k = with_matrix[i];
    s << (i + 1 == matrices ? "set colorbox\nset cblabel 'first closure [s]'\n" : "unset colorbox\n") << "set title "
      << GnuplotTitle({shown[k].first + ": first closure per pair", "run " +
                                                                       std::to_string(shown[k].second.begin()->first) +
                                                                       "; blank: none"})
      << " tc rgb '" << figure_style::StrategyColour(t.StrategyIndex(shown[k].first)) << "'\nplot "
      << GnuplotQuote(view.data_prefix + "closure_matrix_" + std::to_string(i) + ".dat") << " matrix with image notitle\n";
  }
  return FigureScript{s.str() + "unset multiplot\n", 700 + 550 * static_cast<int>(matrices), 600};
}

}  // namespace dvpr
