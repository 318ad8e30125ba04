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
  for (std::size_t i = 0; i < t.networks.size(); ++i) {
    const NetworkLabel& net = t.networks[i];
    if (!SharesOneChannel(net.model)) continue;
    for (const std::string& s : t.strategies) {
      std::string lines;
      for (int n : t.robots) {
        const TrafficCell* c = t.Find(s, net.variant, n);
        if (c == nullptr || c->offered_mbps <= 0) continue;
        const double percent = 100 * c->delivered_mbps / c->offered_mbps;
        const double percent_ci = 100 * c->delivered_ci95 / c->offered_mbps;
        lines += FormatDouble(c->offered_mbps) + " " + FormatDouble(percent) + " " + FormatDouble(c->latency_ms) +
                 " " + FormatDouble(c->offered_ci95) + " " + FormatDouble(percent_ci) + " " +
                 FormatDouble(c->latency_ci95) + "\n";
      }
      if (lines.empty()) continue;
      const std::string title = s + ", " + NetworkName(net);
      dat += "# " + OneLineText(title) + "\n" + lines + "\n\n";
      // Points, not lines: a saturated team offers less as it grows (fewer replies and
      // verifications get through), so joining the team sizes in order would zig-zag.
      const std::string style = " lw 1.5 ps 1.4 lc rgb '" + figure_style::StrategyColour(t.StrategyIndex(s)) +
                                "' pt " + std::to_string(figure_style::NetworkPoint(i)) + " title " +
                                GnuplotQuote(title);
      share << (block ? ", \\\n     " : "") << "'contention.dat' index " << block
            << " using 1:2:4:5 with xyerrorbars" << style;
      latency << (block ? ", \\\n     " : "") << "'contention.dat' index " << block
              << " using 1:3:4:6 with xyerrorbars" << style;
      ++block;
    }
  }
  WriteFileAtomic(data_dir / "contention.dat", dat);
  const std::string sizes = "points: n = " + std::to_string(t.robots.front()) + " .. " + std::to_string(t.robots.back()) +
                            "; mean over runs, bars: 95 % confidence intervals";
  std::string body = "set multiplot layout 1,2 spacing 0.1 title 'One channel, three media access rules: the ideal "
                     "bus, ns-3 CSMA, 802.11 DCF' font ',13'\nset grid\nset logscale x\n";
  body += "set title " + GnuplotTitle({"Delivered share of the offered load", sizes}) +
          "\nset xlabel 'offered load, every copy sent [Mbit/s]'\nset ylabel 'delivered [% of offered]'\n"
          "set yrange [0:105]\nset key at graph 0.01, graph 0.8 left top box samplen 1.5 width -8 font ',9'\nplot " + share.str() + "\n";
  body += "set title " + GnuplotTitle({"Mean query latency", sizes}) +
          "\nset xlabel 'offered load, every copy sent [Mbit/s]'\nset ylabel 'mean query latency [ms]'\n"
          "set autoscale y\nset logscale y\nset key top left box samplen 1.5 width -8 font ',9'\nplot " + latency.str() + "\nunset multiplot\n";
  return FigureScript{body, 1600, 700};
}

}  // namespace dvpr
