#pragma once
// The figures of an experiment (PNG, gnuplot's pngcairo terminal). Each figure is two steps:
// its data goes to DIR/figures/data/ as plain text (or raw float32 for the confusion matrix),
// then a gnuplot script next to it draws DIR/figures/<name>.png. So `dvpr plot DIR` can redraw
// everything from the files alone, and a user can edit a script and rerun gnuplot on it.
// Fixed fonts and sizes, no date stamps: the same data gives the same PNG.
//
//   1 confusion_matrix.png   squared descriptor distances of the deployment, every 5th frame, or
//                            every k-th so that the matrix is at most kConfusionSide frames a
//                            side (confusion.f32 stays under 4 MB; staggered teams have many frames)
//   2 pr_curves.png          precision-recall, centralized vs decentralized at one n
//   3 relative_auc_balance.png  relative AUC and worst balance ratio vs n (mean line, runs dots)
//   4 descriptor_dims.png    descriptor dimensions 1 and 2, training vs deployment
//   5-9 the traffic of the simulation (figures_traffic.h): place_recognition_bytes.png,
//       traffic_by_role.png, robot_load.png, traffic_matrix.png, saturation.png, loop_closures.png;
//       with several sim network variants traffic_by_role, robot_load, traffic_matrix and
//       loop_closures are drawn once per variant, <name>-net<v>-<network slug>.png (VariantFigures)
// A figure with nothing to draw is skipped with a note naming the reason (e.g. no query had a
// revisit within the frames), and no figure is drawn with an empty panel.
//   10 strategy_tradeoff.png  every strategy at two n (10 and 20): relative AUC, worst balance,
//                            bytes per query (dot plots, min-max over runs), and relative AUC vs
//                            worst balance (one labelled point per strategy, the issue-8 target)
//   11 strategy_sweep.png    relative AUC, worst balance, bytes per query vs n, every strategy
//   12 bow_comparison.png    global descriptors vs bag-of-words (docs/bow.md): relative AUC and
//                            query bytes vs n, partial-query sizes, votes off the centralized
//                            best; drawn only when the folder has bow.csv
//   13 connectivity.png, radio_range.png  the radio's (figures_radio.h): drawn only when the
//                            folder has connectivity.csv, or radio variants of two or more ranges
#include <cstddef>
#include <filesystem>
#include <functional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "agents/algorithms/descriptors.h"
#include "experiments/figures/gnuplot_run.h"
#include "experiments/results/results.h"

namespace dvpr {

// Data files of figures 1, 2 and 4 (they come from the inputs, not from runs.csv).
// WriteConfusionData samples every `step`-th frame, or every ConfusionStep(frames, step)-th when
// that keeps the matrix side at most kConfusionSide (1000 x 1000 float32: 4 MB).
inline constexpr long kConfusionSide = 1000;
long ConfusionStep(long frames, long step);
void WriteConfusionData(const std::filesystem::path& data_dir, const DescriptorMatrix& deployment,
                        int step);
void WritePrCurveData(const std::filesystem::path& data_dir, const std::vector<PrCurve>& curves);
void WriteDescriptorDimsData(const std::filesystem::path& data_dir,
                             const DescriptorMatrix& training, const DescriptorMatrix& deployment);

struct FigureData {
  const DescriptorMatrix* deployment = nullptr;
  const DescriptorMatrix* training = nullptr;
  const std::vector<PrCurve>* curves = nullptr;
  int suppression_frames = 250;
};
// All three of the above into out_dir/figures/data/.
void WriteFigureData(const std::filesystem::path& out_dir, const FigureData& data);

// Data file of figure 3, from runs.csv rows: the paper protocol's decentralized runs, else the
// simulation's on its first network variant with a relative AUC (relative_auc.protocol names
// the protocol and, for the simulation, that network: the figure's titles say it). Returns false
// (and writes nothing) when the rows hold nothing to plot; then `why` (when given) says why: no
// decentralized run, or runs whose reference found nothing (no query had a revisit).
bool WriteRelativeAucData(const std::filesystem::path& data_dir, const std::vector<RunResult>& rows,
                          std::string* why = nullptr);

// Figures 7 and 8 (experiments/figures/figures_strategies.cpp): runs.csv aggregated per (strategy, n).
// Mean, min and max over the runs that have the metric (NaN and runs = 0 when none).
struct RunSpread {
  int runs = 0;
  double mean = kNotApplicable;
  double min = kNotApplicable;
  double max = kNotApplicable;
};
struct StrategyStats {
  std::string strategy;
  int robots = 0;
  RunSpread relative_auc;     // rows of StrategyTable::accuracy_protocol
  RunSpread worst_balance;    // idem
  RunSpread bytes_per_query;  // sim rows of network variant StrategyTable::bytes_variant
};
struct StrategyTable {
  // "paper" (the static protocol) when runs.csv has paper rows with a relative AUC, else "sim"
  // (its first network variant), else "" (nothing to plot).
  std::string accuracy_protocol;
  int bytes_variant = -1;             // smallest sim network variant with bytes; -1: no sim rows
  std::string bytes_network;          // e.g. "point-to-point 10 Mbit/s"
  std::vector<std::string> strategies;  // every strategy of runs.csv, in order of appearance
  std::vector<int> robots;            // every n, ascending
  std::vector<StrategyStats> stats;   // every (strategy, n) with a row, strategy-major, n ascending
  // nullptr when (strategy, robots) has no row.
  const StrategyStats* Find(const std::string& strategy, int robots) const;
};
StrategyTable TabulateStrategies(const std::vector<RunResult>& rows);
// The n of figure 7: {10, 20} when both were swept, else the two largest (or the only one).
std::vector<int> ComparedRobots(const std::vector<int>& robots);
// Data of figures 7 and 8; false (nothing written) when there is no relative AUC to plot, or,
// for figure 8, fewer than two robot counts.
bool WriteStrategyTradeoffData(const std::filesystem::path& data_dir,
                               const std::vector<RunResult>& rows);
bool WriteStrategySweepData(const std::filesystem::path& data_dir,
                            const std::vector<RunResult>& rows);
// Their gnuplot scripts (script text; `png` is the file it writes, next to data_dir's parent).
std::string StrategyTradeoffScript(const std::filesystem::path& data_dir,
                                   const std::filesystem::path& png);
std::string StrategySweepScript(const std::filesystem::path& data_dir,
                                const std::filesystem::path& png);
// "point-to-point 10 Mbit/s": how the figures name a network variant.
std::string NetworkText(const NetworkLabel& network);

// Figure 12 (experiments/figures/figures_bow.cpp): its data from out_dir's bow.csv,
// bow_sizes.csv and `rows`; false (nothing written) when out_dir has no bow.csv.
bool WriteBowComparisonData(const std::filesystem::path& out_dir, const std::filesystem::path& data_dir,
                            const std::vector<RunResult>& rows);
// Its bytes panel marks the seed paper's query sizes: BoW's distributed query (16 kB) and
// NetVLAD's (512 bytes to one robot).
std::string BowComparisonScript(const std::filesystem::path& data_dir, const std::filesystem::path& png);
inline constexpr int kSeedBowQueryBytes = 16000;
inline constexpr int kSeedGlobalQueryBytes = 512;

// Reads out_dir/runs.csv (and per_robot.csv, links.csv), whose network rows take their labels
// from `networks` (the run's variants, VariantLabels of its config; LabelNetworks), writes the data of figures 3, 5-12, then
// draws every figure whose data exists; the strategy figures (10, 11) only when runs.csv has a
// strategy other than decentralized and broadcast. Figures without their data, or every figure
// when gnuplot is not installed, are reported on `log` and skipped. A figure gnuplot fails to
// draw (gnuplot_run.h) is an error: the others are still drawn, then std::runtime_error names
// the first that failed (and its log when `logs` keeps it); its earlier PNG stays as it was, and
// the notes of skipped figures are not written (they would bury the error). Returns the PNGs
// written. `progress`, if set, hears of each figure as its drawing starts: its name, how many were
// drawn (or failed) before it, and how many are to be drawn.
using FigureProgress = std::function<void(const std::string& name, std::size_t before, std::size_t total)>;
std::vector<std::filesystem::path> DrawFigures(const std::filesystem::path& out_dir,
                                               std::span<const NetworkLabel> networks, std::ostream& log,
                                               FigureLog logs = FigureLog::kKept, const FigureProgress& progress = {});

}  // namespace dvpr
