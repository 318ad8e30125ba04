// gnuplot scripts for the figures (see figures.h) and running them.
#include "experiments/figures/figures.h"

#include <algorithm>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <utility>

#include "experiments/figures/figures_contention.h"
#include "experiments/figures/figures_radio.h"
#include "experiments/figures/figures_traffic.h"
#include "experiments/figures/gnuplot_run.h"
#include "experiments/figures/gnuplot_text.h"
#include "experiments/results/result_writers.h"

namespace dvpr {

namespace {

namespace fs = std::filesystem;

// Same terminal, font and size for every figure; `noenhanced` so underscores print as such.
// Scripts run in figures/data/, so the PNG (in figures/) is one level up. Draw() passes the
// temporary PNG in `dvpr_output`; the script keeps the PNG's own name (so it is the same file in
// every run of a config, and draws the figure when rerun by hand).
std::string Preamble(const fs::path& png, int width = 900, int height = 600) {
  return "set terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
         " font 'DejaVu Sans,11' noenhanced\nset output (exists('dvpr_output') ? dvpr_output : " +
         GnuplotQuote("../" + png.filename().string()) +
         ")\nset grid lc rgb '#dddddd'\nset border lw 1\nset key box opaque\n";
}

std::vector<std::string> ReadLines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// "plot 'stem.dat' index 0 ... title '...', ..." for every block of a series file.
std::string PlotSeries(const fs::path& data_dir, const std::string& stem, const std::string& style) {
  const auto titles = ReadLines(data_dir / (stem + ".titles"));
  std::string cmd = "plot ";
  for (std::size_t i = 0; i < titles.size(); ++i) {
    cmd += (i ? ", \\\n     " : "") + std::string("'") + stem + ".dat" +
           "' index " + std::to_string(i) + " using 1:2 " + style + " title " +
           GnuplotQuote(titles[i]);
  }
  return cmd + "\n";
}

// "5th", "21st", "22nd", "23rd", "112th".
std::string Ordinal(int k) {
  const int tens = k % 100, ones = k % 10;
  const char* suffix = (tens >= 11 && tens <= 13) ? "th" : ones == 1 ? "st" : ones == 2 ? "nd" : ones == 3 ? "rd" : "th";
  return std::to_string(k) + suffix;
}

std::string ConfusionScript(const fs::path& data_dir, const fs::path& png) {
  std::istringstream meta(ReadLines(data_dir / "confusion.meta").at(0));
  int m = 0, step = 0, frames = 0;
  meta >> m >> step >> frames;
  std::ostringstream s;
  s << Preamble(png, 760, 680)
    << "set title 'Descriptor distance between deployment frames (squared L2, every " << Ordinal(step)
    << " of " << frames << " frames)'\n"
    << "set xlabel 'frame index'\nset ylabel 'frame index'\nset cblabel 'squared L2 distance'\n"
    << "set size ratio -1\nset xrange [0:" << m * step << "]\nset yrange [" << m * step
    << ":0]\nset palette defined (0 '#000004', 1 '#3b0f70', 2 '#8c2981', 3 '#de4968', "
       "4 '#fe9f6d', 5 '#fcfdbf')\nunset grid\nunset key\n"
    << "plot 'confusion.f32' binary array=(" << m << "," << m
    << ") format='%float32' dx=" << step << " dy=" << step
    << " origin=(0,0) with image notitle\n";
  return s.str();
}

std::string PrScript(const fs::path& data_dir, const fs::path& png) {
  return Preamble(png) +
         "set title 'Precision-recall: centralized vs decentralized (paper protocol, run 0)'\n"
         "set xlabel 'recall'\nset ylabel 'precision'\nset xrange [0:1]\nset yrange [0:1.02]\n"
         "set key bottom left\n" + PlotSeries(data_dir, "pr_curves", "with lines lw 2");
}

std::string DimsScript(const fs::path& data_dir, const fs::path& png) {
  return Preamble(png, 760, 680) +
         "set title 'First two descriptor dimensions: training vs deployment'\n"
         "set xlabel 'descriptor dimension 1'\nset ylabel 'descriptor dimension 2'\n"
         "set size ratio -1\nset key top right\n" +
         PlotSeries(data_dir, "descriptor_dims", "with points pt 7 ps 0.25");
}

std::string RelativeAucScript(const fs::path& data_dir, const fs::path& png) {
  // "paper", or "sim" and the network its rows ran on (a second line since issue 48).
  const std::vector<std::string> lines = ReadLines(data_dir / "relative_auc.protocol");
  const std::string protocol = lines.at(0) + " protocol";
  const std::string network = lines.size() > 1 ? lines[1] : "";
  auto panel = [&](const std::string& stem, const std::string& ylabel, const std::string& title) {
    const std::string dat = stem + ".dat";
    // The simulation's network on a second line (the paper protocol has none).
    const std::string quoted = network.empty() ? GnuplotQuote(title) : GnuplotTitle({title, "on " + network});
    // The mean's 95 % confidence band (Student's t over the runs) under the runs and the mean.
    return "set title " + quoted + "\nset xlabel 'robots n'\nset ylabel '" + ylabel +
           "'\nplot '" + stem + "_ci.dat' using 1:2:3 with filledcurves fc rgb '#1f3f8f' fs transparent solid 0.18 "
           "noborder title '95 % confidence interval of the mean', '" + dat +
           "' index 0 using 1:2 with points pt 7 ps 0.6 lc rgb '#7f9fcf' "
           "title 'every run', '" + dat + "' index 1 using 1:2 with linespoints lw 2 pt 7 "
           "lc rgb '#1f3f8f' title 'mean over runs'\n";
  };
  // One key for both panels, below them: inside, a key covers points wherever the data fall.
  return Preamble(png, 1200, 560) + "set multiplot layout 1,2 margins 0.07, 0.98, 0.2, 0.9 spacing 0.1\n"
         "set key at screen 0.5, screen 0.01 center bottom horizontal\nset xtics 2\nset yrange [0:*]\n" +
         panel("relative_auc", "AUC(decentralized) / AUC(reference)",
               "Relative AUC vs team size (" + protocol + ")") +
         "set yrange [0:*]\nunset key\n" +
         panel("balance", "max robot load / mean load",
               "Worst balance ratio vs team size (" + protocol + ")") +
         "unset multiplot\n";
}

// Writes the script and draws it (gnuplot_run.h); throws when the figure was not drawn.
void Draw(const fs::path& gnuplot, const fs::path& data_dir, const fs::path& png, const std::string& name,
          const std::function<std::string(const fs::path&, const fs::path&)>& script, FigureLog log) {
  const fs::path gp = data_dir / (name + ".gp");
  WriteFileAtomic(gp, script(data_dir, png));
  // Run inside the data folder: the scripts name their files relative to it, so they do not
  // depend on where the results folder is (and can be rerun after moving it).
  DrawWithGnuplot(gnuplot, data_dir, gp, png, data_dir / (name + ".log"), log);
}

// Strategy figures compare strategies beyond the paper's two; with only those they repeat
// what the traffic figures show.
bool ComparesStrategies(const std::vector<RunResult>& rows) {
  return std::any_of(rows.begin(), rows.end(), [](const RunResult& r) {
    return r.key.strategy != "decentralized" && r.key.strategy != "broadcast";
  });
}

struct Figure {
  std::string name;
  bool available;
  std::function<std::string(const fs::path&, const fs::path&)> script;
  std::string missing;
};

// Figures 5-9 (figures_traffic.h): data written now, drawn with the others.
void AddTrafficFigures(const fs::path& out_dir, const fs::path& data, const std::vector<RunResult>& rows,
                       std::vector<Figure>& figures) {
  const TrafficTable t = TabulateTraffic(rows);
  const CsvTable per_robot = ReadCsvTable(out_dir / "per_robot.csv");
  const CsvTable links = ReadCsvTable(out_dir / "links.csv");
  auto add = [&](const std::string& name, const std::function<std::optional<FigureScript>(std::string&)>& write) {
    std::string why;
    const std::optional<FigureScript> f = write(why);
    const auto script = [f](const fs::path&, const fs::path& png) {
      return Preamble(png, f->width, f->height) + f->body;
    };
    figures.push_back(Figure{name, f.has_value(), script, why});
  };
  using Write = std::function<std::optional<FigureScript>(std::string&, const VariantFigure&)>;
  const std::vector<VariantFigure> views = VariantFigures(t);
  // One figure per network variant (figures_traffic.h); where no variant has its data, one note.
  const auto per_variant = [&](const std::string& name, const Write& write) {
    const std::size_t first = figures.size();
    for (const VariantFigure& view : views) {
      add(name + view.suffix, [&](std::string& why) { return write(why, view); });
    }
    const bool none = std::none_of(figures.begin() + static_cast<std::ptrdiff_t>(first), figures.end(),
                                   [](const Figure& f) { return f.available; });
    const bool same = std::all_of(figures.begin() + static_cast<std::ptrdiff_t>(first), figures.end(),
                                  [&](const Figure& f) { return f.missing == figures[first].missing; });
    if (views.size() > 1 && none && same) {
      const std::string why = "on all " + std::to_string(views.size()) + " networks: " + figures[first].missing;
      figures.resize(first);
      figures.push_back(Figure{name, false, nullptr, why});
    }
  };
  add("place_recognition_bytes", [&](std::string& why) { return WritePlaceRecognitionFigure(data, t, why); });
  per_variant("traffic_by_role", [&](std::string& why, const VariantFigure& v) { return WriteRoleFigure(data, t, why, v); });
  per_variant("robot_load",
              [&](std::string& why, const VariantFigure& v) { return WriteRobotLoadFigure(data, t, per_robot, why, v); });
  per_variant("traffic_matrix",
              [&](std::string& why, const VariantFigure& v) { return WriteMatrixFigure(data, t, links, why, v); });
  add("saturation", [&](std::string& why) { return WriteSaturationFigure(data, t, why); });
  const CsvTable closure_pairs = ReadCsvTable(out_dir / "closure_pairs.csv");
  per_variant("loop_closures", [&](std::string& why, const VariantFigure& v) {
    return WriteClosureFigure(data, t, closure_pairs, why, v);
  });
}

}  // namespace

std::vector<fs::path> DrawFigures(const fs::path& out_dir, std::span<const NetworkLabel> networks, std::ostream& log,
                                  FigureLog logs, const FigureProgress& progress) {
  std::vector<RunResult> rows = ReadRunsCsv(out_dir / "runs.csv");
  LabelNetworks(rows, networks, out_dir / "runs.csv");
  const fs::path fig = out_dir / "figures";
  const fs::path data = fig / "data";
  fs::create_directories(data);
  std::string why3;
  const bool have3 = WriteRelativeAucData(data, rows, &why3);
  const bool strategies = ComparesStrategies(rows);
  const bool have7 = strategies && WriteStrategyTradeoffData(data, rows);
  const bool have8 = strategies && WriteStrategySweepData(data, rows);
  // Figures 1, 2 and 4 come from the inputs, which only `dvpr run` has (WriteFigureData).
  const bool inputs = fs::exists(data / "confusion.meta");
  const std::string no_inputs = "figures/data/ has no data of the inputs: dvpr run writes it when outputs.figures is true";
  std::vector<Figure> figures = {
      {"confusion_matrix", inputs, ConfusionScript, no_inputs},
      {"pr_curves", fs::exists(data / "pr_curves.titles"), PrScript, inputs ? "needs the paper protocol" : no_inputs},
      {"relative_auc_balance", have3, RelativeAucScript, why3},
      {"descriptor_dims", fs::exists(data / "descriptor_dims.titles"), DimsScript, no_inputs}};
  AddTrafficFigures(out_dir, data, rows, figures);
  const std::string no_strategies = "only the paper's two strategies are configured";
  // Without any relative AUC, the strategy figures say why as figure 3 does.
  const std::string no_auc = TabulateStrategies(rows).accuracy_protocol.empty()
                                 ? "no relative AUC in runs.csv" + (have3 ? std::string() : "; " + why3)
                                 : std::string();
  figures.push_back({"strategy_tradeoff", have7, StrategyTradeoffScript,
                     strategies ? (no_auc.empty() ? "no relative AUC in runs.csv" : no_auc) : no_strategies});
  figures.push_back({"strategy_sweep", have8, StrategySweepScript,
                     strategies ? (no_auc.empty() ? "needs a relative AUC at two or more n" : no_auc) : no_strategies});
  const std::optional<fs::path> gnuplot = FindProgram("gnuplot");
  if (!gnuplot) {
    log << "dvpr: figures not drawn: gnuplot is not installed (scripts/setup.sh installs it)\n";
    return {};
  }
  // The notes of skipped figures follow the drawing, and only when every figure was drawn: before
  // an error they would bury it.
  std::string skipped;
  std::vector<Figure> to_draw;
  for (Figure& f : figures) {
    if (!f.available) {
      skipped += "dvpr: figure " + f.name + ".png skipped (" + f.missing + ")\n";
      continue;
    }
    to_draw.push_back(std::move(f));
  }
  // Figure 9 only where bag-of-words ran (no "skipped" line elsewhere).
  if (WriteBowComparisonData(out_dir, data, rows)) to_draw.push_back({"bow_comparison", true, BowComparisonScript, ""});
  // contention.png only where a variant contends for its medium (figures_contention.h).
  if (const std::optional<FigureScript> f = WriteContentionFigure(data, TabulateTraffic(rows))) {
    to_draw.push_back({"contention", true,
                       [f](const fs::path&, const fs::path& png) { return Preamble(png, f->width, f->height) + f->body; },
                       ""});
  }
  // The radio's figures only where the results have them (figures_radio.h).
  for (const auto& [name, f] : RadioFigures(out_dir, data, rows)) {
    to_draw.push_back(
        {name, true, [f](const fs::path&, const fs::path& png) { return Preamble(png, f.width, f.height) + f.body; }, ""});
  }
  std::vector<fs::path> drawn;
  std::string failed;  // the first figure that was not drawn; the others are still tried
  int failures = 0;
  for (std::size_t i = 0; i < to_draw.size(); ++i) {
    const fs::path png = fig / (to_draw[i].name + ".png");
    if (progress) progress(to_draw[i].name, i, to_draw.size());
    try {
      Draw(*gnuplot, data, png, to_draw[i].name, to_draw[i].script, logs);
      drawn.push_back(png);
    } catch (const std::runtime_error& e) {
      if (failures++ == 0) failed = e.what();
    }
  }
  if (failures > 0) {
    throw std::runtime_error(failed + (failures > 1 ? " (and " + std::to_string(failures - 1) + " more figures)" : ""));
  }
  log << skipped;
  return drawn;
}

}  // namespace dvpr
