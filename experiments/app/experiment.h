#pragma once
// `dvpr run`: a validated config in, the output folder of docs/design.md section 6 out.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "experiments/config/config.h"
#include "experiments/results/results.h"
#include "experiments/sweep/run_executor.h"

namespace dvpr {

// Loads the inputs and checks everything a run would read (CheckSweepInputs; errors up to here
// leave nothing on disk), runs the sweep in parallel, writes
// config.yaml, runs.csv, per_robot.csv, links.csv, summary.json (and queries.csv / messages.csv
// when asked), the figures when outputs.figures, and prints the summary table to `summary`.
// Everything is written into a temporary folder that replaces out_dir as a whole only when all
// succeeded (ResultFolder): an error or a signal leaves an earlier out_dir as it was. Returns
// the runs.csv rows. `origin` names the config in errors. With options.distributor, in a
// process that does not write the results, runs only its share and returns no rows.
std::vector<RunResult> RunExperiment(const ExperimentConfig& config, const std::string& origin,
                                     const std::filesystem::path& out_dir,
                                     const ProtocolRegistry& protocols,
                                     const ExecutorOptions& options, std::ostream& summary);

// The table printed at the end: per protocol, strategy, network and a few robot counts, the
// means of the main metrics. A rel_auc cell of a group one of whose runs has a reference AUC
// (auc_reference: the centralized search's, or the run's broadcast) below kLowReferenceAuc ends
// in '*' ("-*" when no run has a ratio: a reference of AUC 0), and a line under the table gives
// the lowest such reference AUC and the threshold: a ratio to a reference that found almost
// nothing says little (docs/outputs.md, "A relative AUC whose reference found almost nothing").
inline constexpr double kLowReferenceAuc = 0.1;
void PrintSummaryTable(const std::vector<RunResult>& rows, std::ostream& out);

}  // namespace dvpr
