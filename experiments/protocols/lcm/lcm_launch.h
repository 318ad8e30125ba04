#pragma once
// `dvpr launch`: a team of `dvpr agent` processes on this machine, then their
// logs gathered into the files of `dvpr run` with protocol=lcm (README,
// "Running real agents").
//
// Each configured strategy runs in turn as its own team (broadcast first when
// configured: it is the reference of the relative AUC, as in the simulation;
// without it auc_reference stays empty; for the bow_ strategies bow_centralized
// is, docs/bow.md). Rows are made by the simulation's
// own functions (SummarizeSimRun, MakeRow, AppendRows), so the columns mean
// the same, with these differences: latency is wall-clock; links.csv counts
// what senders published and `dropped` = published minus what the destination
// logged receiving; a robot that left no log (its process died) received
// nothing, so everything sent to it counts as dropped, and its own queries are
// missing from queries.csv and from `queries` (agents.csv lists it).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "experiments/protocols/lcm/agent_log.h"
#include "experiments/config/config.h"
#include "experiments/results/results.h"
#include "experiments/protocols/run.h"

namespace dvpr {

struct LaunchOptions {
  std::filesystem::path config;
  std::vector<ConfigOverride> overrides;
  int robots = 0;                  // required
  int run = 0;
  std::filesystem::path out;       // default results/<config name>_lcm
  std::string lcm_url;             // default kDefaultLcmUrl
  double speedup = 1.0;
  double grace_s = 2.0;
  double timeout_s = 0;            // 0: the frames' wall time + grace + 120 s
  std::int64_t hold_bytes = std::int64_t{16} << 20;  // each agent's --hold-bytes
  std::filesystem::path binary = "/proc/self/exe";
  void Validate() const;
};

LaunchOptions ParseLaunchArgs(const std::vector<std::string>& args);

// Runs every strategy's team, writes the output folder as one transaction
// (result_folder.h). An agent that fails is reported on `out` with the first
// error line of its output. A team none of whose agents left a log never ran:
// it gets no rows (rows of zeros would pass for a run). Returns 0 when every
// agent exited cleanly, 1 when some did not (the rows of the teams that ran
// are written anyway); when no team ran, nothing is written at all.
int RunLaunch(const LaunchOptions& options, std::ostream& out);

// One strategy's team, as gathered: logs[r] empty when robot r left none.
struct GatheredRun {
  RunOutput rows;                  // runs (one row), per_robot, links, queries (if outputs.queries)
  double auc = 0.0;
  std::int64_t queries = 0;        // logged queries
  std::int64_t incomplete = 0;     // of which some reply never came
  std::vector<int> missing_robots; // robots without a log
};

// Turns the agents' logs of one team into result rows. reference_auc: the
// broadcast team's AUC (NaN when none).
GatheredRun GatherTeam(const ExperimentConfig& config, const SharedInputs& inputs, const std::string& strategy,
                       int robots, int run, const std::vector<std::optional<AgentLog>>& logs, double reference_auc);

}  // namespace dvpr
