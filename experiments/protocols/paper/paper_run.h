#pragma once
// Protocol "paper" of `dvpr run` (kPaperProtocol, experiments/results/protocol_traits.h): the
// paper's static evaluation (static_protocol.h) of every configured strategy, once per (robots,
// run), without a network. Its one-off work is the centralized ranking (PaperEvaluator) and, when
// a bow_ strategy runs, the BoW index (BowEvaluator, static_bow.h); each run then evaluates its
// strategies on the run's centroids: the paper's method, re-clustering plans
// (static_recluster.h), any other routing (static_strategies.h), broadcast as the centralized
// ranking itself, and the bow_ strategies with their partial-query sizes (bow.csv). The PR curves
// of figure 2 are kept at outputs.pr_robots (10 when swept, else the largest team), run 0.
#include "experiments/protocols/run.h"

namespace dvpr {

RunFunction MakePaperRun(const SharedInputs& inputs);

}  // namespace dvpr
