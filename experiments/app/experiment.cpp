#include "experiments/app/experiment.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <vector>

#include "experiments/config/network_variants.h"
#include "experiments/figures/figures.h"
#include "experiments/protocols/inputs.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/results/result_folder.h"
#include "experiments/results/result_writers.h"
#include "experiments/results/spread.h"
#include "experiments/sweep/run_distributor.h"
#include "experiments/sweep/run_progress.h"
#include "experiments/sweep/run_sweep.h"
#include "experiments/sweep/sweep_checks.h"
#include "experiments/sweep/sweep_size.h"

namespace dvpr {

namespace {

void CheckProtocolsAvailable(const ExperimentConfig& config, const std::string& origin,
                             const ProtocolRegistry& protocols) {
  for (const auto& p : config.sweep.protocols) {
    if (protocols.Find(p) != nullptr) continue;
    std::string have;
    for (const auto& n : protocols.Names()) have += (have.empty() ? "" : ", ") + n;
    throw ConfigError(origin + ": protocols: '" + p + "' is not available in this build of dvpr "
                      "(available: " + have + "); e.g. --set protocols=[" + have + "]");
  }
}

// The row files, open as temporaries until every run has been written.
struct RowFiles {
  // radio: a network variant is a radio (radio.csv, and the radio columns of per_robot.csv,
  // messages.csv and queries.csv, result_writers.h).
  // mac: a network variant contends for its medium (medium.csv, and the MAC columns of
  // per_robot.csv). teams: the sweep runs a team (closure_pairs.csv).
  RowFiles(const OutputDir& dir, const OutputsConfig& outputs, bool dropouts, bool bow_strategies, bool radio,
           bool mac, bool teams)
      : radio_columns(radio), mac_columns(mac), runs(dir, "runs.csv"), per_robot(dir, "per_robot.csv"),
        links(dir, "links.csv") {
    runs.stream() << kRunsHeader << '\n';
    per_robot.stream() << PerRobotHeader(radio, mac) << '\n';
    links.stream() << kLinksHeader << '\n';
    if (outputs.queries) {
      queries.emplace(dir, "queries.csv");
      queries->stream() << QueriesHeader(radio) << '\n';
    }
    if (outputs.messages) {
      messages.emplace(dir, "messages.csv");
      messages->stream() << MessagesHeader(radio) << '\n';
    }
    if (dropouts) {
      failover.emplace(dir, "failover.csv");
      failover->stream() << kFailoverHeader << '\n';
    }
    if (outputs.connectivity) {
      connectivity.emplace(dir, "connectivity.csv");
      connectivity->stream() << kConnectivityHeader << '\n';
    }
    if (bow_strategies) {
      bow.emplace(dir, "bow.csv");
      bow->stream() << kBowHeader << '\n';
      bow_sizes.emplace(dir, "bow_sizes.csv");
      bow_sizes->stream() << kBowSizesHeader << '\n';
    }
    if (radio) {
      radio_rows.emplace(dir, "radio.csv");
      radio_rows->stream() << kRadioHeader << '\n';
    }
    if (mac) {
      medium_rows.emplace(dir, "medium.csv");
      medium_rows->stream() << kMediumHeader << '\n';
    }
    if (teams) {
      closure_pairs.emplace(dir, "closure_pairs.csv");
      closure_pairs->stream() << kClosurePairsHeader << '\n';
    }
  }
  void Write(const RunOutput& out) {
    for (const auto& r : out.runs) runs.stream() << CsvRow(r) << '\n';
    for (const auto& r : out.per_robot) per_robot.stream() << CsvRow(r, radio_columns, mac_columns) << '\n';
    for (const auto& r : out.links) links.stream() << CsvRow(r) << '\n';
    if (queries) for (const auto& r : out.queries) queries->stream() << CsvRow(r, radio_columns) << '\n';
    if (messages) for (const auto& r : out.messages) messages->stream() << CsvRow(r, radio_columns) << '\n';
    if (failover) for (const auto& r : out.failover) failover->stream() << CsvRow(r) << '\n';
    if (bow) for (const auto& r : out.bow) bow->stream() << CsvRow(r) << '\n';
    if (bow_sizes) for (const auto& r : out.bow_sizes) bow_sizes->stream() << CsvRow(r) << '\n';
    if (radio_rows) for (const auto& r : out.radio) radio_rows->stream() << CsvRow(r) << '\n';
    if (medium_rows) for (const auto& r : out.medium) medium_rows->stream() << CsvRow(r) << '\n';
    if (connectivity) for (const auto& r : out.connectivity) connectivity->stream() << CsvRow(r) << '\n';
    if (closure_pairs) for (const auto& r : out.closure_pairs) closure_pairs->stream() << CsvRow(r) << '\n';
  }
  void Commit() {
    runs.Commit();
    per_robot.Commit();
    links.Commit();
    if (queries) queries->Commit();
    if (messages) messages->Commit();
    if (failover) failover->Commit();
    if (bow) bow->Commit();
    if (bow_sizes) bow_sizes->Commit();
    if (radio_rows) radio_rows->Commit();
    if (medium_rows) medium_rows->Commit();
    if (connectivity) connectivity->Commit();
    if (closure_pairs) closure_pairs->Commit();
  }
  bool radio_columns;
  bool mac_columns;
  AtomicFile runs, per_robot, links;
  std::optional<AtomicFile> queries, messages, failover, bow, bow_sizes, radio_rows, medium_rows, connectivity,
      closure_pairs;
};

// synthetic_bow's vectors are made while the inputs load (hours at its largest parameters): a
// sweep too large is refused before that when dataset.frames bounds the frames; CheckSweepInputs
// checks again with the frames the dataset has.
void CheckSizeBeforeLoading(const ExperimentConfig& config, const std::string& origin, const ExecutorOptions& options) {
  if (options.allow_large || !config.dataset.frames) return;
  CheckSweepSize(EstimateSweepSize(config, *config.dataset.frames, config.dataset.dim),
                 SweepMachine::ThisOne(options.threads), origin);
}

// The synthetic BoW world's frames on stderr when making them would take more than 10 s (about two
// hours for KITTI 00 at its largest parameters; decided after the first frame, whose time gives
// the first line's estimate, so small worlds and the tests stay quiet).
FrameProgress BowProgress(const ExecutorOptions& options) {
  if (!options.progress) return {};
  struct State {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    std::optional<RunProgress> shown;
    bool decided = false;
  };
  auto state = std::make_shared<State>();
  return [state](std::size_t done, std::size_t total) {
    if (!state->decided) {
      state->decided = true;
      const double first = std::chrono::duration<double>(std::chrono::steady_clock::now() - state->start).count();
      if (first * static_cast<double>(total) <= 10.0) return;
      state->shown.emplace(total, true, "dataset.synthetic_bow frames", state->start);
    }
    if (state->shown) state->shown->Done(done);
  };
}

// A process of a distributed sweep that does not write the results (run_distributor.h): the
// same inputs and checks, its runs write into the distributor's run folder, its outputs go to
// the process that writes.
void RunShare(const ExperimentConfig& config, const std::string& origin, const ProtocolRegistry& protocols,
              const ExecutorOptions& options) {
  CheckSizeBeforeLoading(config, origin, options);
  SharedInputs inputs = LoadSharedInputs(config, origin, BowProgress(options));
  CheckSweepInputs(inputs, origin, options.allow_large, options.threads);
  inputs.out_dir = options.distributor->run_folder();
  RunSweep(inputs, protocols, options, [](const RunSpec&, RunOutput&&) {
    throw std::logic_error("RunShare: an output handed on to a process that does not write results");
  });
}

}  // namespace

std::vector<RunResult> RunExperiment(const ExperimentConfig& config, const std::string& origin,
                                     const std::filesystem::path& out_dir,
                                     const ProtocolRegistry& protocols,
                                     const ExecutorOptions& options, std::ostream& summary) {
  CheckProtocolsAvailable(config, origin, protocols);
  if (options.distributor != nullptr && !options.distributor->writes_results()) {
    RunShare(config, origin, protocols, options);
    return {};
  }
  CheckOutputFolder(out_dir);  // before the inputs load: a refused --out fails at once
  CheckSizeBeforeLoading(config, origin, options);
  // The steps other than the runs on stderr as each starts (issue 48: 6.6 s of silence before the
  // first run's line, then 10 s of figures), under the same switch as the runs' progress.
  const PhaseLog phases(options.progress);
  const auto phase = [&phases](const std::string& what) { phases.Start(what); };
  SharedInputs inputs = LoadSharedInputs(config, origin, BowProgress(options), phase);
  CheckSweepInputs(inputs, origin, options.allow_large, options.threads);  // what would fail a run fails here, before anything is written
  // Everything is written into folder.dir() and moved to out_dir only when all succeeded.
  ResultFolder folder(out_dir);
  std::vector<RunResult> rows;
  // An error names what it could not write where the user looks for it (the temporary folder
  // goes as the error unwinds).
  try {
    const std::filesystem::path dir = folder.dir();
    inputs.out_dir = dir;
    WriteFileAt(folder.output(), "config.yaml", EmitConfig(config));
    // failover.csv only with failover on: a config with a dropout alone (tests/golden) writes what it
    // always wrote.
    const bool bow = std::any_of(config.sweep.strategies.begin(), config.sweep.strategies.end(),
                                 [](const StrategySpec& s) { return s.bag_of_words(); });
    const bool radio = std::count(config.network.model.begin(), config.network.model.end(), LinkModelKind::kRadio) > 0;
    // closure_pairs.csv when a team runs (its robots exchange messages: inter-robot loop closures).
    const bool teams = AnyProtocol(config.sweep.protocols, &ProtocolTraits::sends_messages);
    // medium.csv and the MAC columns when a variant contends (csma, wifi); only sim runs fill them.
    const bool mac = std::any_of(config.network.model.begin(), config.network.model.end(), Contends);
    RowFiles files(folder.output(), config.outputs, !config.dropout.empty() && config.failover.enabled, bow, radio,
                   mac, teams);
    std::vector<PrCurve> curves;
    std::vector<RunConnectivity> connectivity;  // one per simulated run that tracked it, in spec order
    ExecutorOptions told = options;
    told.phase = phase;
    RunSweep(inputs, protocols, told, [&](const RunSpec&, RunOutput&& out) {
      files.Write(out);
      rows.insert(rows.end(), out.runs.begin(), out.runs.end());
      for (auto& c : out.curves) curves.push_back(std::move(c));
      SummarizeConnectivityRuns(out.connectivity, connectivity);
    });
    phase("writing the result files");
    files.Commit();
    WriteFileAt(folder.output(), "summary.json", SummaryJson(rows, connectivity));
    if (config.outputs.figures) {
      phase("figures: writing their data (the deployment's confusion matrix, descriptors, PR curves)");
      WriteFigureData(dir, FigureData{&inputs.deployment.descriptors, &inputs.training, &curves,
                                      config.evaluation.suppression_frames});
      // A line as each figure starts: one may take most of the time (the confusion matrix of a
      // long team's frames).
      const FigureProgress drawing = [&phase](const std::string& name, std::size_t before, std::size_t total) {
        phase("figures " + std::to_string(before + 1) + "/" + std::to_string(total) + ": drawing " + name + ".png");
      };
      // a failed run removes its folder, logs and all
      DrawFigures(dir, VariantLabels(config.network), std::cerr, FigureLog::kGone, drawing);
    }
    folder.Commit();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(folder.Explain(e.what()));
  } catch (const ConfigError& e) {
    throw ConfigError(folder.Explain(e.what()));
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(folder.Explain(e.what()));
  }
  PrintSummaryTable(rows, summary);
  return rows;
}

namespace {

std::string Cell(double v, int decimals) {
  if (std::isnan(v)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// At most ~5 robot counts per group: the first, the last and evenly spaced ones between.
std::set<int> ShownRobots(const std::vector<RunResult>& rows) {
  std::set<int> all;
  for (const auto& r : rows) all.insert(r.key.robots);
  if (all.size() <= 5) return all;
  const std::vector<int> v(all.begin(), all.end());
  std::set<int> shown;
  for (int i = 0; i < 5; ++i) shown.insert(v[static_cast<std::size_t>(i) * (v.size() - 1) / 4]);
  return shown;
}

}  // namespace

void PrintSummaryTable(const std::vector<RunResult>& rows, std::ostream& out) {
  // lowest_reference: the lowest reference AUC of the group's runs (NaN when none has one).
  struct Acc {
    std::string label;
    int robots;
    int n = 0;
    std::vector<double> values[5];
    double lowest_reference = std::numeric_limits<double>::quiet_NaN();
  };
  std::vector<Acc> groups;
  std::map<std::string, std::size_t> index;
  const std::set<int> shown = ShownRobots(rows);
  for (const auto& r : rows) {
    if (!shown.contains(r.key.robots)) continue;
    std::string label = r.key.protocol + " " + r.key.strategy;
    if (!r.key.network.model.empty()) label += ", " + NetworkName(r.key.network);
    const std::string id = label + "|" + std::to_string(r.key.robots);
    auto [it, added] = index.emplace(id, groups.size());
    if (added) groups.push_back(Acc{.label = label, .robots = r.key.robots, .n = 0, .values = {}});
    Acc& a = groups[it->second];
    ++a.n;
    if (!std::isnan(r.auc_reference) && !(a.lowest_reference <= r.auc_reference)) a.lowest_reference = r.auc_reference;
    const double v[5] = {r.auc, r.relative_auc, r.worst_balance_ratio, r.bytes_per_query,
                         r.mean_latency_ms};
    for (int i = 0; i < 5; ++i) a.values[i].push_back(v[i]);
  }
  // The mean over the runs, +- the half-width of its 95 % confidence interval from two runs on.
  const auto cell = [](const std::vector<double>& values, int decimals) {
    const Spread s = SpreadOf(values);
    std::string c = Cell(s.mean, decimals);
    if (!std::isnan(s.ci95)) c += "+-" + Cell(s.ci95, decimals);
    return c;
  };
  constexpr int kDecimals[5] = {3, 3, 2, 0, 3};
  std::vector<std::vector<std::string>> table;  // one row per group: label, robots, runs, 5 metrics
  table.push_back({"protocol strategy", "robots", "runs", "auc", "rel_auc", "worst_bal", "bytes/query", "latency_ms"});
  // A relative AUC over a reference that found almost nothing is marked, with a footnote.
  double lowest_marked = std::numeric_limits<double>::quiet_NaN();
  for (const Acc& a : groups) {
    std::vector<std::string> row{a.label, std::to_string(a.robots), std::to_string(a.n)};
    for (int i = 0; i < 5; ++i) row.push_back(cell(a.values[i], kDecimals[i]));
    if (a.lowest_reference < kLowReferenceAuc) {
      row[4] += "*";
      if (!(lowest_marked <= a.lowest_reference)) lowest_marked = a.lowest_reference;
    }
    table.push_back(std::move(row));
  }
  // Every column as wide as its widest cell (at least its usual width, so that short tables keep
  // the shape they always had): the columns stay aligned whatever the numbers.
  std::vector<std::size_t> width{34, 6, 5, 13, 13, 11, 15, 15};
  for (const auto& row : table) {
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  }
  for (const auto& row : table) {
    std::string line = row[0] + std::string(width[0] - row[0].size(), ' ');
    for (std::size_t c = 1; c < row.size(); ++c) line += std::string(width[c] - row[c].size() + 1, ' ') + row[c];
    out << line << '\n';
  }
  if (!std::isnan(lowest_marked)) {
    out << "* rel_auc over a reference AUC below " << Cell(kLowReferenceAuc, 2) << " in a run (lowest "
        << Cell(lowest_marked, 3) << ", runs.csv auc_reference): its reference found almost nothing, the ratio "
        << "says little (docs/outputs.md)\n";
  }
}

}  // namespace dvpr
