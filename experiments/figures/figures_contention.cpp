#include "experiments/figures/figures_contention.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include "experiments/figures/figure_style.h"
#include "experiments/figures/gnuplot_text.h"
#include "experiments/results/result_writers.h"

namespace dvpr {

namespace fs = std::filesystem;

namespace {

bool Contending(const std::string& model) { return model == "csma" || model == "wifi"; }
bool SharesOneChannel(const std::string& model) { return model == "shared_medium" || Contending(model); }

}  // namespace

std::optional<FigureScript> WriteContentionFigure(const fs::path& data_dir, const TrafficTable& t) {
  if (std::none_of(t.networks.begin(), t.networks.end(), [](const NetworkLabel& n) { return Contending(n.model); })) {
    return std::nullopt;
  }
  std::string dat;
  std::ostringstream share, latency;
  int block = 0;
  int medium = 0;  // the line's dash and point type: one per medium of the figure
  for (std::size_t i = 0; i < t.networks.size(); ++i) {
    const NetworkLabel& net = t.networks[i];
    if (!SharesOneChannel(net.model)) continue;
    for (const std::string& s : t.strategies) {
      std::string lines;
      std::vector<int> sizes;
      for (int n : t.robots) {
        const TrafficCell* c = t.Find(s, net.variant, n);
        if (c == nullptr || c->offered_mbps <= 0) continue;
        const double percent = 100 * c->delivered_mbps / c->offered_mbps;
        const double percent_ci = 100 * c->delivered_ci95 / c->offered_mbps;
        lines += FormatDouble(c->offered_mbps) + " " + FormatDouble(percent) + " " + FormatDouble(c->latency_ms) +
                 " " + FormatDouble(c->offered_ci95) + " " + FormatDouble(percent_ci) + " " +
                 FormatDouble(c->latency_ci95) + " " + std::to_string(n) + "\n";
        sizes.push_back(n);
      }
      if (lines.empty()) continue;
      const std::string title = s + ", " + NetworkName(net);
      dat += "# " + OneLineText(title) + "\n" + lines + "\n\n";
      // A line joins the team sizes in order, each point labelled with its n: a saturated team
      // offers less as it grows (fewer replies and verifications get through), and the line
      // turning back shows it.
      const std::string colour = figure_style::StrategyColour(t.StrategyIndex(s));
      const std::string style = " lw 1.5 ps 1.3 lc rgb '" + colour + "' dt " + std::to_string(figure_style::NetworkDash(
                                                                                 static_cast<std::size_t>(medium))) +
                                " pt " + std::to_string(figure_style::NetworkPoint(static_cast<std::size_t>(medium)));
      const auto labels = [&](int column) {
        return " using 1:" + std::to_string(column) + ":(sprintf('%d', $7)) with labels offset char 0.9, char 0.5 "
               "font ',8' tc rgb '" + colour + "' notitle";
      };
      share << (block ? ", \\\n     " : "") << "'contention.dat' index " << block
            << " using 1:2:4:5 with xyerrorlines" << style << " title " << GnuplotQuote(title) << ", \\\n     "
            << "'contention.dat' index " << block << labels(2);
      latency << (block ? ", \\\n     " : "") << "'contention.dat' index " << block
              << " using 1:3:4:6 with xyerrorlines" << style << " notitle, \\\n     "
              << "'contention.dat' index " << block << labels(3);
      ++block;
    }
    ++medium;
  }
  WriteFileAtomic(data_dir / "contention.dat", dat);
  std::string sizes;
  for (std::size_t k = 0; k < t.robots.size(); ++k) sizes += (k ? ", " : "") + std::to_string(t.robots[k]);
  const std::string subtitle = "n = " + sizes + " in order (labels: n); means over runs, bars: 95 % CI";
  // One legend for both panels, below them (outside every plot area: it covers no data).
  std::string body = "set multiplot layout 1,2 margins 0.06, 0.98, 0.17, 0.86 spacing 0.08 title 'One channel, three "
                     "media access rules: the ideal bus, ns-3 CSMA, 802.11 DCF' font ',13'\nset grid\nset logscale x\n";
  body += "set title " + GnuplotTitle({"Delivered share of the offered load", subtitle}) +
          "\nset xlabel 'offered load, every copy sent [Mbit/s]'\nset ylabel 'delivered [% of offered]'\n"
          "set yrange [0:100]\nset key at screen 0.5, screen 0.01 center bottom vertical maxrows 2 box samplen 3 "
          "width 1 font ',10'\nplot " + share.str() + "\n";
  body += "set title " + GnuplotTitle({"Mean query latency", subtitle}) +
          "\nset xlabel 'offered load, every copy sent [Mbit/s]'\nset ylabel 'mean query latency [ms]'\n"
          "set autoscale y\nset logscale y\nunset key\nplot " + latency.str() + "\nunset multiplot\n";
  return FigureScript{body, 1600, 760};
}

}  // namespace dvpr
