#pragma once
// The figures of an experiment (PNG, gnuplot's pngcairo terminal). Each figure is two steps:
// its data goes to DIR/figures/data/ as plain text (or raw float32 for the confusion matrix),
// then a gnuplot script next to it draws DIR/figures/<name>.png. So `dvpr plot DIR` can redraw
// everything from the files alone, and a user can edit a script and rerun gnuplot on it.
// Fixed fonts and sizes, no date stamps: the same data gives the same PNG.
//
//   1 confusion_matrix.png   squared descriptor distances of the deployment, every 5th frame
//   2 pr_curves.png          precision-recall, centralized vs decentralized at one n
//   3 relative_auc_balance.png  relative AUC and worst balance ratio vs n (mean line, runs dots)
//   4 descriptor_dims.png    descriptor dimensions 1 and 2, training vs deployment
//   5 bytes_per_query.png    bytes per query vs n, per strategy and network model (sim)
//   6 query_latency.png      mean query latency vs n, per strategy and bandwidth (sim)
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "agents/descriptors.h"
#include "experiments/results.h"

namespace dvpr {

// Data files of figures 1, 2 and 4 (they come from the inputs, not from runs.csv).
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

// Data files of figures 3, 5 and 6, from runs.csv rows. Each returns false (and writes nothing)
// when the rows hold nothing to plot (e.g. no sim rows for figure 5).
bool WriteRelativeAucData(const std::filesystem::path& data_dir, const std::vector<RunResult>& rows);
bool WriteBytesPerQueryData(const std::filesystem::path& data_dir,
                            const std::vector<RunResult>& rows);
bool WriteLatencyData(const std::filesystem::path& data_dir, const std::vector<RunResult>& rows);

// Reads out_dir/runs.csv, writes the data of figures 3, 5, 6, then draws every figure whose data
// exists. Figures that cannot be drawn (no data, gnuplot missing or failing) are reported on
// `log` and skipped. Returns the PNGs written.
std::vector<std::filesystem::path> DrawFigures(const std::filesystem::path& out_dir,
                                               std::ostream& log);

}  // namespace dvpr
