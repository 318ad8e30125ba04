#pragma once
// The static protocol (docs/design.md section 2) for any routing strategy (issue 8). The paper's
// decentralized evaluation (PaperEvaluator::Evaluate) restricts each query to frames routed to
// the same robot; strategies that search at several robots or store at several generalise that:
//
// - every frame i is routed once, as the robot that took it (SplitSequence) would route it:
//   search_at(i) and store_at(i);
// - query i's candidates are the frames j outside its window with store_at(j) and search_at(i)
//   sharing a robot (every earlier or later frame, as in the paper's static protocol);
// - worst balance ratio = max over robots of (searches that robot serves) / (N / n). Searches,
//   not stores: serving a query is the work; for one-robot routings this is the paper's ratio,
//   and a strategy that probes m robots per query pays m times in the average too.
// Ground truth, R and the centralized reference are the evaluator's.
#include <string>

#include "agents/placement/placement.h"
#include "experiments/protocols/paper/static_protocol.h"

namespace dvpr {

// Fills row (protocol "paper", strategy `name`, robots, auc, auc_reference, relative_auc,
// worst_balance_ratio, queries = N), per_robot (queries_received = searches served, stored,
// comparisons) and the curve when keep_curve. Run, seed and centroids are the caller's.
PaperRunResult EvaluatePlacement(const PaperEvaluator& evaluator, const PlacementStrategy& routing,
                               const std::string& name, bool keep_curve);

}  // namespace dvpr
