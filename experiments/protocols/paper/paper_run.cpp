#include "experiments/protocols/paper/paper_run.h"

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <map>
#include <memory>
#include <stdexcept>

#include "experiments/config/config.h"
#include "experiments/domain/strategies/run_placement.h"
#include "experiments/protocols/paper/static_bow.h"
#include "experiments/protocols/paper/static_protocol.h"
#include "experiments/protocols/paper/static_recluster.h"
#include "experiments/protocols/paper/static_strategies.h"
#include "experiments/protocols/strategy_inputs.h"

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
  // Given centroids are the user's files; only trained ones are saved.
  if (p.centroids_pattern.empty() && !in.out_dir.empty()) p.centroids_out_dir = in.out_dir / "centroids";
  p.Validate();
  return p;
}

// In the static protocol, broadcast ranks every query against every other robot's frames and
// keeps the best: exactly the centralized ranking. Its row says so (relative AUC 1, or undefined
// like every other row's when the reference AUC is 0: a run without a revisit); balance is not
// defined for it (every robot receives every query).
RunResult PaperBroadcastRow(const RunSpec& spec, const PaperEvaluator& evaluator,
                            std::int64_t queries) {
  RunResult row;
  row.key = spec.Key("broadcast");
  row.seed = spec.seed;
  row.auc = evaluator.centralized().auc;
  row.auc_reference = row.auc;
  row.relative_auc = row.auc_reference == 0 ? kNotApplicable : 1.0;
  row.queries = queries;
  return row;
}

// A strategy in the static protocol: its table and routing for this run, then the paper's own
// evaluation of its table (decentralized; writes the run's centroids), of its re-clustering plan,
// or of any routing.
PaperRunResult PaperStrategyRun(const StrategySpec& spec, const RunSpec& run, const PaperEvaluator& evaluator,
                                const StrategyInputs& inputs, const PaperProtocolParams& params) {
  const RunPlacement routing = BuildRunPlacement(spec, inputs, run.robots, run.run);
  const DescriptorMatrix& deployment = evaluator.deployment().descriptors;
  PaperRunResult r = routing.Visit(
      [&](const StatelessFamily& f) {
        return spec.paper_method() ? EvaluatePaperRun(evaluator, *f.table, params, run.run)
                                   : EvaluatePlacement(evaluator, *f.strategy, spec.name, params.keep_curves);
      },
      [&](const ReclusterFamily& f) {
        return EvaluateRecluster(evaluator, PlanStaticRecluster(deployment, f.table, f.params), spec.name,
                                 params.keep_curves);
      },
      [&](const BowFamily&) -> PaperRunResult {
        throw std::logic_error("PaperStrategyRun: " + spec.name + " is a bow_ strategy (AppendBowRun)");
      });
  r.row.key = run.Key(spec.name);
  r.row.seed = params.centroids_pattern.empty() ? RunSeed(params.seed, run.robots, run.run) : 0;
  for (auto& load : r.per_robot) load.key = r.row.key;
  r.curve.run = run.run;
  return r;
}

// A bow_ strategy in the static protocol (experiments/protocols/paper/static_bow.h): its row,
// per-robot load, bow.csv row and partial-query sizes.
// Its PR curve is not kept: figure 2 compares the descriptor strategies with their centralized one.
void AppendBowRun(const StrategySpec& strategy, const RunSpec& spec, const BowEvaluator& bow,
                  const StrategyInputs& inputs, RunOutput& out) {
  BowRunResult r;
  if (bow.IsPlanned(strategy.name, spec.robots)) {
    r = bow.EvaluatePlanned(strategy.name, spec.robots);  // its owners built once, by the plan
  } else {
    const RunPlacement routing = BuildRunPlacement(strategy, inputs, spec.robots, spec.run);
    const BowFamily* family = routing.As<BowFamily>();
    if (family == nullptr) throw std::logic_error("AppendBowRun: " + strategy.name + " is not a bow_ strategy");
    r = family->words ? bow.EvaluateShared(*family->words, strategy.name)
                      : bow.Reference(strategy.name, spec.robots, strategy.bow == StrategySpec::Bow::kBroadcast);
  }
  r.paper.row.key = spec.Key(strategy.name);
  r.paper.row.seed = spec.seed;
  out.runs.push_back(r.paper.row);
  for (auto& load : r.paper.per_robot) {
    load.key = r.paper.row.key;
    out.per_robot.push_back(std::move(load));
  }
  r.bow.key = r.paper.row.key;
  out.bow.push_back(r.bow);
  for (const auto& [bytes, count] : r.part_sizes) out.bow_sizes.push_back({r.paper.row.key, bytes, count});
}

// Beside the bow_ strategies, a descriptor strategy's query messages in the same terms
// (bow.csv), so the comparison sets the bytes of the three designs side by side.
void AppendDescriptorTraffic(const StrategySpec& strategy, const RunSpec& spec, const StrategyInputs& inputs,
                             RunOutput& out) {
  const DescriptorMatrix& x = *inputs.deployment;
  BowRunResult r;
  if (strategy.broadcast()) {
    r = DescriptorQueryTraffic(nullptr, spec.robots, x);
  } else {
    const RunPlacement routing = BuildRunPlacement(strategy, inputs, spec.robots, spec.run);
    const StatelessFamily* family = routing.As<StatelessFamily>();
    if (family == nullptr) return;  // re-clustering: its traffic is the simulation's to count
    r = DescriptorQueryTraffic(family->strategy, spec.robots, x);
  }
  r.bow.key = spec.Key(strategy.name);
  out.bow.push_back(r.bow);
  for (const auto& [bytes, count] : r.part_sizes) out.bow_sizes.push_back({r.bow.key, bytes, count});
}

bool AnyBow(const ExperimentConfig& c) {
  return std::any_of(c.sweep.strategies.begin(), c.sweep.strategies.end(),
                     [](const StrategySpec& s) { return s.bag_of_words(); });
}

// The distributed-index evaluations the sweep will ask the BoW evaluator for, in the order its
// runs ask (robots outer, strategies in the config's order), each built when its batch runs.
std::vector<BowEvaluator::PlannedAssignment> PlanBow(const ExperimentConfig& c, const StrategyInputs& inputs) {
  std::vector<BowEvaluator::PlannedAssignment> planned;
  for (const int robots : c.sweep.robots) {
    for (const StrategySpec& strategy : c.sweep.strategies) {
      if (strategy.bow != StrategySpec::Bow::kModulo && strategy.bow != StrategySpec::Bow::kDocumentFrequency) continue;
      const auto same = [&](const BowEvaluator::PlannedAssignment& p) { return p.name == strategy.name && p.robots == robots; };
      if (std::any_of(planned.begin(), planned.end(), same)) continue;
      planned.push_back({strategy.name, robots, [strategy, inputs, robots] {
                           const RunPlacement routing = BuildRunPlacement(strategy, inputs, robots, 0);
                           const BowFamily* family = routing.As<BowFamily>();
                           if (family == nullptr || !family->words) {
                             throw std::logic_error("PlanBow: " + strategy.name + " has no word owners");
                           }
                           return family->words;
                         }});
    }
  }
  return planned;
}

}  // namespace

RunFunction MakePaperRun(const SharedInputs& in) {
  PaperProtocolParams params = ToPaperParams(in);
  if (!params.centroids_out_dir.empty()) std::filesystem::create_directories(params.centroids_out_dir);
  // One evaluator for the paper's split (every team drives the same frames); one per team size for a
  // plan swept over team sizes (each team its own frames, ground truth and centralized ranking).
  // `evaluator` is the deployment's, made only when a team of the sweep drives all of it (always for
  // the split, which the bow_ strategies need: plans refuse them).
  std::map<int, std::shared_ptr<const PaperEvaluator>> evaluators;
  std::shared_ptr<const PaperEvaluator> evaluator;
  for (const int n : in.config->sweep.robots) {
    const Dataset& team = in.Team(n);
    if (&team != &in.deployment) {
      evaluators[n] = std::make_shared<const PaperEvaluator>(team, params.evaluation);
      continue;
    }
    if (!evaluator) evaluator = std::make_shared<const PaperEvaluator>(in.deployment, params.evaluation);
    evaluators[n] = evaluator;
  }
  const int pr_robots = PrRobots(*in.config);
  const StrategyInputs strategy_inputs = StrategyInputsOf(in);
  const SharedInputs* inputs = &in;
  // The BoW index and its centralized ranking, once for all runs; only when a bow_ strategy runs.
  std::shared_ptr<const BowEvaluator> bow;
  if (AnyBow(*in.config)) {
    auto planned = std::make_shared<BowEvaluator>(*evaluator, in.bow);
    planned->Plan(PlanBow(*in.config, strategy_inputs));
    bow = std::move(planned);
  }
  return [params, evaluators, bow, pr_robots, inputs](const RunSpec& spec) {
    RunOutput out;
    PaperProtocolParams run_params = params;
    run_params.keep_curves = spec.robots == pr_robots && spec.run == 0;
    const std::shared_ptr<const PaperEvaluator>& evaluator = evaluators.at(spec.robots);
    const std::int64_t frames = evaluator->deployment().size();  // every frame is one query
    // Its cache is the sweep's: each (robots, run) clusters once for every protocol and variant.
    const StrategyInputs run_inputs = StrategyInputsOf(*inputs, spec.robots);
    for (const StrategySpec& strategy : spec.strategies) {
      if (strategy.bag_of_words()) {
        AppendBowRun(strategy, spec, *bow, run_inputs, out);
        continue;
      }
      if (bow) AppendDescriptorTraffic(strategy, spec, run_inputs, out);
      if (strategy.broadcast()) {
        out.runs.push_back(PaperBroadcastRow(spec, *evaluator, frames));
        continue;
      }
      PaperRunResult r = PaperStrategyRun(strategy, spec, *evaluator, run_inputs, run_params);
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

}  // namespace dvpr
