#pragma once
// Protocol "sim" of `dvpr run`: for each (robots, run, network variant) the
// team runs in virtual time once per strategy, on the same data and
// centroids as the paper protocol's run; broadcast is the reference of the
// relative AUC (docs/design.md section 3). The bag-of-words strategies run as teams of BoW agents
// (agents/bow_robot_agent.h) with the centralized BoW server (bow_centralized) as their
// reference (docs/bow.md).
#include <string>

#include "experiments/config/config.h"
#include "experiments/protocols/run.h"
#include "experiments/protocols/sim/simulation.h"

namespace dvpr {

RunFunction MakeSimRun(const SharedInputs& inputs);

// Shared with the real-agent protocol (experiments/protocols/lcm/lcm_launch.h), which turns
// its gathered logs into the same rows.
// runs.csv row of one strategy; reference_auc: broadcast's AUC of the same run (NaN: none).
RunResult MakeRow(const RunSpec& spec, const std::string& strategy, const SimRunSummary& s, double reference_auc);
// per_robot, links and (when outputs.queries) queries rows of one strategy's run.
void AppendRows(const RunSpec& spec, const std::string& strategy, const SimRunLog& log, const SimRunSummary& s,
                const ExperimentConfig& c, RunOutput& out);

}  // namespace dvpr
