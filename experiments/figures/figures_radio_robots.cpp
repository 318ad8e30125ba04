// robots_in_range.png (figures_radio.h): each robot's teammates in range over time, with the
// number of separate networks, from connectivity.csv's robots_in_range and components.
#include <algorithm>
#include <charconv>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "experiments/figures/figures_radio.h"
#include "experiments/figures/gnuplot_text.h"
#include "experiments/results/result_writers.h"

namespace dvpr {

namespace {

namespace fs = std::filesystem;

// connectivity.csv's robots_in_range field ("2 1 1"): exactly `n` counts in [0, n - 1].
std::vector<int> InRange(const CsvTable& t, std::size_t row, std::size_t column, int n) {
  std::vector<int> out;
  std::istringstream in(t.rows[row][column]);
  for (std::string field; in >> field;) {
    int v = -1;
    const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
    if (ec != std::errc() || end != field.data() + field.size() || v < 0 || v > n - 1) v = -1;
    if (v < 0) {
      throw std::runtime_error(t.path.string() + ": line " + std::to_string(row + 2) +
                               ": robots_in_range: expected counts from 0 to " + std::to_string(n - 1) + ", got '" +
                               OneLineText(field) + "'");
    }
    out.push_back(v);
  }
  if (static_cast<int>(out.size()) != n) {
    throw std::runtime_error(t.path.string() + ": line " + std::to_string(row + 2) + ": robots_in_range: expected " +
                             std::to_string(n) + " counts, got " + std::to_string(out.size()));
  }
  return out;
}

struct RobotStep {
  double time_s = 0;
  int components = 0;
  std::vector<int> in_range;
};

}  // namespace

std::optional<FigureScript> WriteRobotsInRangeFigure(const fs::path& dir, const CsvTable& t,
                                                     const std::vector<RunResult>& rows, std::string& why) {
  if (t.rows.empty() || std::find(t.header.begin(), t.header.end(), "robots_in_range") == t.header.end()) {
    why = "no connectivity.csv rows with robots_in_range";
    return std::nullopt;
  }
  const std::size_t c_strategy = t.Column("strategy"), c_robots = t.Column("robots"), c_run = t.Column("run"),
                    c_variant = t.Column("network_variant"), c_time = t.Column("time_s"),
                    c_components = t.Column("components"), c_in_range = t.Column("robots_in_range");
  // The largest team, its first run and first strategy (every strategy of a run has the same rows).
  int n = 0;
  for (std::size_t i = 0; i < t.rows.size(); ++i) n = std::max(n, t.Integer(i, c_robots, 2, 1 << 20));
  std::string strategy;
  int first_run = 1 << 30;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    if (t.Integer(i, c_robots, 2, 1 << 20) != n) continue;
    if (strategy.empty()) strategy = t.rows[i][c_strategy];
    first_run = std::min(first_run, t.Integer(i, c_run, 0, 1 << 30));
  }
  // One panel per radio (variants that differ only in routing have the same connectivity).
  std::map<int, std::vector<RobotStep>> by_variant;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    if (t.rows[i][c_strategy] != strategy || t.Integer(i, c_robots, 2, 1 << 20) != n ||
        t.Integer(i, c_run, 0, 1 << 30) != first_run) {
      continue;
    }
    by_variant[t.Integer(i, c_variant, 0, 1 << 20)].push_back(
        RobotStep{t.Count(i, c_time), t.Integer(i, c_components, 1, n), InRange(t, i, c_in_range, n)});
  }
  std::vector<std::pair<std::string, const std::vector<RobotStep>*>> panels;
  std::set<std::string> radios;
  for (const auto& [variant, steps] : by_variant) {
    const std::string radio = RadioLabelOf(rows, variant);
    if (radios.insert(radio).second) panels.emplace_back(radio, &steps);
  }
  std::ostringstream body;
  body << "set multiplot layout " << panels.size() << ",1 title "
       << GnuplotQuote("Teammates in range of each robot over time, n = " + std::to_string(n) + " (connectivity.csv: run " +
                       std::to_string(first_run) + "); orange: separate networks (components)")
       << " font ',13'\n"
       << "set xlabel 'virtual time (s)'\nset xrange [0:*]\nset autoscale xfix\nset ylabel 'robot'\nset yrange [-0.5:" << n - 0.5 << "]\n"
       << "set y2label 'components'\nset y2range [0:" << n + 1 << "]\nset y2tics\nset ytics nomirror\n"
       << "set cblabel 'robots in range'\nset cbrange [0:" << n - 1 << "]\n"
       << "set palette defined (0 '#f7fbff', 1 '#c6dbef', 2 '#6baed6', 3 '#2171b5', 4 '#08306b')\n"
       << "set tmargin 3\nset key off\n";
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const auto& [radio, steps] = panels[p];
    const std::string file = "in_range_" + std::to_string(p) + ".dat";
    // Index 0: the image, one scan per time; index 1: the components, one line per time.
    std::string dat = "# " + OneLineText(radio) + ": time_s robot robots_in_range\n";
    std::string components = "# time_s components\n";
    for (const RobotStep& s : *steps) {
      for (int r = 0; r < n; ++r) {
        dat += FormatDouble(s.time_s) + " " + std::to_string(r) + " " +
               std::to_string(s.in_range[static_cast<std::size_t>(r)]) + "\n";
      }
      dat += "\n";
      components += FormatDouble(s.time_s) + " " + std::to_string(s.components) + "\n";
    }
    WriteFileAtomic(dir / file, dat + "\n" + components);
    body << "set title " << GnuplotQuote(radio) << "\n"
         << "plot " << GnuplotQuote(file) << " index 0 using 1:2:3 with image, \\\n     " << GnuplotQuote(file)
         << " index 1 using 1:2 axes x1y2 with steps lw 3 lc rgb '#e66101'\n";
  }
  body << "unset multiplot\n";
  FigureScript f;
  f.width = 1400;
  f.height = 140 + 270 * static_cast<int>(panels.size());
  f.body = body.str();
  return f;
}

}  // namespace dvpr
