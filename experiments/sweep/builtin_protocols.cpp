// The protocols `dvpr run` knows: the static paper protocol (experiments/protocols/paper/static_protocol.h)
// and the simulation (experiments/protocols/sim/sim_protocol.h).
#include <algorithm>
#include <iterator>
#include <memory>

#include "experiments/sweep/run_executor.h"
#include "experiments/protocols/sim/sim_protocol.h"
#include "experiments/protocols/paper/static_protocol.h"
#include "experiments/protocols/paper/static_recluster.h"
#include "experiments/protocols/paper/static_strategies.h"
#include "experiments/strategies/strategy_catalogue.h"

namespace dvpr {

namespace {

int PrRobots(const ExperimentConfig& c) {
  if (c.outputs.pr_robots) return *c.outputs.pr_robots;
  const auto& robots = c.sweep.robots;
  if (std::find(robots.begin(), robots.end(), 10) != robots.end()) return 10;
  return *std::max_element(robots.begin(), robots.end());
}

PaperProtocolParams ToPaperParams(const SharedInputs& in) {
  const ExperimentConfig& c = *in.config;
  PaperProtocolParams p;
  static_cast<RunCentroidParams&>(p) = c.training.run_centroids;
  p.evaluation = c.evaluation;
  p.robots = c.sweep.robots;
  p.runs = c.sweep.runs;
  // Given centroids are the user's files; only trained ones are saved.
  if (p.centroids_pattern.empty() && !in.out_dir.empty()) p.centroids_out_dir = in.out_dir / "centroids";
  p.threads = 1;  // the executor already runs one spec per core
  p.Validate();
  return p;
}

// In the static protocol, broadcast ranks every query against every other robot's frames and
// keeps the best: exactly the centralized ranking. Its row says so (relative AUC 1); balance is
// not defined for it (every robot receives every query).
RunResult PaperBroadcastRow(const RunSpec& spec, const PaperEvaluator& evaluator,
                            std::int64_t queries) {
  RunResult row;
  row.key = spec.Key("broadcast");
  row.seed = spec.seed;
  row.auc = evaluator.centralized().auc;
  row.auc_reference = row.auc;
  row.relative_auc = 1.0;
  row.queries = queries;
  return row;
}

// A catalogued strategy (experiments/strategies/strategy_catalogue.h) in the static protocol: its table
// for this run, then EvaluateRouting.
PaperRunResult PaperStrategyRun(const StrategySpec& spec, const RunSpec& run, const PaperEvaluator& evaluator,
                                const DescriptorMatrix& training, const PaperProtocolParams& params) {
  PaperProtocolParams table_params = params;
  table_params.centroids_out_dir.clear();  // the paper run writes its own centroids
  const auto table = BuildStrategyTable(spec, training, evaluator.deployment().descriptors, table_params,
                                        run.robots, run.run);
  PaperRunResult r =
      spec.recluster_period > 0
          ? EvaluateRecluster(evaluator,
                              PlanStaticRecluster(evaluator.deployment().descriptors, table,
                                                  ReclusterParamsOf(spec, params.seed, run.robots, run.run)),
                              spec.name, params.keep_curves)
          : EvaluateRouting(evaluator, *MakeSpecRouting(spec, table), spec.name, params.keep_curves);
  r.row.key = run.Key(spec.name);
  r.row.seed = params.centroids_pattern.empty() ? RunSeed(params.seed, run.robots, run.run) : 0;
  for (auto& load : r.per_robot) load.key = r.row.key;
  r.curve.run = run.run;
  return r;
}

RunFunction MakePaperRun(const SharedInputs& in) {
  PaperProtocolParams params = ToPaperParams(in);
  if (!params.centroids_out_dir.empty()) std::filesystem::create_directories(params.centroids_out_dir);
  auto evaluator = std::make_shared<const PaperEvaluator>(in.deployment, params.evaluation);
  const int pr_robots = PrRobots(*in.config);
  const DescriptorMatrix* training = &in.training;
  const std::int64_t frames = in.deployment.size();  // every frame is one query
  return [params, evaluator, pr_robots, training, frames](const RunSpec& spec) {
    RunOutput out;
    PaperProtocolParams run_params = params;
    run_params.keep_curves = spec.robots == pr_robots && spec.run == 0;
    for (const std::string& strategy : spec.strategies) {
      if (strategy == "broadcast") {
        out.runs.push_back(PaperBroadcastRow(spec, *evaluator, frames));
        continue;
      }
      const StrategySpec* beyond = FindStrategySpec(strategy);
      if (strategy != "decentralized" && !beyond) continue;  // a strategy the static protocol has no form of
      PaperRunResult r = beyond ? PaperStrategyRun(*beyond, spec, *evaluator, *training, run_params)
                                : RunPaperRun(*evaluator, *training, run_params, spec.robots, spec.run);
      r.row.key = spec.Key(strategy);
      for (auto& load : r.per_robot) load.key = r.row.key;
      out.runs.push_back(r.row);
      std::move(r.per_robot.begin(), r.per_robot.end(), std::back_inserter(out.per_robot));
      if (run_params.keep_curves) {
        const PrResult& central = evaluator->centralized();
        const bool first = out.curves.empty();  // the centralized curve once, however many strategies
        if (first) {
          out.curves.push_back(PrCurve{"centralized", spec.robots, spec.run, central.recall, central.precision});
        }
        out.curves.push_back(std::move(r.curve));
      }
    }
    return out;
  };
}

}  // namespace

ProtocolRegistry BuiltinProtocols() {
  ProtocolRegistry registry;
  registry.Add("paper", MakePaperRun);
  registry.Add("sim", MakeSimRun);
  return registry;
}

}  // namespace dvpr
